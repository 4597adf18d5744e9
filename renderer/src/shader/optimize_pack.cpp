// Packing (optimize.h step 4): every group of virtual slots gets physical ones, by linear scan over the
// groups' live ranges. A range is the first to the last instruction touching the group, widened to a whole
// loop when it crosses the loop's edges, since a value read in the next iteration must survive the
// back-edge. Pinned groups (the masks, inputs, uniforms, constants, the prologue's values) keep theirs.
#include <algorithm>
#include <limits>
#include <queue>
#include <unordered_map>

#include "shader/optimize.h"

namespace raster::shader {
namespace {

// Which of d, a, b, c (bits 0 to 3) hold slots, so that packing renumbers only them.
unsigned slot_fields(const Instr& in) {
  switch (in.op) {
    case Op::load_index:
    case Op::store_index:
      return 1 | 2 | 4;  // c is the stride
    case Op::tex_sample:
      return in.flags == static_cast<std::uint8_t>(TexMode::implicit) ? 1 | 2 | 4 : 15;
    case Op::tex_size:
      return 1 | 2;
    case Op::if_begin:
    case Op::loop_test:
    case Op::leave_if:
      return 1 | 2;
    case Op::if_else:
      return 1 | 2 | 4;
    case Op::if_end:
    case Op::mask_or:
    case Op::loop_end:
      return 2;
    case Op::if_merge:
    case Op::mask_or_and:
      return 2 | 4;
    case Op::clear:
    case Op::leave:
      return 1;
    case Op::loop_back:
      return 0;
    default:
      break;
  }
  // Arithmetic: the fields operands() names.
  const Operands o = operands(in);
  unsigned fields = 1;
  if (o.read_count > 0) fields |= 2;
  if (o.read_count > 1) fields |= 4;
  if (o.read_count > 2) fields |= 8;
  return fields;
}

struct Ranges {
  std::vector<std::int64_t> first, last;
  std::vector<bool> used;
};

Ranges live_ranges(const Lowered& l, const std::vector<std::uint32_t>& forced) {
  const Program& p = l.program;
  const std::size_t groups = l.group_first.size();
  Ranges r{std::vector<std::int64_t>(groups, std::numeric_limits<std::int64_t>::max()),
           std::vector<std::int64_t>(groups, -1), std::vector<bool>(groups, false)};
  const auto touch = [&](Slot s, std::int64_t i) {
    const std::uint32_t g = l.group_of[s];
    r.used[g] = true;
    r.first[g] = std::min(r.first[g], i), r.last[g] = std::max(r.last[g], i);
  };
  for (const Instr& in : p.prologue) {
    const Operands o = operands(in);
    for (int k = 0; k < o.read_count; ++k) touch(o.reads[k], 0);
    for (int k = 0; k < o.write_count; ++k) touch(o.writes[k], 0);
  }
  for (std::size_t i = 0; i < p.code.size(); ++i) {
    const Operands o = operands(p.code[i]);
    for (int k = 0; k < o.read_count; ++k) touch(o.reads[k], static_cast<std::int64_t>(i));
    for (int k = 0; k < o.write_count; ++k) touch(o.writes[k], static_cast<std::int64_t>(i));
  }
  for (const std::uint32_t g : forced) {
    r.used[g] = true;
    r.first[g] = std::min<std::int64_t>(r.first[g], 0), r.last[g] = static_cast<std::int64_t>(p.code.size());
  }
  // Loops, innermost (shortest) first; widening for one may make a range cross an outer loop's edge.
  std::vector<std::pair<std::int64_t, std::int64_t>> loops;
  for (std::size_t i = 0; i < p.code.size(); ++i)
    if (p.code[i].op == Op::loop_back) loops.emplace_back(p.code[i].imm, static_cast<std::int64_t>(i));
  std::sort(loops.begin(), loops.end(),
            [](auto x, auto y) { return x.second - x.first < y.second - y.first; });
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [top, back] : loops)
      for (std::size_t g = 0; g < groups; ++g) {
        if (!r.used[g] || r.last[g] < top || r.first[g] > back) continue;  // outside the loop
        if (r.first[g] >= top && r.last[g] <= back) continue;              // inside it
        if (r.first[g] > top || r.last[g] < back) changed = true;
        r.first[g] = std::min(r.first[g], top), r.last[g] = std::max(r.last[g], back);
      }
  }
  return r;
}

}  // namespace

bool pack_slots(Lowered& l, std::size_t max_slots, Program& out, Diagnostics& diagnostics) {
  Program& p = l.program;
  std::vector<std::uint32_t> forced = {l.group_of[kExecSlot], l.group_of[kDiscardSlot]};
  if (p.output_slots > 0) forced.push_back(l.group_of[p.output]);
  const Ranges r = live_ranges(l, forced);
  const std::size_t groups = l.group_first.size();
  std::vector<Slot> base(groups, kUnusedSlot);
  Slot next = 0;
  for (std::size_t g = 0; g < groups; ++g)
    if (r.used[g] && l.pinned[g]) base[g] = next, next += l.group_size[g];
  std::vector<std::uint32_t> order;
  for (std::size_t g = 0; g < groups; ++g)
    if (r.used[g] && !l.pinned[g]) order.push_back(static_cast<std::uint32_t>(g));
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t x, std::uint32_t y) { return r.first[x] < r.first[y]; });
  using Active = std::pair<std::int64_t, std::uint32_t>;  // (last instruction, group)
  std::priority_queue<Active, std::vector<Active>, std::greater<>> active;
  std::unordered_map<std::uint32_t, std::vector<Slot>> free;  // by size
  for (const std::uint32_t g : order) {
    while (!active.empty() && active.top().first < r.first[g]) {
      free[l.group_size[active.top().second]].push_back(base[active.top().second]);
      active.pop();
    }
    std::vector<Slot>& same = free[l.group_size[g]];
    if (!same.empty()) {
      base[g] = same.back();
      same.pop_back();
    } else {
      base[g] = next, next += l.group_size[g];
    }
    active.emplace(r.last[g], g);
  }
  if (next > max_slots) {
    diagnostics.error({}, std::string("the program needs ") + std::to_string(next) +
                              std::string(" values a pixel at once, more than the ") +
                              std::to_string(max_slots) + " allowed");
    return false;
  }
  const auto map = [&](Slot s) {
    const std::uint32_t g = l.group_of[s];
    return base[g] == kUnusedSlot ? kUnusedSlot : base[g] + (s - l.group_first[g]);
  };
  const auto rewrite = [&](std::vector<Instr>& code) {
    for (Instr& in : code) {
      const unsigned f = slot_fields(in);
      in.d = f & 1 ? map(in.d) : 0;
      in.a = f & 2 ? map(in.a) : 0;
      in.b = f & 4 ? map(in.b) : 0;
      if (in.op != Op::load_index && in.op != Op::store_index && in.op != Op::loop_back)
        in.c = f & 8 ? map(in.c) : 0;
    }
  };
  rewrite(p.code);
  rewrite(p.prologue);
  std::vector<std::pair<Slot, std::uint32_t>> constants;
  for (const auto& [s, bits] : p.constants)
    if (map(s) != kUnusedSlot) constants.emplace_back(map(s), bits);
  p.constants = std::move(constants);
  for (UniformSlots& u : p.uniforms) u.first = map(u.first);
  p.frag_coord = map(p.frag_coord), p.front_facing = map(p.front_facing), p.point_coord = map(p.point_coord);
  if (p.output_slots > 0) p.output = map(p.output);
  p.slots = next;
  out = std::move(p);
  return true;
}

}  // namespace raster::shader
