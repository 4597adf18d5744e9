// Typed errors of the library: every rejection of input says which class it belongs to and where.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "raster/utf8.h"

namespace raster {

/// What kind of problem the input has; the HTTP layer maps each kind to one status in one place.
enum class ErrorKind {
  syntax,    ///< not well-formed (bad JSON, truncated, too deeply nested): HTTP 400
  invalid,   ///< well-formed but not a valid scene (wrong type, unknown field, bad colour): HTTP 400
  limit,     ///< valid but over a configured limit (image size, primitive count): HTTP 422
  model,     ///< an uploaded model is unusable (bad index, no faces): HTTP 422
  encoding,  ///< text (a scene, a model, a name) that is not well-formed UTF-8: HTTP 400, with its byte
  shader,    ///< a program that does not compile: HTTP 400, with its line and column
  program,   ///< a program that ran past a bound (loop iterations a pixel): HTTP 422, with the loop's line
};

/// Where a problem is. Fields that do not apply are empty / zero.
struct ErrorLocation {
  std::string pointer;     ///< RFC 6901 JSON pointer into the scene, e.g. "/primitives/3/points/1"
  std::size_t byte = 0;    ///< 1-based byte offset into the input text, 0 when unknown
  std::size_t line = 0;    ///< 1-based line number (OBJ models, shader programs), 0 when unknown
  std::size_t column = 0;  ///< 1-based column (bytes) in that line (shader programs), 0 when unknown
};

/// A further problem found with the first (a program's other compile errors), where it is and what.
struct ErrorNote {
  std::size_t line = 0, column = 0;
  std::string message;
};

/// The single exception type for bad input. what() is a human sentence without the location, and always
/// valid UTF-8 on one line: messages quote client text (a key, a token, nlohmann's "last read" excerpt,
/// which can cut a multi-byte character in half), and callers send them on to clients as JSON.
class SceneError : public std::runtime_error {
 public:
  SceneError(ErrorKind kind, std::string_view message, ErrorLocation where = {},
             std::vector<ErrorNote> notes = {})
      : std::runtime_error(escape_for_display(message)),
        kind_(kind),
        where_(std::move(where)),
        notes_(std::move(notes)) {}

  ErrorKind kind() const { return kind_; }
  const ErrorLocation& where() const { return where_; }
  /// Every problem found, the first included (a program's compile errors, in the order found); empty for
  /// errors that stop at the first.
  const std::vector<ErrorNote>& notes() const { return notes_; }

 private:
  ErrorKind kind_;
  ErrorLocation where_;
  std::vector<ErrorNote> notes_;
};

}  // namespace raster
