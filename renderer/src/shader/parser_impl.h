// The parser's state, shared by its parts: tokens and names (parser.cpp), declarations (parse_decl.cpp),
// statements (parse_stmt.cpp) and expressions (parse_expr.cpp). Private to them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "shader/parser.h"

namespace raster::shader {

class Parser {
 public:
  Parser(const std::vector<Token>& tokens, int max_depth, Ast& ast, Diagnostics& diagnostics);
  void run();

  // Expressions (parse_expr.cpp).
  Expr* expression();
  Expr* assignment();

 private:
  friend class DepthGuard;

  // Tokens.
  const Token& peek(std::size_t ahead = 0) const;
  const Token& advance();
  bool at(Punct p, std::size_t ahead = 0) const { return peek(ahead).is(p); }
  bool at_word(std::string_view w, std::size_t ahead = 0) const { return peek(ahead).is_identifier(w); }
  bool accept(Punct p);
  bool accept_word(std::string_view w);
  bool expect(Punct p, std::string_view where);
  std::string describe(const Token& t) const;
  void error(SourcePos pos, std::string message);
  void error_at_token(std::string message);
  void skip_to_statement_end();

  // Names.
  bool is_type_name(const Token& t) const;
  bool is_qualifier(const Token& t) const;
  bool is_precision(const Token& t) const;
  bool name(std::string_view& out, SourcePos& pos, std::string_view what);
  void open_scope() { type_scopes_.emplace_back(); }
  void close_scope() { type_scopes_.pop_back(); }

  // Declarations (parse_decl.cpp).
  bool declaration_ahead() const;
  TypeSpec* type_spec();
  Precision precision_qualifier();
  StructDecl* struct_body();
  bool fields(StructDecl* s);
  bool array_suffix(bool& array, Expr*& size);
  void qualifiers(Declaration& d);
  bool qualifier_in_order(const Token& t, int rank, int& last, bool& layout_seen);
  void layout(std::vector<LayoutId>& ids);
  void external();
  void interface_block(Declaration* d, External& e);
  void function_rest(TypeSpec* ret, std::string_view name, SourcePos pos);
  bool parameter(ParamDecl& p);
  Declaration* declaration_rest(Declaration* d, std::string_view first, SourcePos first_pos);
  Stmt* declaration_statement();
  Stmt* precision_statement(Stmt* s);

  // Statements (parse_stmt.cpp).
  Stmt* statement();
  Stmt* block(bool scope);
  Stmt* if_statement();
  Stmt* for_statement();
  Stmt* while_statement();
  Stmt* do_statement();
  Stmt* switch_statement();
  Stmt* simple(StmtKind kind);
  Stmt* condition(Stmt* s);

  // Expressions (parse_expr.cpp).
  Expr* conditional();
  Expr* binary(int min_strength);
  Expr* unary();
  Expr* postfix();
  Expr* primary();
  Expr* literal(const Token& t);
  Expr* call_arguments(Expr* call);
  Expr* make(ExprKind kind, SourcePos pos);

  const std::vector<Token>& tokens_;
  std::size_t i_ = 0;
  int max_depth_;
  int depth_ = 0;
  bool fatal_ = false;  ///< nesting past the limit: the rest is not parsed
  Ast& ast_;
  Diagnostics& diagnostics_;
  /// Struct names visible here; the outermost scope holds the built-in one, gl_DepthRangeParameters.
  std::vector<std::vector<std::string_view>> type_scopes_{{"gl_DepthRangeParameters"}};
  SourcePos last_error_;
};

/// Counts one level of nesting for as long as it lives; past the parser's limit it stops the parse.
class DepthGuard {
 public:
  explicit DepthGuard(Parser& p);
  ~DepthGuard() { --parser_.depth_; }
  bool ok() const { return ok_; }

 private:
  Parser& parser_;
  bool ok_;
};

}  // namespace raster::shader
