// The OBJ test oracle (obj_tinyobj.cpp): rasterd 0.4's OBJ reader through tinyobjloader, which the library's
// own reader (raster::parse_obj) is checked against. Not linked into the library or the server.
#pragma once

#include <string_view>

#include "raster/model.h"

namespace raster::oracle {

/// What raster::parse_obj gave before it read OBJ itself: the same arguments, the same errors; the mesh
/// through tinyobjloader 2.0.0~rc10 (its own number parser, its shapes and groups).
Mesh parse_obj_tinyobj(std::string_view obj_text, std::string_view mtl_text = {}, const Limits& limits = {},
                       const Uploads& files = {});

}  // namespace raster::oracle
