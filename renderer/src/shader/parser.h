// Parse: preprocessed tokens -> Ast (GLSL ES 3.00's grammar, chapter 9), by recursive descent. Errors are
// reported where they are found and the parser resumes at the next `;` or `}`, so one compilation reports
// several; nesting deeper than the limit (brackets, statements, operators) stops it, so no program can
// exhaust the stack.
#pragma once

#include <vector>

#include "shader/ast.h"
#include "shader/diagnostics.h"

namespace raster::shader {

void parse(const std::vector<Token>& tokens, int max_depth, Ast& ast, Diagnostics& diagnostics);

/// Whether `word` is a keyword of GLSL ES 3.00 or a word it reserves (section 3.7): neither names anything.
bool is_keyword(std::string_view word);
bool is_reserved_word(std::string_view word);

}  // namespace raster::shader
