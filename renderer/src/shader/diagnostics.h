// Diagnostics: the errors every pass of the compiler reports, each at a place in the shader's text, and the
// arena that holds text the passes make (pasted tokens, names of generated things) for the compilation.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "shader/token.h"

namespace raster::shader {

struct Diagnostic {
  SourcePos pos;
  std::string message;  ///< one sentence, no location, valid UTF-8 (quoted source text is escaped)
};

/// Errors in the order found. After kMaxErrors more are counted but not kept, so a hostile program of a
/// million errors costs a bounded report; `overflow` says how many were dropped.
///
/// A pass goes on after an error wherever it can, and the passes after it run on what it made, so one
/// compile reports every independent mistake; a pass that reached a bound (tokens, nesting) calls stop(),
/// and no later pass runs on its truncated output.
class Diagnostics {
 public:
  static constexpr std::size_t kMaxErrors = 32;

  void error(SourcePos pos, std::string message);
  void stop() { stopped_ = true; }
  bool stopped() const { return stopped_; }
  bool failed() const { return !errors_.empty(); }
  const std::vector<Diagnostic>& errors() const { return errors_; }
  std::size_t overflow() const { return overflow_; }

 private:
  std::vector<Diagnostic> errors_;
  std::size_t overflow_ = 0;
  bool stopped_ = false;
};

/// Text made during a compilation, at stable addresses (a deque never moves what it holds), so tokens and
/// names can view it.
class TextArena {
 public:
  std::string_view keep(std::string text) { return texts_.emplace_back(std::move(text)); }

 private:
  std::deque<std::string> texts_;
};

/// Source text quoted in a message: printable ASCII kept, anything else as \xNN, at most `max` bytes.
std::string quote(std::string_view text, std::size_t max = 40);

}  // namespace raster::shader
