// What the model readers share: the error of a model over the face limit, and a colour channel of 0..1 as a
// byte (OBJ's Kd and vertex colours, glTF's colours and factors, PLY's float colours), rounded as a pixel's
// channel is (base/srgb.h), so a colour becomes the same byte whichever format carried it.
#pragma once

#include <cstdint>
#include <string>

#include "base/srgb.h"
#include "raster/scene.h"

namespace raster::detail {

/// SceneError(limit): the model has more faces (triangles) than `limit` (Limits::max_model_faces).
[[noreturn]] inline void too_many_faces(std::int64_t limit) {
  throw SceneError(ErrorKind::limit, "the model has more than " + std::to_string(limit) + " faces");
}

/// A colour channel of 0..1 as a byte: rounded to nearest, clamped, NaN as 0.
inline std::uint8_t unit_byte(double v) {
  return to_byte(255 * v);
}

}  // namespace raster::detail
