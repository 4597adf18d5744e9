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
    case raster::ErrorKind::shader:
      p = problem(400, "invalid-shader", "The shader does not compile", error.what());
      break;
    case raster::ErrorKind::program:
      p = problem(422, "shader-limit", "The shader went past a limit while it ran", error.what());
      break;
  }
  const raster::ErrorLocation& where = error.where();
  // Semantic errors are located by pointer (possibly "" = the whole document); syntax and encoding errors
  // by byte (of the text the detail names: the body, a model, a parameter) and, in a model, by line.
  if (error.kind() == raster::ErrorKind::invalid || error.kind() == raster::ErrorKind::limit ||
      error.kind() == raster::ErrorKind::shader || error.kind() == raster::ErrorKind::program)
    p.pointer = where.pointer;
  p.byte = where.byte;
  p.line = where.line;
  p.column = where.column;
  for (const raster::ErrorNote& n : error.notes()) p.errors.push_back(n);
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
  if (p.column != 0) body["column"] = p.column;
  if (!p.errors.empty()) {  // every compile error of a shader, in the order found
    nlohmann::ordered_json errors = nlohmann::ordered_json::array();
    for (const raster::ErrorNote& n : p.errors) {
      nlohmann::ordered_json e = {{"message", raster::escape_for_display(n.message)}};
      if (n.line != 0) e["line"] = n.line;
      if (n.column != 0) e["column"] = n.column;
      errors.push_back(std::move(e));
    }
    body["errors"] = std::move(errors);
  }
  if (p.parameter) body["parameter"] = raster::escape_for_display(*p.parameter);
  res.status = p.status;
  res.set_content(body.dump(), "application/problem+json");
}

}  // namespace rasterd
