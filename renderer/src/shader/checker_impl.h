// The checker's state, shared by its parts: names, types and declarations (check_decl.cpp), qualifiers,
// precisions and uniform blocks (check_qualifiers.cpp), functions (check_func.cpp), statements
// (check_stmt.cpp), expressions (check_expr.cpp), calls and constructors (check_call.cpp). Private to them.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "shader/builtins.h"
#include "shader/check.h"

namespace raster::shader {

/// Which default precision a type takes (section 4.5.4): float's, int's (uint's too) or one sampler type's;
/// -1 for types without precision (bool, structs, void).
int precision_key(const Type& t);

class Checker {
 public:
  Checker(Ast& ast, const Folder& fold, Checked& out, Diagnostics& diagnostics);
  void run();

 private:
  struct Symbol {
    Variable* variable = nullptr;
    StructType* type = nullptr;
    std::vector<Function*> functions;
    const StructType* block = nullptr;  ///< a uniform block's name: it names nothing a program can use
  };
  struct Scope : std::unordered_map<std::string_view, Symbol> {
    /// The precision statements of this scope, in order: a type's precision_key and its default.
    std::vector<std::pair<int, Precision>> precisions;
  };
  /// Where a layout(...) stands, which decides the names it may hold (section 4.3.8).
  enum class LayoutUse : std::uint8_t { none, block, member, output };

  // Names and declarations (check_decl.cpp).
  void error(SourcePos pos, std::string message);
  Symbol* lookup(std::string_view name);
  bool declarable(std::string_view name, SourcePos pos, bool function = false);
  Variable* make_variable(std::string_view name, const Type& type, SourcePos pos, Variable::Kind kind);
  void builtin_variables();
  void depth_range(Scope& s);
  Type resolve(TypeSpec* spec);
  bool sized(Type& type, bool array, Expr* size, SourcePos pos);
  int array_size(Expr* size);
  StructType* struct_type(StructDecl* decl);
  bool field(FieldDecl& f, StructType* st);
  void declaration(Declaration* d, bool global);
  void declarator(Declaration* d, const Type& base, Declarator& v, bool global);
  void global_kind(Declaration* d, Variable* v);

  // Qualifiers, precisions and uniform blocks (check_qualifiers.cpp).
  Precision default_precision(const Type& t) const;
  Precision precision(const TypeSpec* spec, const Type& t);
  void precision_statement(const Declaration* d);
  void layout(const std::vector<LayoutId>& ids, LayoutUse use);
  void qualifiers_alone(const Declaration* d);
  void interface_block(Declaration* d);
  void block_member(FieldDecl& f, StructType* st);
  void block_instance(Declaration* d, StructType* st);
  bool frame_clash(std::string_view name, SourcePos program, SourcePos frame);

  // Functions (check_func.cpp).
  void function(FunctionDecl* f);
  Function* signature(FunctionDecl* f);
  bool same_signature(FunctionDecl* f, Function* fn, const Type& ret,
                      const std::vector<Qualifier>& qualifiers, const std::vector<Precision>& precisions);
  void entry_point(FunctionDecl* f, const Function* fn);
  Function* entry();
  void recursion();
  void undefined_calls();

  // Statements (check_stmt.cpp).
  void statement(Stmt* s);
  void block(Stmt* s);
  void condition(Stmt* s);
  void bool_condition(Expr* e, std::string_view where);
  void switch_statement(Stmt* s);
  void return_statement(Stmt* s);

  // Expressions (check_expr.cpp).
  void expr(Expr* e);
  void name(Expr* e);
  void unary(Expr* e);
  void binary(Expr* e);
  void assign(Expr* e);
  void ternary(Expr* e);
  void field(Expr* e);
  void index(Expr* e);
  void length(Expr* e);
  bool lvalue(Expr* e, std::string_view action);
  Type operation(Punct op, const Type& a, const Type& b, std::string& why);
  bool constant_int(Expr* e, std::int64_t& value);

  // Calls and constructors (check_call.cpp).
  void call(Expr* e);
  void construct(Expr* e);
  void construct_type(Expr* e, const Type& type);
  void construct_plain(Expr* e, const Type& type);
  bool call_builtin(Expr* e, const std::vector<const Builtin*>& overloads);
  bool call_user(Expr* e, const std::vector<Function*>& overloads);
  void texture_offset(Expr* e);
  void out_arguments(Expr* e, const std::vector<Qualifier>& qualifiers);
  std::string argument_types(const Expr* e) const;

  Ast& ast_;
  const Folder& fold_;
  Checked& out_;
  Diagnostics& diagnostics_;
  std::vector<Scope> scopes_;
  Function* function_ = nullptr;  ///< whose body is being checked
  bool returned_ = false;         ///< its body has a return statement
  SourcePos last_error_;          ///< one error a place: a clash seen from both sides is reported once
  std::vector<char> breakable_;   ///< 'l' a loop, 's' a switch, innermost last
  std::vector<const Declaration*>* global_order_ = nullptr;
};

}  // namespace raster::shader
