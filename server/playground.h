// The playground: GET / serves one static page (server/playground/index.html) and GET /examples, GET
// /examples/<name>.json the repository's example scenes for its menu. All of it is embedded into the
// binary at build time (cmake/EmbedFiles.cmake), so a deployed rasterd reads no files.
#pragma once

#include <httplib.h>

namespace rasterd {

void install_playground(httplib::Server& server);

}  // namespace rasterd
