#include "plan/view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/vecmath.h"

namespace raster::detail {
namespace {

[[noreturn]] void camera_error(const std::string& pointer, const std::string& message) {
  throw SceneError(ErrorKind::invalid, message, {pointer, 0, 0});
}

// The box of positions under the identity (a model's usual transform), in one pass the compiler vectorises:
// the floats' own minimum and maximum, as doubles, a zero of either sign as +0 (as the transform's sums give
// it), so the box is the bits the general loop below would find.
__attribute__((target_clones("avx2", "default"))) void untransformed_bounds(
    const std::vector<Vec3f>& positions, Vec3& lo, Vec3& hi) {
  float l[3] = {INFINITY, INFINITY, INFINITY}, h[3] = {-INFINITY, -INFINITY, -INFINITY};
  const float* c = &positions.data()->x;
  for (std::size_t i = 0; i < positions.size(); ++i)
    for (int k = 0; k < 3; ++k) l[k] = std::min(l[k], c[3 * i + k]), h[k] = std::max(h[k], c[3 * i + k]);
  lo = {std::min(lo.x, l[0] + 0.0), std::min(lo.y, l[1] + 0.0), std::min(lo.z, l[2] + 0.0)};
  hi = {std::max(hi.x, h[0] + 0.0), std::max(hi.y, h[1] + 0.0), std::max(hi.z, h[2] + 0.0)};
}

// World-space bounding box of every mesh's positions after its transform.
bool world_bounds(const Scene& scene, Vec3& lo, Vec3& hi) {
  bool any = false;
  lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.transform == Mat4{} && !mesh.positions.empty()) {  // finite positions (validate) stay finite
      untransformed_bounds(mesh.positions, lo, hi);
      any = true;
      continue;
    }
    for (const Vec3 p : mesh.positions) {
      const Vec3 w = transform_point(mesh.transform, p);
      if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) continue;
      lo = {std::min(lo.x, w.x), std::min(lo.y, w.y), std::min(lo.z, w.z)};
      hi = {std::max(hi.x, w.x), std::max(hi.y, w.y), std::max(hi.z, w.z)};
      any = true;
    }
  }
  return any;
}

// The side of the target a fitted eye is on for a named view, as a unit vector.
Vec3 side_of(View view) {
  switch (view) {
    case View::front:
      return {0, 0, 1};
    case View::back:
      return {0, 0, -1};
    case View::right:
      return {1, 0, 0};
    case View::left:
      return {-1, 0, 0};
    case View::top:
      return {0, 1, 0};
    case View::bottom:
      return {0, -1, 0};
    case View::iso:
      return normalize(Vec3{1, 1, 1});
  }
  return {0, 0, 1};
}

// A named view's direction for a camera whose up is `up`: the views are defined for +Y up, and turned by the
// rotation that takes +Y to `up` (Rodrigues), so "front" with ?up=+z looks at a Z-up model from its front
// (from -Y), as CAD tools do, instead of straight down the up axis.
Vec3 relative_to_up(const Vec3& d, const Vec3& up) {
  const Vec3 y{0, 1, 0}, u = normalize(up);
  const double c = dot(y, u);
  Vec3 axis = cross(y, u);
  const double s = length(axis);
  if (!(s > 1e-12)) return c > 0 ? d : Vec3{d.x, -d.y, -d.z};  // +Y: as it is; -Y: half a turn about x
  axis = axis * (1 / s);
  return d * c + cross(axis, d) * s + axis * (dot(axis, d) * (1 - c));
}

// The basis of a camera at v.eye looking at v.target with v.up; a camera error when either is degenerate.
ViewBasis basis_of(const ViewPlan& v) {
  const Vec3 forward = normalize(v.target - v.eye);
  if (length(forward) == 0)  // only a fitted target can meet a given eye: validate() rejects the rest
    camera_error("/camera/eye",
                 "\"eye\" and \"target\" are the same point: the camera has no view direction");
  const Vec3 side = normalize(cross(forward, v.up));
  // sin of the angle between up and the view direction; below ~1e-9 the basis is not defined.
  if (length(side) == 0 || length(cross(forward, normalize(v.up))) < 1e-9)
    camera_error("/camera/up", "\"up\" is parallel to the view direction, so the image has no defined up");
  return {side, cross(side, forward), forward};
}

// Near and far: the content's extent (the box lo..hi) along the view direction, unless the camera gives them.
void fit_depth_range(const Camera& cam, const Vec3& lo, const Vec3& hi, const Vec3& forward, ViewPlan& v) {
  double d_min = INFINITY, d_max = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    const double d = dot(corner - v.eye, forward);
    d_min = std::min(d_min, d), d_max = std::max(d_max, d);
  }
  v.far = cam.has_far ? cam.far : std::max(d_max * 1.01, 1e-9);
  // With the eye inside the content's box, content may be arbitrarily close: take a thousandth of the
  // distance to the target, as viewers do (not a fraction of `far`, which an outlying vertex can make
  // astronomically large). Reversed float depth keeps precision for near/far ratios down to ~1e-38.
  v.near = cam.has_near
               ? cam.near
               : (d_min > 0 ? d_min * 0.99 : std::max(length(v.target - v.eye) * 1e-3, v.far * 1e-30));
  if (!cam.has_far && v.near >= v.far) v.far = v.near * 2;
  if (!(v.near < v.far)) camera_error("/camera/near", "\"near\" must be less than \"far\"");
}

// Projection x view: world space to clip space with reversed depth. `half`: half the vertical field of view,
// radians.
Mat4 world_to_clip(const ViewPlan& v, const ViewBasis& b, double half, double aspect) {
  Mat4 view;
  const Vec3 rows[3] = {b.side, b.up, b.forward * -1.0};
  for (int r = 0; r < 3; ++r) {
    view(r, 0) = rows[r].x, view(r, 1) = rows[r].y, view(r, 2) = rows[r].z;
    view(r, 3) = -dot(rows[r], v.eye);
  }
  Mat4 proj;  // maps view space (looking down -z) to clip space with reversed depth
  const double n = v.near, f = v.far;
  if (v.projection == Projection::perspective) {
    proj(0, 0) = 1 / (std::tan(half) * aspect);
    proj(1, 1) = 1 / std::tan(half);
    proj(2, 2) = n / (f - n), proj(2, 3) = n * f / (f - n);  // z = n (f - d) / (f - n) with d = -z_view
    proj(3, 2) = -1, proj(3, 3) = 0;                         // w = d
  } else {
    proj(0, 0) = 2 / (v.height * aspect);
    proj(1, 1) = 2 / v.height;
    proj(2, 2) = 1 / (f - n), proj(2, 3) = f / (f - n);  // z = (f - d) / (f - n), w = 1
  }
  return proj * view;
}

}  // namespace

ViewPlan resolve_view(const Scene& scene, double aspect) {
  const Camera& cam = scene.camera;
  Vec3 lo, hi;
  if (!world_bounds(scene, lo, hi)) lo = {-1, -1, -1}, hi = {1, 1, 1};
  const Vec3 centre = (lo + hi) * 0.5;
  double radius = length(hi - lo) * 0.5;
  if (!(radius > 0)) radius = std::max(1.0, length(centre)) * 1e-6;  // a single point: any small sphere

  ViewPlan v;
  v.projection = cam.projection;
  v.fov_deg = cam.fov_deg;
  v.up = cam.up;
  v.target = cam.has_target ? cam.target : centre;
  // Named views are relative to the up axis (a camera without `up` has +Y: the views as they are); looking
  // along it, the image's up is the model's back (top view: the front edge at the bottom, as in CAD).
  auto turned = [&](const Vec3& d) { return cam.has_up ? relative_to_up(d, cam.up) : d; };
  if (cam.view == View::top) v.up = turned({0, 0, -1});
  if (cam.view == View::bottom) v.up = turned({0, 0, 1});
  const double half = cam.fov_deg * std::numbers::pi / 360.0;
  // Distance at which the bounding sphere fits the narrower of the two fields of view.
  const double tan_fit = std::min(std::tan(half), std::tan(half) * aspect);
  const double fit_distance = radius * std::sqrt(1 + tan_fit * tan_fit) / tan_fit;
  v.eye = cam.has_eye ? cam.eye
                      : v.target + turned(side_of(cam.view)) * (fit_distance + length(v.target - centre));
  const ViewBasis basis = basis_of(v);
  fit_depth_range(cam, lo, hi, basis.forward, v);
  v.height = cam.has_height ? cam.height : 2 * length(v.target - v.eye) * std::tan(half);
  v.world_to_clip = world_to_clip(v, basis, half, aspect);
  v.lights = place_lights(scene.lights, v.eye, basis);
  return v;
}

}  // namespace raster::detail
