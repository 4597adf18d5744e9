// The lowering's matrix functions (section 8.6) and texture functions (section 8.8). Only sampler2D
// channels hold images; every other sampler, and a channel the request did not fill, reads zero.
#include <functional>

#include "shader/lowerer.h"

namespace raster::shader {
namespace {

// Column c, row r of a matrix value with `rows` rows.
Slot at(const Value& m, int c, int r) {
  return m.s[static_cast<std::size_t>(c * m.type.rows + r)];
}

}  // namespace

Value Lowerer::matrix_builtin(BuiltinOp op, const Type& t, const std::vector<Value>& a) {
  const Value& m = a[0];
  Value r{t, {}};
  switch (op) {
    case BuiltinOp::matrix_comp_mult:
      return map(Op::fmul, t, {&a[0], &a[1]});
    case BuiltinOp::outer_product:  // column vector a[0] times row vector a[1]
      for (std::size_t c = 0; c < a[1].s.size(); ++c)
        for (std::size_t row = 0; row < a[0].s.size(); ++row)
          r.s.push_back(emit(Op::fmul, a[0].s[row], a[1].s[c]));
      return r;
    case BuiltinOp::transpose:  // moves no data
      for (int c = 0; c < t.cols; ++c)
        for (int row = 0; row < t.rows; ++row) r.s.push_back(at(m, row, c));
      return r;
    default:
      break;
  }
  const int n = m.type.cols;
  // det of the square sub-matrix of the given columns and rows, by expansion along its first column.
  std::function<Slot(std::vector<int>, std::vector<int>)> det = [&](std::vector<int> cols,
                                                                    std::vector<int> rows) {
    if (cols.size() == 1) return at(m, cols[0], rows[0]);
    if (cols.size() == 2)
      return emit(Op::fsub, emit(Op::fmul, at(m, cols[0], rows[0]), at(m, cols[1], rows[1])),
                  emit(Op::fmul, at(m, cols[1], rows[0]), at(m, cols[0], rows[1])));
    Slot sum = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      std::vector<int> sub_rows = rows;
      sub_rows.erase(sub_rows.begin() + static_cast<std::ptrdiff_t>(i));
      const Slot term = emit(Op::fmul, at(m, cols[0], rows[i]),
                             det(std::vector<int>(cols.begin() + 1, cols.end()), sub_rows));
      sum = i == 0 ? term : emit(i % 2 ? Op::fsub : Op::fadd, sum, term);
    }
    return sum;
  };
  std::vector<int> all(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
  const Slot d = det(all, all);
  if (op == BuiltinOp::determinant) return Value{t, {d}};
  // inverse: the adjugate (transposed cofactors), each divided by the determinant (as Mesa does).
  for (int c = 0; c < n; ++c)
    for (int row = 0; row < n; ++row) {
      // Entry (c, row) of the inverse is cofactor (row, c) of m: m without column row and row c.
      std::vector<int> cols, rows;
      for (int k = 0; k < n; ++k) {
        if (k != row) cols.push_back(k);
        if (k != c) rows.push_back(k);
      }
      Slot cof = det(cols, rows);
      if ((c + row) % 2) cof = emit(Op::fneg, cof);
      r.s.push_back(emit(Op::fdiv, cof, d));
    }
  return r;
}

Value Lowerer::texture(BuiltinOp op, const Type& t, const std::vector<Value>& a, const Expr* e) {
  const Value& sampler = a[0];
  const bool bound = sampler.type.sampler == SamplerKind::sampler2D && sampler.channel >= 0;
  if (!bound)
    return constant_value(t, std::vector<std::uint32_t>(static_cast<std::size_t>(t.slots()), 0u), false);
  const auto channel = static_cast<std::uint32_t>(sampler.channel);
  out_.program.channels_read = static_cast<std::uint8_t>(out_.program.channels_read | 1u << channel);
  if (op == BuiltinOp::texture_size) {
    const Slot d = group(2);
    emit_to(Op::tex_size, d, a[1].s[0], 0, 0, channel);
    return Value{t, {d, d + 1}};
  }
  const auto offset = [&](std::size_t k) -> std::uint32_t {
    const Expr* o = e->args[k];
    const std::vector<std::uint32_t> v = o->value.empty() ? fold_constant(*o) : o->value;
    if (v.size() < 2) return 8u | 8u << 8;
    return ((v[0] + 8u) & 0xffu) | ((v[1] + 8u) & 0xffu) << 8;
  };
  std::uint32_t offsets = 8u | 8u << 8;  // no offset
  if (op == BuiltinOp::texel_fetch || op == BuiltinOp::texel_fetch_offset) {
    Slot x = a[1].s[0], y = a[1].s[1];
    if (op == BuiltinOp::texel_fetch_offset) {
      const Value& o = a[3];
      x = emit(Op::iadd, x, o.s[0]), y = emit(Op::iadd, y, o.s[1]);
    }
    const Slot d = group(4);
    emit_to(Op::tex_fetch, d, x, y, a[2].s[0], channel);
    return Value{t, {d, d + 1, d + 2, d + 3}};
  }
  const bool proj = op == BuiltinOp::texture_proj || op == BuiltinOp::texture_proj_offset ||
                    op == BuiltinOp::texture_proj_lod || op == BuiltinOp::texture_proj_lod_offset ||
                    op == BuiltinOp::texture_proj_grad || op == BuiltinOp::texture_proj_grad_offset;
  Slot u = a[1].s[0], v = a[1].s[1];
  if (proj) {
    const Slot q = a[1].s.back();
    u = emit(Op::fdiv, u, q), v = emit(Op::fdiv, v, q);
  }
  TexMode mode = TexMode::implicit;
  Slot c = 0;
  switch (op) {
    case BuiltinOp::texture:
    case BuiltinOp::texture_proj:
      if (a.size() > 2) mode = TexMode::bias, c = a[2].s[0];
      break;
    case BuiltinOp::texture_offset:
    case BuiltinOp::texture_proj_offset:
      offsets = offset(2);
      if (a.size() > 3) mode = TexMode::bias, c = a[3].s[0];
      break;
    case BuiltinOp::texture_lod:
    case BuiltinOp::texture_proj_lod:
      mode = TexMode::lod, c = a[2].s[0];
      break;
    case BuiltinOp::texture_lod_offset:
    case BuiltinOp::texture_proj_lod_offset:
      mode = TexMode::lod, c = a[2].s[0], offsets = offset(3);
      break;
    default: {  // the gradient forms
      mode = TexMode::grad;
      c = group(4);
      const Slot g[4] = {a[2].s[0], a[2].s[1], a[3].s[0], a[3].s[1]};
      for (Slot k = 0; k < 4; ++k) emit_to(Op::mov, c + k, g[k]);
      if (op == BuiltinOp::texture_grad_offset || op == BuiltinOp::texture_proj_grad_offset)
        offsets = offset(4);
      break;
    }
  }
  if (mode == TexMode::implicit || mode == TexMode::bias) out_.program.derivatives = true;
  const Slot d = group(4);
  emit_to(Op::tex_sample, d, u, v, c, channel | offsets << 8, static_cast<std::uint8_t>(mode));
  return Value{t, {d, d + 1, d + 2, d + 3}};
}

}  // namespace raster::shader
