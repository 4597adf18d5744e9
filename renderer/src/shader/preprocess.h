// Preprocess: GLSL text -> the tokens the parser reads, with directives obeyed (GLSL ES 3.00 section 3.4):
// #define (object- and function-like, ## pasting), #undef, #if / #ifdef / #ifndef / #elif / #else / #endif
// with `defined`, #error, #pragma, #extension, #version and #line, and the predefined macros __LINE__,
// __FILE__, __VERSION__, GL_ES and GL_FRAGMENT_PRECISION_HIGH. Macros are expanded with hide sets
// (Prosser's algorithm, as C preprocessors do), and every expansion counts toward a bound, so a macro that
// doubles itself costs an error, not the machine.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "shader/diagnostics.h"
#include "shader/token.h"

namespace raster::shader {

struct PreprocessLimits {
  std::size_t max_tokens = 1 << 18;  ///< tokens made, source and expansions together
  int max_depth = 64;                ///< #if blocks inside each other, and macro arguments inside arguments
};

/// The tokens of `text` after preprocessing (no newlines; `end` last). Errors go to `diagnostics`; the
/// tokens up to the first fatal one (a bound reached) are returned either way.
std::vector<Token> preprocess(std::string_view text, const PreprocessLimits& limits, Diagnostics& diagnostics,
                              TextArena& arena);

}  // namespace raster::shader
