// Entity tags of rendered images: equal tags mean equal bytes, across requests, spellings and replicas.
#pragma once

#include <string>
#include <string_view>

#include "raster/scene.h"
#include "raster/version.h"

namespace rasterd {

/// The strong ETag (quoted) of the PNG that `scene` renders to: SHA-256 over every field of the parsed
/// scene and the render version (raster::kRenderVersion), cut to 128 bits. Hashing the parsed scene rather
/// than the request's bytes gives every spelling of one scene the same tag (key order, whitespace, 1 vs 1.0,
/// "#fff" vs [1, 1, 1], flat vs nested mesh arrays, an OBJ inline or uploaded); since the render is a
/// function of the scene alone (the thread count does not change the bytes), two scenes with one tag render
/// the same bytes. `render_version` is raster::kRenderVersion; a parameter so that a test can show that it
/// changes every tag.
std::string scene_etag(const raster::Scene& scene, int render_version = raster::kRenderVersion);

/// RFC 9110 section 13.1.2: whether an If-None-Match field value ("*", or a list of entity tags, weak or
/// strong) names `etag`, compared weakly as that section requires.
bool none_match_hits(std::string_view if_none_match, std::string_view etag);

}  // namespace rasterd
