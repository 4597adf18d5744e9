// The scene format's checks of single values, for a Scene built in code from values that did not come in a
// scene document (the service's query parameters of a bare model). Each returns what the field would hold,
// or throws SceneError with the words the scene reader uses for the same value in that field (the reader
// calls these too, so the words are written once). The errors carry no location: the caller knows where the
// value came from. `text` is how the value is quoted in an error.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "raster/model.h"
#include "raster/scene.h"

namespace raster::checks {

/// "width" or "height" (`key`): a whole number from 1 to min(`max_side`, kMaxImageSide); over it is
/// SceneError(limit).
int image_side(std::string_view key, double value, std::string_view text, int max_side);

/// width x height within `limits.max_pixels`, else SceneError(limit).
void image_size(int width, int height, const Limits& limits);

/// A colour as text: "#rgb", "#rgba", "#rrggbb" or "#rrggbbaa".
Rgba8 color(std::string_view text);

/// A camera's "projection": "perspective" or "orthographic".
Projection projection(std::string_view name);

/// A camera's "view": "front", "back", "left", "right", "top", "bottom", "iso" or "three-quarter".
View view(std::string_view name);

/// A camera's "fov", in degrees.
double fov(double degrees, std::string_view text);
/// A model's "point_size", in pixels (format::kPointSize).
float point_size(double pixels, std::string_view text);

/// One coordinate of a point or direction: within +-kMaxCoordinate.
double coordinate(double value, std::string_view text);

/// A camera's "up": not the zero vector.
Vec3 up(const Vec3& direction);

/// An up axis by name: "+x", "-x", "+y", "-y", "+z", "-z" (or "x", "y", "z" for the positive ones).
Vec3 up_axis(std::string_view name);

/// What a camera's fields must satisfy together ("view" or "eye"; "near" before "far"), as a camera object
/// is checked when it ends. Throws with the pointer of the field at fault under `at` (a camera object's), at
/// `byte`.
void camera(const Camera& camera, const std::string& at, std::size_t byte);

/// A model primitive's "format": a name of model_formats(), as written (case matters, as in a scene).
ModelFormat model_format(std::string_view name);

/// "area" or the samples per pixel as digits (1, 4, 8, 16): the scene's "antialias" field, as text.
Antialias antialias(std::string_view text);

/// The mesh of a model primitive, read as the scene reader reads one: parse_model(bytes, hint, ...) within
/// the texels `limits` leave, grey when the model has no colours of its own. A reader's error is rethrown
/// with its line or its byte in the model's words, located at `pointer` and `byte` (0 when the model came in
/// no document). `format`: the format when the caller has decided it already (model_format_of, with the
/// sniff it made to route the request: the service and the CLI sniff a request once), so the bytes are not
/// sniffed again; without it, parse_model decides here.
Mesh model_mesh(std::string_view bytes, std::optional<ModelFormat> hint, const Limits& limits,
                const Uploads& files, std::string_view mtl_text, const std::string& pointer, std::size_t byte,
                std::optional<ModelFormat> format = std::nullopt);

}  // namespace raster::checks
