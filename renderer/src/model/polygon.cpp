// Ear clipping (Meisters' two-ears theorem: a simple polygon of more than three corners has two
// non-overlapping ears) in the plane the polygon's Newell normal is most perpendicular to. Only reflex
// corners can lie inside an ear, so each ear test looks at those alone, and clipping an ear changes only
// its two neighbours: about n x r point tests for n corners, r of them reflex.
#include "model/polygon.h"

#include <cmath>
#include <string>

namespace raster {

void PolygonSplitter::split(std::span<const Vec3> corners, std::vector<std::array<std::uint32_t, 3>>& out) {
  const std::size_t n = corners.size();
  if (n < 3) return;
  if (n == 3) {
    out.push_back({0, 1, 2});
  } else if (n == 4) {  // the shorter diagonal, as tinyobjloader splits quads
    auto d2 = [&](std::size_t a, std::size_t b) {
      const Vec3 &p = corners[a], &q = corners[b];
      return (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y) + (q.z - p.z) * (q.z - p.z);
    };
    if (d2(0, 2) < d2(1, 3)) {
      out.push_back({0, 1, 2});
      out.push_back({0, 2, 3});
    } else {
      out.push_back({0, 1, 3});
      out.push_back({1, 2, 3});
    }
  } else {
    ear_clip(corners, out);
  }
}

void PolygonSplitter::charge(std::int64_t work, std::size_t n) {
  work_left_ -= work;
  if (meter_) meter_->add(static_cast<std::uint64_t>(work));
  if (work_left_ < 0)
    throw SceneError(ErrorKind::limit,
                     "the model's faces of many corners are too many or too concave to split into triangles "
                     "(the budget ran out at a face of " +
                         std::to_string(n) + " corners, " + std::to_string(reflexes_.size()) +
                         " of them reflex); split them into smaller faces before sending");
}

// Newell's normal; the polygon is seen along its largest component, mirrored where that component is
// negative, so that it runs counter-clockwise in 2D: `corners` -> p_.
void PolygonSplitter::project(std::span<const Vec3> corners) {
  const std::size_t n = corners.size();
  double nx = 0, ny = 0, nz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 &a = corners[i], &b = corners[(i + 1) % n];
    nx += (a.y - b.y) * (a.z + b.z), ny += (a.z - b.z) * (a.x + b.x), nz += (a.x - b.x) * (a.y + b.y);
  }
  const double ax = std::fabs(nx), ay = std::fabs(ny), az = std::fabs(nz);
  p_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& c = corners[i];
    if (az >= ax && az >= ay)
      p_[i] = {c.x, nz >= 0 ? c.y : -c.y};
    else if (ax >= ay)
      p_[i] = {c.y, nx >= 0 ? c.z : -c.z};
    else
      p_[i] = {c.z, ny >= 0 ? c.x : -c.x};
  }
}

void PolygonSplitter::ear_clip(std::span<const Vec3> corners,
                               std::vector<std::array<std::uint32_t, 3>>& out) {
  const std::size_t n = corners.size();
  // Twice the signed area of (a, b, c): positive when they turn counter-clockwise.
  auto turn = [](P2 a, P2 b, P2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); };
  project(corners);

  // The remaining polygon as a ring; reflex corners (turning clockwise) listed once: a corner never turns
  // from convex back to reflex as ears are clipped.
  prev_.resize(n), next_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    prev_[i] = static_cast<std::uint32_t>((i + n - 1) % n),
    next_[i] = static_cast<std::uint32_t>((i + 1) % n);
  reflex_.assign(n, 0), removed_.assign(n, 0), ear_.assign(n, 0);
  reflexes_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (turn(p_[prev_[i]], p_[i], p_[next_[i]]) < 0)
      reflex_[i] = 1, reflexes_.push_back(static_cast<std::uint32_t>(i));
  charge(static_cast<std::int64_t>(n) * static_cast<std::int64_t>(reflexes_.size() + 1), n);

  // An ear: a convex corner whose triangle with its neighbours holds no other corner (only reflex ones
  // can be inside; one at the same place as a corner of the triangle does not count).
  auto is_ear = [&](std::uint32_t i) {
    const std::uint32_t a = prev_[i], c = next_[i];
    const P2 pa = p_[a], pi = p_[i], pc = p_[c];
    if (turn(pa, pi, pc) <= 0) return false;
    for (const std::uint32_t r : reflexes_) {
      if (removed_[r] || !reflex_[r] || r == a || r == i || r == c) continue;
      const P2 q = p_[r];
      auto same = [&](P2 s) { return s.x == q.x && s.y == q.y; };
      if (turn(pa, pi, q) >= 0 && turn(pi, pc, q) >= 0 && turn(pc, pa, q) >= 0 && !same(pa) && !same(pi) &&
          !same(pc))
        return false;
    }
    return true;
  };
  for (std::uint32_t i = 0; i < n; ++i) ear_[i] = is_ear(i);

  std::size_t left = n;
  std::uint32_t v = 0;
  std::size_t misses = 0;  // corners passed since the last ear
  while (left > 3) {
    if (!ear_[v] && ++misses < left) {
      charge(1, n);
      v = next_[v];
      continue;
    }
    // An ear, or (after a whole round without one: the polygon crosses itself or is degenerate) the corner
    // at hand, so that the loop always ends with n - 2 triangles.
    const std::uint32_t a = prev_[v], c = next_[v];
    out.push_back({a, v, c});
    removed_[v] = 1;
    next_[a] = c, prev_[c] = a;
    --left;
    misses = 0;
    // Only the neighbours' ears change; a reflex neighbour may have become convex.
    charge(2 * static_cast<std::int64_t>(reflexes_.size() + 1), n);
    for (const std::uint32_t k : {a, c}) {
      if (reflex_[k] && turn(p_[prev_[k]], p_[k], p_[next_[k]]) >= 0) reflex_[k] = 0;
      ear_[k] = is_ear(k);
    }
    v = a;
  }
  out.push_back({prev_[v], v, next_[v]});
}

}  // namespace raster
