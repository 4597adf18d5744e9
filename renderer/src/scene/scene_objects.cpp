// The scene reader's objects that become one value each: the camera, the lights ("light", rasterd 0.1's
// one light, and the list "lights"), and a mesh's "transform" (-> a matrix), "edges" and "texture" (an
// image decoded under the scene's texel budget). Each is a table of fields read by read_object(), then
// the checks across its fields.
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "base/vecmath.h"
#include "raster/scene_checks.h"
#include "scene/scene_reader.h"

namespace raster::scene_reader {
namespace {

// "transform": {"translate", "rotate" (degrees about x, then y, then z), "scale"} or {"matrix"}.
constexpr Field<TransformState> kTransformFields[] = {
    {"translate", format::kArray, "[x, y, z]",
     [](Reader& r, TransformState& t, const Path& at) { t.translate = r.vec3(at); }},
    {"rotate", format::kArray, "[x, y, z] in degrees",
     [](Reader& r, TransformState& t, const Path& at) { t.rotate = r.vec3(at); }},
    {"scale", format::kNumber | format::kArray, "a number or [x, y, z]",
     [](Reader& r, TransformState& t, const Path& at) {
       if (r.in.peek() != Kind::number) return void(t.scale = r.vec3(at));
       const double k = r.number(at);
       t.scale = {k, k, k};
     }},
    {"matrix", format::kArray, "16 numbers (a row-major 4x4 matrix)",
     [](Reader& r, TransformState& t, const Path& at) {
       std::size_t k = 0;
       for (bool more = r.in.array_begin(); more; more = r.in.array_next(), ++k) {
         const double v = r.number(r.element(at, k));
         if (k < 16) t.matrix.m[k] = v;
       }
       if (k != 16) r.invalid(at, "expected 16 numbers (a row-major 4x4 matrix)");
     }},
};

constexpr Field<EdgesState> kEdgesFields[] = {
    {"color", format::kString | format::kArray, "a colour",
     [](Reader& r, EdgesState& e, const Path& at) { e.edges.color = r.color(at); }},
    {"width", format::kNumber, "a number",
     [](Reader& r, EdgesState& e, const Path& at) {
       e.edges.width = static_cast<float>(r.ranged(at, format::kEdgeWidth));
     }},
    {"angle", format::kNumber, "a number",
     [](Reader& r, EdgesState& e, const Path& at) {
       e.edges.crease_deg = static_cast<float>(r.ranged(at, format::kCreaseAngle));
     }},
};

constexpr Field<TextureState> kTextureFields[] = {
    {"data", format::kString, "the image file as base64 text",
     [](Reader& r, TextureState& t, const Path& at) {
       try {
         t.texture = decode_texture(r.base64(at), "data", t.budget);
       } catch (const SceneError& e) {
         if (!e.where().pointer.empty()) throw;
         r.fail(e.kind(), at, e.what());
       }
     }},
    {"source", format::kString, "the name of an uploaded part",
     [](Reader& r, TextureState& t, const Path& at) {
       const std::string name(r.in.string());
       const auto part = r.uploads.find(name);
       if (part == r.uploads.end())
         r.invalid(at, "no uploaded part named \"" + name + "\" (send it as a multipart part of that name)");
       try {
         t.texture = decode_texture(part->second, name, t.budget);
       } catch (const SceneError& e) {
         r.fail(e.kind(), at, e.what());
       }
     }},
    {"wrap", format::kString, "\"repeat\" or \"clamp\"",
     [](Reader& r, TextureState& t, const Path& at) {
       t.clamp = r.choice(at, std::array<std::string_view, 2>{"repeat", "clamp"}) == 1;
     }},
};

constexpr Field<CameraState> kCameraFields[] = {
    {"projection", format::kString, "\"perspective\" or \"orthographic\"",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.projection = static_cast<Projection>(r.choice(at, format::kProjectionNames));
     }},
    {"view", format::kString, "a view name",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.view = static_cast<View>(r.choice(at, format::kViewNames)), c.camera.has_view = true;
     }},
    {"fit", format::kString, "\"sphere\" or \"vertices\"",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.fit = static_cast<CameraFit>(r.choice(at, format::kFitNames));
     }},
    {"eye", format::kArray, "a point [x, y, z]",
     [](Reader& r, CameraState& c, const Path& at) { c.camera.eye = r.vec3(at), c.camera.has_eye = true; }},
    {"target", format::kArray, "a point [x, y, z]",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.target = r.vec3(at), c.camera.has_target = true;
     }},
    {"up", format::kArray | format::kString, "a direction [x, y, z] or an axis (\"+z\", \"-y\", ...)",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.has_up = true;
       if (r.in.peek() == Kind::string) {
         try {
           c.camera.up = checks::up_axis(r.in.string());
         } catch (const SceneError& e) {
           r.invalid(at, std::string("\"up\": ") + e.what());
         }
         return;
       }
       c.camera.up = r.vec3(at);
       if (c.camera.up == Vec3{}) r.invalid(at, "\"up\" must not be the zero vector");
     }},
    {"fov", format::kNumber, "a number",
     [](Reader& r, CameraState& c, const Path& at) { c.camera.fov_deg = r.ranged(at, format::kFov); }},
    {"near", format::kNumber, "a number",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.near = r.ranged(at, format::kNear), c.camera.has_near = true;
     }},
    {"far", format::kNumber, "a number",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.far = r.ranged(at, format::kFar), c.camera.has_far = true;
     }},
    {"height", format::kNumber, "a number",
     [](Reader& r, CameraState& c, const Path& at) {
       c.camera.height = r.ranged(at, format::kViewHeight), c.camera.has_height = true;
     }},
};

Vec3 direction(Reader& r, const Path& at) {
  const Vec3 d = r.vec3(at);
  if (d == Vec3{}) r.invalid(at, "the light direction must not be the zero vector");
  return d;
}

// "light": rasterd 0.1's one directional light plus ambient.
constexpr Field<LightState> kLightFields[] = {
    {"direction", format::kArray, "a direction [x, y, z]",
     [](Reader& r, LightState& l, const Path& at) { l.direction = direction(r, at), l.directed = true; }},
    {"ambient", format::kNumber, "a number",
     [](Reader& r, LightState& l, const Path& at) { l.ambient = r.ranged(at, format::kAmbient); }},
};

std::uint64_t light_keys(LightKind kind);

// One of "lights"; its "type" narrows the keys (light_keys).
constexpr Field<LightsEntry> kLightsFields[] = {
    {"type", format::kString, "\"ambient\", \"directional\" or \"point\"",
     [](Reader& r, LightsEntry& l, const Path& at) {
       l.light.kind = static_cast<LightKind>(
           r.choice(at, std::array<std::string_view, 3>{"ambient", "directional", "point"}));
       l.allowed = light_keys(l.light.kind), l.typed = true;
     }},
    {"color", format::kString | format::kArray, "a colour",
     [](Reader& r, LightsEntry& l, const Path& at) {
       const Rgba8 c = r.color(at);
       if (c.a != 255) r.invalid(at, "a light's colour is opaque (it has no alpha)");
       l.light.color = {c.r / 255.0, c.g / 255.0, c.b / 255.0};
     }},
    {"space", format::kString, "\"world\" or \"camera\"",
     [](Reader& r, LightsEntry& l, const Path& at) {
       l.light.camera_space = r.choice(at, std::array<std::string_view, 2>{"world", "camera"}) == 1;
     }},
    {"direction", format::kArray, "a direction [x, y, z]",
     [](Reader& r, LightsEntry& l, const Path& at) { l.light.direction = direction(r, at); }},
    {"intensity", format::kNumber, "a number",
     [](Reader& r, LightsEntry& l, const Path& at) { l.light.intensity = r.ranged(at, format::kIntensity); }},
    {"position", format::kArray, "a point [x, y, z]",
     [](Reader& r, LightsEntry& l, const Path& at) { l.light.position = r.vec3(at); }},
};

std::uint64_t light_keys(LightKind kind) {
  constexpr std::uint64_t kAll = format::mask_of(kLightsFields, {"type", "color", "intensity"});
  if (kind == LightKind::ambient) return kAll;
  return kAll |
         format::mask_of(kLightsFields, {kind == LightKind::point ? "position" : "direction", "space"});
}

}  // namespace

Camera Reader::camera(const Path& at) {
  CameraState c;
  read_object(kCameraFields, c, at, "a camera object");
  checks::camera(c.camera, at.str(), at.byte());  // the checks across its fields
  return c.camera;
}

std::vector<Light> Reader::light(const Path& at) {
  LightState l;
  read_object(kLightFields, l, at, "a light object");
  return single_light(l.ambient, l.directed ? &l.direction : nullptr);
}

void Reader::lights(const Path& at) {
  std::size_t k = 0;
  for (bool more = in.array_begin(); more; more = in.array_next(), ++k) {
    const Path entry = element(at, k);
    if (k == kMaxLights) invalid(at, "at most " + std::to_string(kMaxLights) + " lights");
    LightsEntry l;
    read_object(kLightsFields, l, entry, "a light object");
    if (!l.typed) invalid(entry, "missing \"type\": \"ambient\", \"directional\" or \"point\"");
    if (l.light.kind == LightKind::point && !(l.seen & format::mask_of(kLightsFields, {"position"})))
      invalid(entry, "a point light needs \"position\": [x, y, z]");
    scene.lights.push_back(l.light);
  }
  if (k == 0) invalid(at, "an empty list of lights; leave \"lights\" out for the default ones");
}

// Scale first, then rotate about x, y and z, then translate: T * Rz * Ry * Rx * S; or "matrix" as given.
Mat4 Reader::transform(const Path& at) {
  TransformState t;
  read_object(kTransformFields, t, at, "a transform object");
  if (t.seen & 8u) {  // "matrix"
    if (t.seen != 8u) invalid(at, "\"matrix\" replaces translate/rotate/scale; give one or the other");
    return t.matrix;
  }
  Mat4 m;
  m(0, 0) = t.scale.x, m(1, 1) = t.scale.y, m(2, 2) = t.scale.z;
  const double angles[3] = {t.rotate.x, t.rotate.y, t.rotate.z};
  for (int axis = 0; axis < 3 && (t.seen & 2u); ++axis) {
    const double rad = angles[axis] * std::numbers::pi / 180.0, c = std::cos(rad), sn = std::sin(rad);
    Mat4 rot;
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    rot(a, a) = c, rot(a, b) = -sn, rot(b, a) = sn, rot(b, b) = c;
    m = detail::operator*(rot, m);
  }
  Mat4 tm;
  tm(0, 3) = t.translate.x, tm(1, 3) = t.translate.y, tm(2, 3) = t.translate.z;
  return (t.seen & 1u) ? detail::operator*(tm, m) : m;
}

// true, false, or an object of the edges' colour, width and crease angle (which turns them on).
Edges Reader::edges(const Path& at) {
  EdgesState e;
  if (in.peek() == Kind::boolean)
    e.edges.enabled = in.boolean();
  else
    read_object(kEdgesFields, e, at, "an edges object"), e.edges.enabled = true;
  return e.edges;
}

// An image from "data" or "source" (one of them), within the texels the scene has left (less `pending`,
// what the primitive being read holds already).
Texture Reader::texture(const Path& at, std::int64_t pending) {
  TextureState t;
  t.budget = texels_left(scene, limits) - pending;
  read_object(kTextureFields, t, at, "a texture object");
  if (std::popcount(t.seen & 3u) != 1)
    invalid(at, "a texture needs \"data\" (the PNG or JPEG file as base64) or \"source\" (an uploaded part)");
  t.texture.clamp = t.clamp;
  return std::move(t.texture);
}

}  // namespace raster::scene_reader
