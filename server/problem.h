// RFC 9457 problem details: the one place where an error becomes an HTTP status and a JSON body.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <httplib.h>

#include "raster/error.h"

namespace rasterd {

/// A problem response about to be written. `type` is a stable URN clients can switch on.
struct Problem {
  int status = 500;
  std::string type;                       ///< e.g. "urn:rasterd:problem:invalid-scene"
  std::string title;                      ///< short, the same for every instance of the type
  std::string detail;                     ///< this instance, human readable
  std::optional<std::string> pointer;     ///< RFC 6901 pointer into the scene ("" is the root)
  std::size_t byte = 0;                   ///< 1-based byte offset into the body, 0 = none
  std::size_t line = 0;                   ///< 1-based line of an uploaded model or a shader, 0 = none
  std::size_t column = 0;                 ///< 1-based column in that line (shaders), 0 = none
  std::vector<raster::ErrorNote> errors;  ///< a shader's compile errors, every one
  std::optional<std::string> parameter;   ///< the query parameter at fault (invalid-query)
};

/// The mapping from library error kinds to statuses (400 malformed/invalid, 422 over a limit or bad model).
Problem problem_from(const raster::SceneError& error);

/// A problem with no library error behind it (413, 415, 404, 500, ...).
Problem problem(int status, std::string slug, std::string title, std::string detail);

/// Writes `p` as application/problem+json; body "status" always equals the HTTP status.
void write_problem(httplib::Response& res, const Problem& p);

}  // namespace rasterd
