// The preprocessor's state, shared by its two halves: directives (preprocess.cpp) and macro expansion
// (macros.cpp). Private to them; everyone else calls preprocess() (preprocess.h).
#pragma once

#include <cstdint>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "shader/lexer.h"
#include "shader/preprocess.h"

namespace raster::shader {

struct Macro {
  enum class Builtin : std::uint8_t { none, line, file, version, gl_es, precision_high };
  Builtin builtin = Builtin::none;  ///< predefined: its value is made where it is used
  bool function_like = false;
  std::vector<std::string_view> params;
  std::vector<Token> body;
};

/// Where tokens are read from: a stack of tokens (back is next), then, for the program itself, the lexer.
struct Input {
  std::vector<Token> stack;
  bool lexer = false;
};

class Preprocessor {
 public:
  Preprocessor(std::string_view text, const PreprocessLimits& limits, Diagnostics& diagnostics,
               TextArena& arena);
  std::vector<Token> run();

 private:
  // Reading.
  Token next(Input& in);
  void unread(Input& in, const Token& t);
  std::vector<Token> line_tokens();

  // Directives (preprocess.cpp).
  void directive();
  void define(const std::vector<Token>& line, SourcePos at);
  void undef(const std::vector<Token>& line, SourcePos at);
  void conditional(std::string_view name, const std::vector<Token>& line, SourcePos at);
  void line_directive(const std::vector<Token>& line, SourcePos at);
  void extension(const std::vector<Token>& line, SourcePos at);
  void pragma(const std::vector<Token>& line);
  void version(const std::vector<Token>& line, SourcePos at);
  bool evaluate(std::vector<Token> line, SourcePos at);
  bool taking() const { return conditionals_.empty() || conditionals_.back().taking; }
  bool reserved_name(const Token& name, std::string_view what);

  // Expansion (macros.cpp).
  bool expand(const Token& name, Input& in);
  std::vector<Token> expand_all(std::vector<Token> tokens);
  bool collect_arguments(const Token& name, Input& in, std::vector<std::vector<Token>>& args, Token& close);
  std::vector<Token> substitute(const Macro& macro, const std::vector<std::vector<Token>>& args,
                                std::uint32_t hide, SourcePos at);
  bool paste(Token& left, const Token& right);
  Token builtin_value(Macro::Builtin builtin, const Token& use);
  bool hidden(std::uint32_t set, std::string_view name) const;
  std::uint32_t hide_union(std::uint32_t set, std::string_view name);
  std::uint32_t hide_union(std::uint32_t a, std::uint32_t b);
  std::uint32_t hide_intersection(std::uint32_t a, std::uint32_t b);
  bool count(std::size_t tokens, SourcePos at);
  void fatal(SourcePos at, std::string message);

  struct Conditional {
    bool taking = false;     ///< this group's lines are kept
    bool any_taken = false;  ///< some group of this #if was taken (or the #if is inside a skipped one)
    bool seen_else = false;
    SourcePos pos;
  };

  Lexer lexer_;
  PreprocessLimits limits_;
  Diagnostics& diagnostics_;
  TextArena& arena_;
  Input main_{{}, true};
  std::unordered_map<std::string_view, Macro> macros_;
  std::vector<Conditional> conditionals_;
  std::vector<std::vector<std::string_view>> hide_sets_{{}};  ///< index 0: the empty set
  std::size_t made_ = 0;        ///< tokens read or made so far, against limits_.max_tokens
  int depth_ = 0;               ///< macro arguments being expanded inside each other
  bool fatal_ = false;          ///< a bound was reached: stop
  bool seen_anything_ = false;  ///< a token or directive came before (so #version is late)
  bool seen_token_ = false;     ///< a token that is not a directive's came before (so #extension is late)
};

}  // namespace raster::shader
