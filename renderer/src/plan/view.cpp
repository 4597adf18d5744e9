#include "plan/view.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "base/vecmath.h"
#include "plan/light.h"

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
    case View::three_quarter: {
      const double azimuth = kThreeQuarterAzimuthDeg * std::numbers::pi / 180;
      const double elevation = kThreeQuarterElevationDeg * std::numbers::pi / 180;
      return {std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
              std::cos(azimuth) * std::cos(elevation)};
    }
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

// The content's extent along the view direction, as distances from the eye: its box's corners'.
void box_depths(const Vec3& lo, const Vec3& hi, const Vec3& forward, const Vec3& eye, double& d_min,
                double& d_max) {
  d_min = INFINITY, d_max = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    const double d = dot(corner - eye, forward);
    d_min = std::min(d_min, d), d_max = std::max(d_max, d);
  }
}

// Near and far: the content's extent along the view direction (d_min..d_max from the eye), unless the
// camera gives them.
void fit_depth_range(const Camera& cam, double d_min, double d_max, ViewPlan& v) {
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

// The four one-sided extents of the points as the camera sees them, and their depths: with (x, y, z) a
// point's coordinates along the basis (side, up, forward) and k the tangents of the frame's half-angles less
// the margin (0 for orthographic), the largest x - kx z, -x - kx z, y - ky z, -y - ky z, and the smallest and
// largest z.
struct Spread {
  double right = -INFINITY, left = -INFINITY, top = -INFINITY, bottom = -INFINITY;
  double z_min = INFINITY, z_max = -INFINITY;
  void add(const Vec3& p, const ViewBasis& b, double kx, double ky) {
    const double x = dot(p, b.side), y = dot(p, b.up), z = dot(p, b.forward);
    right = std::max(right, x - kx * z), left = std::max(left, -x - kx * z);
    top = std::max(top, y - ky * z), bottom = std::max(bottom, -y - ky * z);
    z_min = std::min(z_min, z), z_max = std::max(z_max, z);
  }
};

// Spread::add over a mesh's positions under the identity, in one pass the compiler vectorises (max and min
// are exact, so the lanes' order does not change a bit).
__attribute__((target_clones("avx2", "default"))) void untransformed_spread(
    const std::vector<Vec3f>& positions, const ViewBasis& b, double kx, double ky, Spread& s) {
  for (const Vec3f& p : positions) s.add({p.x + 0.0, p.y + 0.0, p.z + 0.0}, b, kx, ky);
}

// The points' screen extent from an eye at `e` (in the basis), as tangents of the angle off the view's
// axis: the smallest and largest (x - ex) / (z - ez) and (y - ey) / (z - ez).
struct Extent {
  double x_min = INFINITY, x_max = -INFINITY, y_min = INFINITY, y_max = -INFINITY;
  void add(const Vec3& p, const ViewBasis& b, const Vec3& e) {
    const double depth = dot(p, b.forward) - e.z;
    const double x = (dot(p, b.side) - e.x) / depth, y = (dot(p, b.up) - e.y) / depth;
    x_min = std::min(x_min, x), x_max = std::max(x_max, x), y_min = std::min(y_min, y),
    y_max = std::max(y_max, y);
  }
};
__attribute__((target_clones("avx2", "default"))) void untransformed_extent(
    const std::vector<Vec3f>& positions, const ViewBasis& b, const Vec3& e, Extent& s) {
  for (const Vec3f& p : positions) s.add({p.x + 0.0, p.y + 0.0, p.z + 0.0}, b, e);
}

// `visit(point)` over every finite world position of the scene's meshes: a mesh under the identity
// through `untransformed` (one vectorised pass over its positions), the others point by point.
template <typename Untransformed, typename Visit>
void each_world_point(const Scene& scene, Untransformed&& untransformed, Visit&& visit) {
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.transform == Mat4{}) {
      untransformed(mesh.positions);
      continue;
    }
    for (const Vec3 p : mesh.positions) {
      const Vec3 w = transform_point(mesh.transform, p);
      if (std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z)) visit(w);
    }
  }
}

/// What fit_to_vertices finds besides the eye: the content's depths from the eye, and the picture's shift
/// (in NDC, a lens shift) that centres it on the axis the distance does not fix.
struct VertexFit {
  double d_min = 0, d_max = 0;
  double shift_x = 0, shift_y = 0;
};

// CameraFit::vertices: where the eye goes for the view `b` so that every vertex lies within the frame less
// its margin and touches it on the tighter axis, the picture centred (Camera's words). In perspective, with
// the eye at (ex, ey, ez) in the basis, a point is inside the right edge when x - ex <= kx (z - ez), that is
// ex - kx ez >= x - kx z for every point, and inside the left when -ex - kx ez >= -x - kx z: both hold with
// equality (the picture touching both edges, so centred) at ez = -(right + left) / (2 kx), ex = (right -
// left) / 2, and any eye further back keeps them. The eye takes the further of the two axes' ez. On the
// other axis the picture then has room, which the slack of those inequalities does not split evenly on
// screen (the extreme points lie at different depths): a second pass measures the picture from the eye and
// shifts it to the middle. Orthographic has k = 0: the centre is the extents' midpoint and the height what
// holds them, in one pass. Also sets the target (on the view's axis at the content's middle depth).
VertexFit fit_to_vertices(const Scene& scene, const ViewBasis& b, double half, double aspect, double radius,
                          ViewPlan& v) {
  const bool perspective = v.projection == Projection::perspective;
  const double ky = perspective ? std::tan(half) * (1 - 2 * kFitMargin) : 0, kx = ky * aspect;
  Spread s;
  each_world_point(
      scene, [&](const std::vector<Vec3f>& positions) { untransformed_spread(positions, b, kx, ky, s); },
      [&](const Vec3& w) { s.add(w, b, kx, ky); });
  const double ex = (s.right - s.left) / 2, ey = (s.top - s.bottom) / 2;
  // The eye stays a little in front of the nearest vertex even when every vertex is on one line of sight.
  double ez = s.z_min - radius;
  if (perspective)
    ez = std::min({-(s.right + s.left) / (2 * kx), -(s.top + s.bottom) / (2 * ky), s.z_min - radius * 1e-3});
  else  // content all on one line of sight has no extent across: a frame of its sphere's size
    v.height =
        std::max({s.top + s.bottom, (s.right + s.left) / aspect, radius * 1e-3}) / (1 - 2 * kFitMargin);
  // + 0.0: a zero of either sign as +0, whichever of two equal extents the lanes' order kept.
  v.eye = b.side * (ex + 0.0) + b.up * (ey + 0.0) + b.forward * (ez + 0.0);
  v.target = v.eye + b.forward * ((s.z_min + s.z_max) / 2 - ez);
  VertexFit fit{s.z_min - ez, s.z_max - ez, 0, 0};
  if (perspective) {
    const Vec3 e{ex + 0.0, ey + 0.0, ez + 0.0};
    Extent x;
    each_world_point(
        scene, [&](const std::vector<Vec3f>& positions) { untransformed_extent(positions, b, e, x); },
        [&](const Vec3& w) { x.add(w, b, e); });
    const double t = std::tan(half);
    fit.shift_x = (x.x_min + x.x_max) / 2 / (t * aspect), fit.shift_y = (x.y_min + x.y_max) / 2 / t;
  }
  return fit;
}

// A flat model's side to be seen from (CameraFit::vertices, no view named): the world axis along which the
// content's box has no thickness (under a ten-thousandth of its largest side), signed toward where its
// faces' summed normal points, so its front is seen; nullopt for content with thickness.
std::optional<Vec3> flat_side(const Scene& scene, const Vec3& lo, const Vec3& hi) {
  const Vec3 size = hi - lo;
  const double sides[3] = {size.x, size.y, size.z};
  const int thin = static_cast<int>(std::min_element(sides, sides + 3) - sides);
  if (!(sides[thin] <= 1e-4 * std::max({size.x, size.y, size.z}))) return std::nullopt;
  Vec3 axis{thin == 0 ? 1.0 : 0.0, thin == 1 ? 1.0 : 0.0, thin == 2 ? 1.0 : 0.0};
  double facing = 0;
  for (const Mesh& mesh : scene.meshes)
    for (const auto& t : mesh.triangles) {
      const Vec3 a = transform_point(mesh.transform, mesh.positions[t[0]]);
      const Vec3 n = cross(transform_point(mesh.transform, mesh.positions[t[1]]) - a,
                           transform_point(mesh.transform, mesh.positions[t[2]]) - a);
      if (std::isfinite(dot(n, axis))) facing += dot(n, axis);
    }
  return facing < 0 ? axis * -1.0 : axis;
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
  const bool fit_vertices = cam.fit == CameraFit::vertices && !cam.has_eye && !cam.has_target;
  Vec3 side = turned(side_of(cam.view));
  View seen_as = cam.view;  // the named view the eye's side is, for the image's up along the up axis
  if (const auto flat = fit_vertices && !cam.has_view ? flat_side(scene, lo, hi) : std::nullopt) {
    side = *flat;
    const double along_up = dot(side, normalize(v.up));
    seen_as = along_up > 0.5 ? View::top : along_up < -0.5 ? View::bottom : cam.view;
  }
  if (seen_as == View::top) v.up = turned({0, 0, -1});
  if (seen_as == View::bottom) v.up = turned({0, 0, 1});
  const double half = cam.fov_deg * std::numbers::pi / 360.0;
  // Distance at which the bounding sphere fits the narrower of the two fields of view.
  const double tan_fit = std::min(std::tan(half), std::tan(half) * aspect);
  const double fit_distance = radius * std::sqrt(1 + tan_fit * tan_fit) / tan_fit;
  v.eye = cam.has_eye ? cam.eye : v.target + side * (fit_distance + length(v.target - centre));
  const ViewBasis basis = basis_of(v);
  VertexFit fit;
  if (fit_vertices)
    fit = fit_to_vertices(scene, basis, half, aspect, radius, v);
  else
    box_depths(lo, hi, basis.forward, v.eye, fit.d_min, fit.d_max);
  fit_depth_range(cam, fit.d_min, fit.d_max, v);
  if (cam.has_height)
    v.height = cam.height;
  else if (!(fit_vertices && v.projection == Projection::orthographic))
    v.height = 2 * length(v.target - v.eye) * std::tan(half);
  v.world_to_clip = world_to_clip(v, basis, half, aspect);
  if (fit.shift_x != 0 || fit.shift_y != 0) {  // the lens shift: x_ndc - shift_x, so x_clip - shift_x w
    Mat4 shift;
    shift(0, 3) = -fit.shift_x, shift(1, 3) = -fit.shift_y;
    v.world_to_clip = shift * v.world_to_clip;
  }
  v.lights = place_lights(scene.lights, v.eye, basis);
  return v;
}

}  // namespace raster::detail
