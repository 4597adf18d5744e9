// validate(): what a scene's own data must satisfy, whoever built it (the JSON reader or code).
#include <algorithm>
#include <cmath>
#include <string>

#include "raster/scene.h"

namespace raster {
namespace {

void check_references(const Scene& scene) {
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    if (p.kind == PrimitiveKind::mesh) continue;  // checked below
    const std::size_t colors = p.per_vertex_color ? p.point_count : 1;
    const bool ok = std::size_t{p.first_point} + p.point_count <= scene.points.size() &&
                    std::size_t{p.first_color} + colors <= scene.colors.size() &&
                    p.point_count == (p.kind == PrimitiveKind::triangle ? 3u
                                      : p.kind == PrimitiveKind::line   ? 2u
                                                                        : std::max(p.point_count, 2u));
    if (!ok)
      throw SceneError(ErrorKind::invalid, "primitive refers to points or colours the scene does not have",
                       {"/primitives/" + std::to_string(i), 0, 0});
  }
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    if (p.kind != PrimitiveKind::mesh) continue;
    const std::string where = "/primitives/" + std::to_string(i);
    if (p.mesh >= scene.meshes.size())
      throw SceneError(ErrorKind::invalid, "mesh primitive refers to a missing mesh", {where, 0, 0});
    const Mesh& m = scene.meshes[p.mesh];
    const std::size_t n = m.positions.size();
    bool ok = (m.colors.size() == 1 || m.colors.size() == n) &&
              (m.face_colors.empty() || m.face_colors.size() == m.triangles.size()) &&
              (m.normal_triangles.empty() || m.normal_triangles.size() == m.triangles.size());
    for (const auto& t : m.triangles) ok = ok && t[0] < n && t[1] < n && t[2] < n;
    for (const auto& s : m.segments) ok = ok && s[0] < n && s[1] < n;
    for (const auto& t : m.normal_triangles)
      ok = ok && t[0] < m.normals.size() && t[1] < m.normals.size() && t[2] < m.normals.size();
    for (const Vec3& q : m.positions)
      ok = ok && std::fabs(q.x) <= kMaxCoordinate && std::fabs(q.y) <= kMaxCoordinate &&
           std::fabs(q.z) <= kMaxCoordinate;
    if (!ok)
      throw SceneError(ErrorKind::invalid,
                       "mesh has indices, colours or normals that do not match its positions", {where, 0, 0});
  }
  // Scenes built in code skip the parser's checks; coverage relies on these bounds.
  for (std::size_t i = 0; i < scene.points.size(); ++i) {
    const Point2& q = scene.points[i];
    if (!(std::fabs(q.x) <= kMaxCoordinate && std::fabs(q.y) <= kMaxCoordinate))
      throw SceneError(ErrorKind::invalid,
                       "point " + std::to_string(i) + " is not finite or outside +-2^128");
  }
}

void check_camera_and_light(const Scene& scene) {
  const Camera& c = scene.camera;
  auto invalid = [](const char* pointer, const std::string& message) {
    throw SceneError(ErrorKind::invalid, message, {pointer, 0, 0});
  };
  if (c.up.x == 0 && c.up.y == 0 && c.up.z == 0) invalid("/camera/up", "\"up\" must not be the zero vector");
  if (!(c.fov_deg > 0 && c.fov_deg < 180))
    invalid("/camera/fov", "\"fov\" is the vertical field of view in degrees, strictly between 0 and 180");
  if (c.has_near && !(c.near > 0)) invalid("/camera/near", "\"near\" is a distance in front of the eye and must be > 0");
  if (c.has_far && !(c.far > 0)) invalid("/camera/far", "\"far\" must be > 0");
  if (c.has_near && c.has_far && !(c.near < c.far)) invalid("/camera/far", "\"far\" must be greater than \"near\"");
  if (c.has_height && !(c.height > 0))
    invalid("/camera/height", "\"height\" (orthographic view height) must be > 0");
  if (c.has_eye && c.has_target && c.eye == c.target)
    invalid("/camera/target", "\"eye\" and \"target\" are the same point: the camera has no view direction");
  const Light& l = scene.light;
  if (!l.headlight && l.direction == Vec3{})
    invalid("/light/direction", "the light direction must not be the zero vector");
  if (!(l.ambient >= 0 && l.ambient <= 1)) invalid("/light/ambient", "\"ambient\" is in 0..1");
}

}  // namespace

void validate(const Scene& scene) {
  if (scene.width < 1 || scene.height < 1)
    throw SceneError(ErrorKind::invalid, "image size must be at least 1x1");
  if (scene.samples != 1 && scene.samples != 4 && scene.samples != 8 && scene.samples != 16)
    throw SceneError(ErrorKind::invalid, "\"antialias\" must be 1, 4, 8 or 16 samples", {"/antialias", 0, 0});
  if (scene.area && scene.samples != 1)
    throw SceneError(ErrorKind::invalid, "\"antialias\" is either \"area\" or a sample count, not both",
                     {"/antialias", 0, 0});
  check_references(scene);
  check_camera_and_light(scene);
}

}  // namespace raster
