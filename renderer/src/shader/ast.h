// The syntax tree: what the parser makes of a program's tokens, and what the checker adds to it (each
// expression's type, what each name and call refers to, the values of constant expressions). Nodes live in
// the Ast's arenas and point at each other; nothing is freed before the compilation ends.
#pragma once

#include <cstdint>
#include <deque>
#include <string_view>
#include <vector>

#include "shader/token.h"
#include "shader/types.h"

namespace raster::shader {

struct Expr;
struct Stmt;
struct Function;
struct Builtin;
struct Declaration;

enum class Qualifier : std::uint8_t { none, const_, uniform, in, out, inout, const_in };

/// A precision qualifier as written (section 4.5); `none` where the type takes its scope's default.
enum class Precision : std::uint8_t { none, lowp, mediump, highp };

/// One entry of `layout(...)` (section 4.3.8): a name, maybe `= integer`. The parser keeps whatever is
/// written; the checker knows which names the declaration they qualify allows.
struct LayoutId {
  std::string_view name;
  SourcePos pos;
  bool has_value = false;
  std::int64_t value = 0;
};

/// A type as written: a keyword type, a struct's name, or a struct defined in place; maybe with `[n]`.
struct TypeSpec {
  SourcePos pos;
  Type type;                                ///< keyword types: set by the parser; structs: by the checker
  std::string_view struct_name;             ///< a struct named here (not defined)
  struct StructDecl* definition = nullptr;  ///< a struct defined here
  bool array = false;                       ///< `type[...]`
  Expr* array_size = nullptr;               ///< the size in `type[size]`; null for `type[]`
  Precision precision = Precision::none;    ///< as written
};

struct FieldDecl {
  TypeSpec* type;
  std::string_view name;
  SourcePos pos;
  bool array = false;
  Expr* array_size = nullptr;
  Declaration* qualifiers = nullptr;  ///< a block's member: its own qualifiers (null: none written)
};

struct StructDecl {
  std::string_view name;  ///< empty: an anonymous struct
  SourcePos pos;
  std::vector<FieldDecl> fields;
  bool block = false;          ///< an interface block's members (`uniform Name { ... }`), not a struct
  StructType* type = nullptr;  ///< made by the checker
};

/// A variable as the checker knows it. `value` holds a constant's slots.
struct Variable {
  enum class Kind : std::uint8_t {
    local,
    global,
    uniform,
    parameter,
    input,       ///< a global `in`: nothing feeds a ShaderToy program's, so it reads zero
    output,      ///< a global `out`: the fragment colour
    frag_coord,  ///< gl_FragCoord
    front_facing,
    point_coord,
  };
  std::string_view name;
  Type type;
  SourcePos pos;
  Kind kind = Kind::local;
  Qualifier qualifier = Qualifier::none;
  bool constant = false;             ///< `const` with a constant value in `value`
  std::vector<std::uint32_t> value;  ///< constant: the slots, as types.h lays them out
  bool written = false;              ///< assigned or passed as out/inout anywhere after its declaration
  int channel = -1;                  ///< uniform sampler2D iChannelN: N
};

struct Declarator {
  std::string_view name;
  SourcePos pos;
  bool array = false;          ///< `name[...]`
  Expr* array_size = nullptr;  ///< null for `name[]`
  Expr* init = nullptr;
  bool broken = false;           ///< its initializer did not parse: declared, of no type, so uses are quiet
  Variable* variable = nullptr;  ///< checker
};

struct Declaration {
  SourcePos pos;
  Qualifier qualifier = Qualifier::none;
  bool invariant = false, interpolation = false, flat = false, centroid = false;
  std::vector<LayoutId> layout;  ///< `layout(...)`'s entries (empty: none written)
  TypeSpec* type = nullptr;      ///< null: qualifiers alone (`layout(std140) uniform;`), or a block
  std::vector<Declarator>
      vars;  ///< empty: a struct declared alone, or `invariant name;`; a block: its instance
  std::vector<std::string_view> invariant_names;  ///< `invariant a, b;`
  StructDecl* block = nullptr;                    ///< an interface block's name and members
  bool precision_statement = false;               ///< `precision highp float;`: `type` and its precision
};

enum class ExprKind : std::uint8_t {
  literal,    ///< `type`, `bits`
  name,       ///< `name`
  unary,      ///< `op` args[0], prefix: + - ! ~ ++ --
  postfix,    ///< `op` args[0]: ++ --
  binary,     ///< args[0] `op` args[1]
  assign,     ///< args[0] `op` args[1], op = or a compound assignment
  ternary,    ///< args[0] ? args[1] : args[2]
  call,       ///< `name`(args): a function, a built-in, or a struct's constructor
  construct,  ///< `spec`(args): a constructor of a keyword type or an array
  field,      ///< args[0].`name`: a swizzle or a struct's field
  index,      ///< args[0][args[1]]
  length,     ///< args[0].length()
  sequence,   ///< args[0], args[1]
};

struct Expr {
  ExprKind kind = ExprKind::literal;
  Punct op = Punct::none;
  SourcePos pos;
  std::vector<Expr*> args;
  std::string_view name;
  TypeSpec* spec = nullptr;  ///< construct
  std::uint32_t bits = 0;    ///< literal: its one slot

  // Filled by the checker.
  Type type;
  Variable* variable = nullptr;            ///< name
  Function* function = nullptr;            ///< call of a user function
  const Builtin* builtin = nullptr;        ///< call of a built-in function
  std::uint8_t swizzle[4] = {0, 0, 0, 0};  ///< field on a vector: the components, in order
  std::uint8_t swizzle_count = 0;          ///< field on a vector: how many (0: a struct's field)
  int field = -1;                          ///< field on a struct: its index
  bool constant = false;                   ///< a constant expression, of value `value`
  std::vector<std::uint32_t> value;
};

enum class StmtKind : std::uint8_t {
  block,
  declaration,
  expression,
  if_,
  for_,
  while_,
  do_,
  switch_,
  case_,     ///< `case expr:`
  default_,  ///< `default:`
  break_,
  continue_,
  return_,
  discard,
  empty,
};

struct Stmt {
  StmtKind kind = StmtKind::empty;
  SourcePos pos;
  Expr* expr = nullptr;  ///< expression; if/while/do/for condition; switch selector; case label; return value
  Declaration* decl = nullptr;  ///< declaration; or a condition declared in `while (bool b = ...)`
  Stmt* body = nullptr;         ///< if (then), loops, switch
  Stmt* else_body = nullptr;    ///< if
  Stmt* init = nullptr;         ///< for
  Expr* step = nullptr;         ///< for
  std::vector<Stmt*> list;      ///< block
  bool scope = true;            ///< block: opens a scope (a function's body shares its parameters')
  bool broken = false;          ///< return or case: its expression did not parse (the error is reported)
};

struct ParamDecl {
  Qualifier qualifier = Qualifier::in;
  TypeSpec* type = nullptr;
  std::string_view name;  ///< may be empty in a prototype
  SourcePos pos;
  bool array = false;
  Expr* array_size = nullptr;
};

struct FunctionDecl {
  TypeSpec* ret = nullptr;
  std::string_view name;
  SourcePos pos;
  std::vector<ParamDecl> params;
  Stmt* body = nullptr;  ///< null: a prototype
};

/// A function as the checker knows it: one per signature, however many prototypes declare it.
struct Function {
  std::string_view name;
  Type ret;
  std::vector<Type> params;
  std::vector<Qualifier> qualifiers;
  std::vector<Precision> precisions;  ///< of the parameters: as written, or their scope's default
  SourcePos pos;
  const FunctionDecl* definition = nullptr;
  std::vector<Variable*> parameters;      ///< of the definition
  std::vector<Function*> calls;           ///< the user functions its body calls
  std::vector<SourcePos> call_positions;  ///< where, one per entry of `calls`
};

struct External {
  enum class Kind : std::uint8_t { function, declaration, precision };
  Kind kind = Kind::declaration;
  FunctionDecl* function = nullptr;
  Declaration* declaration = nullptr;
  SourcePos pos;
};

/// A parsed program and the arenas its nodes live in.
struct Ast {
  std::vector<External> externals;
  std::deque<Expr> exprs;
  std::deque<Stmt> stmts;
  std::deque<TypeSpec> specs;
  std::deque<StructDecl> structs;
  std::deque<Declaration> declarations;
  std::deque<FunctionDecl> functions;

  template <class T, class... Args>
  static T* make(std::deque<T>& arena, Args&&... args) {
    return &arena.emplace_back(std::forward<Args>(args)...);
  }
};

}  // namespace raster::shader
