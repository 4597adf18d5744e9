// The described API: GET /schema/scene.json (JSON Schema of scene format v1) and GET /openapi.json (the
// OpenAPI 3.1 document of every route). Both are the repository's files (server/schema/), embedded into
// the binary at build time, so what is served is what the tests check.
#pragma once

#include <string_view>

#include <httplib.h>

namespace rasterd {

void install_api_routes(httplib::Server& server);

/// The embedded documents, byte for byte as in server/schema/.
std::string_view scene_schema_text();
std::string_view openapi_text();

}  // namespace rasterd
