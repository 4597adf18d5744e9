#include "problem.h"

#include <nlohmann/json.hpp>

#include "raster/utf8.h"

namespace rasterd {

Problem problem(int status, std::string slug, std::string title, std::string detail) {
  Problem p;
  p.status = status;
  p.type = "urn:rasterd:problem:" + slug;
  p.title = std::move(title);
  p.detail = std::move(detail);
  return p;
}

Problem problem_from(const raster::SceneError& error) {
  Problem p;
  switch (error.kind()) {
    case raster::ErrorKind::syntax:
      p = problem(400, "malformed-scene", "The scene is not well-formed JSON", error.what());
      break;
    case raster::ErrorKind::invalid:
      p = problem(400, "invalid-scene", "The scene is not valid", error.what());
      break;
    case raster::ErrorKind::limit:
      p = problem(422, "over-limit", "The scene exceeds a service limit", error.what());
      break;
    case raster::ErrorKind::model:
      p = problem(422, "invalid-model", "The model cannot be used", error.what());
      break;
    case raster::ErrorKind::encoding:
      p = problem(400, "invalid-encoding", "The text is not valid UTF-8", error.what());
      break;
  }
  const raster::ErrorLocation& where = error.where();
  // Semantic errors are located by pointer (possibly "" = the whole document); syntax and encoding errors
  // by byte (of the text the detail names: the body, a model, a parameter) and, in a model, by line.
  if (error.kind() == raster::ErrorKind::invalid || error.kind() == raster::ErrorKind::limit)
    p.pointer = where.pointer;
  p.byte = where.byte;
  p.line = where.line;
  return p;
}

void write_problem(httplib::Response& res, const Problem& p) {
  // Details and pointers may quote client text (a header, a path, a key): escaped here, in the one place
  // every problem passes, so no byte a client sends can make the JSON writer throw.
  nlohmann::ordered_json body = {{"type", p.type},
                                 {"title", p.title},
                                 {"status", p.status},
                                 {"detail", raster::escape_for_display(p.detail)}};
  if (p.pointer) body["pointer"] = raster::escape_for_display(*p.pointer);
  if (p.byte != 0) body["byte"] = p.byte;
  if (p.line != 0) body["line"] = p.line;
  if (p.parameter) body["parameter"] = raster::escape_for_display(*p.parameter);
  res.status = p.status;
  res.set_content(body.dump(), "application/problem+json");
}

}  // namespace rasterd
