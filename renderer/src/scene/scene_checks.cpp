// The checks of single values (raster/scene_checks.h): the scene reader's words for a field, for values that
// come from elsewhere too. The reader calls them, so a query parameter and a scene's field are refused alike.
#include "raster/scene_checks.h"

#include <charconv>
#include <cmath>
#include <string>

#include "scene/scene_format.h"

namespace raster::checks {
namespace {

[[noreturn]] void invalid(const std::string& message) {
  throw SceneError(ErrorKind::invalid, message);
}

// The index of `name` among `names`, else the choice's error.
std::size_t choice(std::span<const std::string_view> names, std::string_view name) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  invalid(format::expected_one_of(names) + ", got \"" + std::string(name) + "\"");
}

}  // namespace

int image_side(std::string_view key, double value, std::string_view text, int max_side) {
  if (value != std::floor(value)) invalid("expected a whole number, got " + std::string(text));
  std::string quoted = "\"";  // appended, not `"\"" + ...`, which GCC 12 misreads (-Wrestrict)
  quoted.append(key).append("\" ");
  if (value < 1) invalid(quoted + "must be at least 1, got " + std::string(text));
  const int cap = std::min(max_side, kMaxImageSide);
  if (value > cap)
    throw SceneError(ErrorKind::limit,
                     quoted + std::string(text) + " exceeds the limit of " + std::to_string(cap));
  return static_cast<int>(value);
}

void image_size(int width, int height, const Limits& limits) {
  if (const std::int64_t pixels = std::int64_t{width} * height; pixels > limits.max_pixels)
    throw SceneError(ErrorKind::limit, std::to_string(width) + "x" + std::to_string(height) + " is " +
                                           std::to_string(pixels) + " pixels, over the limit of " +
                                           std::to_string(limits.max_pixels));
}

Vec3 up_axis(std::string_view name) {
  return format::kUpAxes[choice(format::kUpAxisNames, name)];
}

Antialias antialias(std::string_view text) {
  if (text == "area") return Antialias::area;
  if (text == "auto") return Antialias::automatic;
  int samples = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), samples);
  Antialias a = Antialias::none;
  if (ec != std::errc() || end != text.data() + text.size() || !antialias_of_samples(samples, a))
    invalid(std::string(format::kAntialiasRule) + "\"" + std::string(text) + "\"");
  return a;
}

Projection projection(std::string_view name) {
  return static_cast<Projection>(choice(format::kProjectionNames, name));
}

View view(std::string_view name) {
  return static_cast<View>(choice(format::kViewNames, name));
}

float point_size(double pixels, std::string_view text) {
  if (!format::kPointSize.contains(pixels)) invalid(format::out_of_range(format::kPointSize, text));
  return static_cast<float>(pixels);
}

double fov(double degrees, std::string_view text) {
  if (!format::kFov.contains(degrees)) invalid(format::out_of_range(format::kFov, text));
  return degrees;
}

double coordinate(double value, std::string_view text) {
  if (std::fabs(value) > kMaxCoordinate) invalid(format::outside_coordinates(text));
  return value;
}

Vec3 up(const Vec3& direction) {
  if (direction == Vec3{}) invalid("\"up\" must not be the zero vector");
  return direction;
}

void camera(const Camera& c, const std::string& at, std::size_t byte) {
  if (c.has_view && c.has_eye)
    throw SceneError(ErrorKind::invalid, "\"view\" and \"eye\" both place the camera: give one of them",
                     {at + "/view", byte, 0});
  if (c.has_near && c.has_far && !(c.near < c.far))
    throw SceneError(ErrorKind::invalid, "\"far\" must be greater than \"near\"", {at + "/far", byte, 0});
}

ModelFormat model_format(std::string_view name) {
  return model_formats()[choice(format_names(), name)].format;
}

Mesh model_mesh(std::string_view bytes, std::optional<ModelFormat> hint, const Limits& limits,
                const Uploads& files, std::string_view mtl_text, const std::string& pointer, std::size_t byte,
                std::optional<ModelFormat> format) {
  Mesh mesh;
  try {
    mesh = format ? model_format(*format).read(bytes, limits, files, mtl_text)
                  : parse_model(bytes, hint, limits, files, mtl_text);
  } catch (const SceneError& e) {
    // An encoding error keeps its byte: the offset into the model's own text, which the message names.
    std::string message = e.what();
    if (e.where().line)
      message += " (line " + std::to_string(e.where().line) + ")";
    else if (e.where().byte && e.kind() != ErrorKind::encoding)  // a binary model's place in its own bytes
      message += " (byte " + std::to_string(e.where().byte) + " of the model)";
    throw SceneError(
        e.kind(), message,
        ErrorLocation{pointer, e.kind() == ErrorKind::encoding ? e.where().byte : byte, e.where().line});
  }
  if (mesh.colors.empty()) mesh.colors = {Rgba8{204, 204, 204, 255}};  // the grey of meshes without colours
  return mesh;
}

}  // namespace raster::checks
