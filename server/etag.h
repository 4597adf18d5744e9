// Entity tags of rendered images: equal tags mean equal bytes, across requests, spellings and replicas.
#pragma once

#include <cstddef>
#include <optional>
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

/// The ETag a rendered PNG is sent with: the scene's tag with the PNG's length in bytes inside its quotes
/// ("<hash>-<length>"). The length names nothing new (the scene's tag already decides every byte), but a
/// client that sends the tag back tells the service the length a 304 must declare (RFC 9110 8.6: only the
/// length the 200 had, or none) without a render.
std::string image_etag(std::string_view scene_tag, std::size_t png_bytes);

/// What an If-None-Match field value says of the image of the scene whose tag is `scene_tag`.
struct NoneMatch {
  bool hit = false;                      ///< it names this image (or is "*")
  std::optional<std::size_t> png_bytes;  ///< the image's length, from an image_etag it names
};
/// RFC 9110 13.1.2, compared weakly: "*", the scene's tag, or an image_etag of it hit.
NoneMatch none_match(std::string_view if_none_match, std::string_view scene_tag);

}  // namespace rasterd
