// The playground: GET / serves one static page (server/playground/index.html) and GET /examples, GET
// /examples/<name>.json the repository's example scenes for its menu. All of it is embedded into the
// binary at build time (cmake/EmbedFiles.cmake), so a deployed rasterd reads no files.
#pragma once

#include <httplib.h>

namespace rasterd {

/// GET /: the page. (server/routes.cpp registers these.)
void serve_playground(const httplib::Request& req, httplib::Response& res);
/// GET /examples: the example names, a JSON array.
void serve_example_list(const httplib::Request& req, httplib::Response& res);
/// GET /examples/<name>.json, with the name in req.matches[1]; a 404 problem naming the examples if none.
void serve_example(const httplib::Request& req, httplib::Response& res);

}  // namespace rasterd
