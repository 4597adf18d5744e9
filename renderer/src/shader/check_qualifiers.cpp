// The checker's qualifiers: default precisions and precision statements (section 4.5), layout(...)
// (section 4.3.8), uniform blocks (section 4.3.7), and the names ShaderToy's frame declares after the
// program.
#include <algorithm>
#include <cctype>

#include "shader/checker_impl.h"
#include "shader/shadertoy.h"

namespace raster::shader {
namespace {

// A layout name as GLSL ES 3.00 knows it: its spelling, where it may stand, and whether it takes `= N`.
struct LayoutName {
  std::string_view name;
  bool block, member, output;
  bool value;
};

constexpr LayoutName kLayoutNames[] = {
    {"shared", true, false, false, false},      {"packed", true, false, false, false},
    {"std140", true, false, false, false},      {"row_major", true, true, false, false},
    {"column_major", true, true, false, false}, {"location", false, false, true, true},
};

// The name as written, or (`case_only`) one that differs from it in case alone: section 4.3.8 makes layout
// names case sensitive, which glslang is not.
const LayoutName* layout_name(std::string_view written, bool case_only = false) {
  for (const LayoutName& n : kLayoutNames)
    if (case_only
            ? std::equal(written.begin(), written.end(), n.name.begin(), n.name.end(),
                         [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; })
            : written == n.name)
      return &n;
  return nullptr;
}

const char* layout_place(const LayoutName& n) {
  if (n.output) return "the fragment's outputs";
  if (n.member) return "uniform blocks and their members";
  return "uniform blocks";
}

}  // namespace

int precision_key(const Type& t) {
  if (t.basic == Basic::float_) return 0;
  if (t.basic == Basic::int_ || t.basic == Basic::uint_) return 1;
  if (t.basic == Basic::sampler) return 2 + static_cast<int>(t.sampler);
  return -1;
}

Precision Checker::default_precision(const Type& t) const {
  const int key = precision_key(t);
  for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s)
    for (auto p = s->precisions.rbegin(); p != s->precisions.rend(); ++p)
      if (p->first == key) return p->second;
  return Precision::none;
}

// The precision of a declared type (a variable's, a field's, a parameter's, a return type): as written, or
// its scope's default. A float, int, uint or sampler with neither is an error (section 4.5.4: samplers but
// sampler2D and samplerCube have no default), reported once: the type then defaults to mediump, as glslang
// does.
Precision Checker::precision(const TypeSpec* spec, const Type& t) {
  if (spec->precision != Precision::none) return spec->precision;
  const int key = precision_key(t);
  if (key < 0) return Precision::none;
  const Precision p = default_precision(t);
  if (p != Precision::none) return p;
  const std::string name = type_name(t.with_array(0));
  error(spec->pos, std::string("'") + name + "' has no default precision: write one (highp " + name +
                       ") or declare it first with 'precision highp " + name + ";'");
  scopes_.front().precisions.emplace_back(key, Precision::mediump);
  return Precision::mediump;
}

// `precision highp float;`: the default of float, int or a sampler type (not uint, vectors, arrays or
// structs: section 4.5.3) for the rest of its scope.
void Checker::precision_statement(const Declaration* d) {
  const TypeSpec* spec = d->type;
  const Type& t = spec->type;  // a keyword's type; a struct's name is left an error here
  if (spec->array || spec->definition || spec->type.is_error() ||
      !((t.is_scalar() && (t.basic == Basic::float_ || t.basic == Basic::int_)) || t.is_sampler())) {
    const std::string name = spec->definition ? "a struct"
                             : t.is_error()   ? std::string("'") + quote(spec->struct_name) + "'"
                                              : type_name(t) + (spec->array ? "[]" : "");
    return error(spec->pos, "a precision statement applies to float, int and sampler types, not " + name);
  }
  scopes_.back().precisions.emplace_back(precision_key(t), spec->precision);
}

// The entries of a layout(...) where `use` says it stands: a uniform block (and `layout(...) uniform;`) takes
// its packing and matrix order, a block's member its matrix order, the fragment's output a location;
// nothing else in a fragment shader takes one.
void Checker::layout(const std::vector<LayoutId>& ids, LayoutUse use) {
  for (const LayoutId& id : ids) {
    const LayoutName* n = layout_name(id.name);
    if (!n) {
      const LayoutName* spelled = layout_name(id.name, true);
      error(id.pos,
            std::string("'") + quote(id.name) + "' is not a layout qualifier of GLSL ES 3.00" +
                (spelled ? std::string(" (they are case sensitive: ") + std::string(spelled->name) + ")"
                         : std::string()));
    } else if (!(use == LayoutUse::block    ? n->block
                 : use == LayoutUse::member ? n->member
                 : use == LayoutUse::output ? n->output
                                            : false)) {
      error(id.pos,
            std::string("layout(") + std::string(n->name) + ") applies to " + layout_place(*n) + " only");
    } else if (n->value != id.has_value) {
      error(id.pos, n->value ? std::string("layout(") + std::string(n->name) +
                                   ") needs a value: " + std::string(n->name) + " = N"
                             : std::string("layout(") + std::string(n->name) + ") takes no value");
    } else if (n->value && id.value < 0) {
      error(id.pos, std::string("layout(") + std::string(n->name) + ") cannot be negative");
    }
  }
}

// Qualifiers without a type, `layout(std140) uniform;`: a default for the blocks after it (rasterd lays out
// nothing, so it is only checked). glslang takes `uniform;`, `in;` and `out;` too.
void Checker::qualifiers_alone(const Declaration* d) {
  const bool storage =
      d->qualifier == Qualifier::uniform || d->qualifier == Qualifier::in || d->qualifier == Qualifier::out;
  if (!storage || d->invariant || d->interpolation || d->centroid)
    return error(d->pos, "a declaration without a type takes layout(...) and uniform, in or out only");
  layout(d->layout, d->qualifier == Qualifier::uniform ? LayoutUse::block : LayoutUse::none);
}

// A uniform block: its members are uniforms, read through its instance (`block.member`) or, without one, by
// their own names at global scope. rasterd makes the instance a value of a struct type (StructType::block)
// and each member of a block without one a uniform of its own. The block's name names nothing else.
void Checker::interface_block(Declaration* d) {
  StructDecl* decl = d->block;
  if (d->qualifier != Qualifier::uniform)
    return error(d->pos, "only uniform blocks exist in GLSL ES 3.00 (in and out blocks came with ES 3.10)");
  if (d->invariant || d->interpolation || d->centroid)
    error(d->pos, "a uniform block takes layout(...) and uniform only");
  layout(d->layout, LayoutUse::block);
  StructType* st = &out_.structs.emplace_back();
  st->name = decl->name, st->pos = decl->pos, st->block = true;
  decl->type = st;
  if (decl->fields.empty()) error(decl->pos, "a uniform block needs at least one member");
  for (FieldDecl& f : decl->fields) block_member(f, st);
  for (const Field& f : st->fields) st->slots += f.type.slots();
  if (declarable(decl->name, decl->pos)) scopes_.back()[decl->name].block = st;
  if (!d->vars.empty()) return block_instance(d, st);
  for (const Field& f : st->fields) {
    if (!declarable(f.name, f.pos)) continue;
    Variable* v = make_variable(f.name, f.type, f.pos, Variable::Kind::uniform);
    v->qualifier = Qualifier::uniform;
    out_.uniforms.push_back(v);
    scopes_.back()[f.name].variable = v;
  }
}

void Checker::block_member(FieldDecl& f, StructType* st) {
  if (const Declaration* q = f.qualifiers) {
    if ((q->qualifier != Qualifier::none && q->qualifier != Qualifier::uniform) || q->invariant ||
        q->interpolation || q->centroid)
      error(q->pos, "a uniform block's member takes layout(row_major or column_major) and uniform only");
    layout(q->layout, LayoutUse::member);
  }
  const std::size_t before = st->fields.size();
  if (!field(f, st) || st->fields.size() == before) return;
  if (st->fields.back().type.has_sampler()) {
    error(f.pos,
          std::string("'") + quote(f.name) + "': a uniform block's member cannot be or hold a sampler");
    st->fields.pop_back();
  }
}

// `uniform B { ... } b;` or `b[n]`: one uniform of the block's type (an array of blocks needs its size).
void Checker::block_instance(Declaration* d, StructType* st) {
  Declarator& v = d->vars.front();
  Type t = Type::of(Basic::structure);
  t.structure = st;
  if (!sized(t, v.array, v.array_size, v.pos)) return;
  if (t.array == Type::kUnsized)
    return error(v.pos, std::string("'") + quote(v.name) + "': an array of blocks needs a size");
  if (!declarable(v.name, v.pos)) return;
  Variable* var = make_variable(v.name, t, v.pos, Variable::Kind::uniform);
  var->qualifier = Qualifier::uniform;
  out_.uniforms.push_back(var);
  scopes_.back()[v.name].variable = var;
  v.variable = var;
}

// A name the program declares that ShaderToy's frame declares again after it (the epilogue's main() and
// rasterd_FragColor): reported at the program's declaration, the one its author can change.
bool Checker::frame_clash(std::string_view name, SourcePos program, SourcePos frame) {
  if (program.string != kProgramString || frame.string != kEpilogueString) return false;
  error(program, std::string("'") + quote(name) +
                     "' is declared by ShaderToy's frame after the program (its main() calls mainImage and "
                     "writes rasterd_FragColor), so the program cannot declare it");
  return true;
}

}  // namespace raster::shader
