// The described API: GET /schema/scene.json (JSON Schema of scene format v1) and GET /openapi.json (the
// OpenAPI 3.1 document of every route). Both are the repository's files (server/schema/), embedded into
// the binary at build time, so what is served is what the tests check.
#pragma once

#include <string_view>

#include <httplib.h>

namespace rasterd {

/// GET /schema/scene.json and GET /openapi.json (server/routes.cpp registers them).
void serve_scene_schema(const httplib::Request& req, httplib::Response& res);
void serve_openapi(const httplib::Request& req, httplib::Response& res);

/// The embedded documents, byte for byte as in server/schema/.
std::string_view scene_schema_text();
std::string_view openapi_text();

}  // namespace rasterd
