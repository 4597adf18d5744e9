// Area shares: the share of a pixel's square inside one or more half-planes, the closed forms and the
// clipping that area coverage (coverage.h, cover_area) takes for each pixel an edge cuts.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace raster::detail {

/// Area coverage: the share of a pixel's square inside a shape (a triangle, a line quad), in (0, 1], for the
/// pixels an edge cuts.
/// Entry 8 r + i is pixel (x0 + i, y0 + r) of the block; only the entries of `partial`'s set bits are
/// meaningful.
struct AreaCover {
  std::uint64_t partial = 0;  ///< pixels cut by an edge: some but not all of their square is inside
  float share[64];            ///< covered share of those pixels' squares
};

namespace coverage_detail {

/// The share of the unit square [0, 1]^2 where t + A (u - 1/2) + B (v - 1/2) >= 0, for a line that crosses
/// it (|t| < (|A| + |B|) / 2). It depends only on t, p = max(|A|, |B|) and q = min(|A|, |B|): a trapezoid
/// while the line crosses two opposite sides, a corner triangle (or its complement) beyond that. What
/// depends only on the edge (its steps A, B) is worked out once per record, so a cut pixel's share takes no
/// division.
struct HalfPlane {
  double band = 0;     ///< |t| up to which the line crosses two opposite sides: (p - q) / 2
  double reach = 0;    ///< (p + q) / 2: |t| at the far corner
  double inv_p = 0;    ///< 1 / p
  double inv_2pq = 0;  ///< 1 / (2 p q), or 0 for an axis-aligned edge (q = 0, always within the band)
  HalfPlane() = default;
  HalfPlane(double A, double B) {
    const double p = std::max(std::fabs(A), std::fabs(B)), q = std::min(std::fabs(A), std::fabs(B));
    band = (p - q) / 2, reach = (p + q) / 2, inv_p = 1 / p, inv_2pq = q > 0 ? 1 / (2 * p * q) : 0;
  }
  double share(double t) const {
    if (std::fabs(t) <= band) return 0.5 + t * inv_p;
    const double r = reach - std::fabs(t);
    const double corner = r * r * inv_2pq;
    return t > 0 ? 1 - corner : corner;
  }
};

/// The share of the unit square inside several half-planes t_k + A_k (u - 1/2) + B_k (v - 1/2) >= 0: the
/// square clipped by each (Sutherland-Hodgman), then the shoelace area. Near a vertex, and in slivers.
inline double clipped_share(int n, const double* t, const double* A, const double* B) {
  double xs[2][8] = {{0, 1, 1, 0}}, ys[2][8] = {{0, 0, 1, 1}};
  int count = 4, from = 0;
  for (int k = 0; k < n && count > 0; ++k) {
    const double* x = xs[from];
    const double* y = ys[from];
    double* ox = xs[1 - from];
    double* oy = ys[1 - from];
    double f[8];
    for (int j = 0; j < count; ++j) f[j] = t[k] + A[k] * (x[j] - 0.5) + B[k] * (y[j] - 0.5);
    int out = 0;
    for (int j = 0; j < count; ++j) {
      const int next = j + 1 == count ? 0 : j + 1;
      if (f[j] >= 0) ox[out] = x[j], oy[out] = y[j], ++out;
      if ((f[j] >= 0) != (f[next] >= 0)) {
        const double s = f[j] / (f[j] - f[next]);
        ox[out] = x[j] + s * (x[next] - x[j]), oy[out] = y[j] + s * (y[next] - y[j]), ++out;
      }
    }
    count = out, from = 1 - from;
  }
  double twice = 0;
  for (int j = 0; j < count; ++j) {
    const int next = j + 1 == count ? 0 : j + 1;
    twice += xs[from][j] * ys[from][next] - xs[from][next] * ys[from][j];
  }
  return std::fabs(twice) / 2;
}

/// The share of the unit square inside two half-planes whose lines both cross it (each as in
/// HalfPlane), in closed form unless the lines meet inside the square. Lines that do not meet there
/// cut it into three strips, and the half-planes either face each other (their intersection is the middle
/// strip: a0 + a1 - 1 of the square) or nest (the smaller one: min(a0, a1)). That is every pixel along a
/// sliver or a line's diagonal but the few at a vertex, which are clipped.
inline double two_edge_share(const double* t, const double* A, const double* B, const HalfPlane& h0,
                             const HalfPlane& h1) {
  // The lines meet at (nx, ny) / det from the pixel centre (Cramer's rule), inside the square when both
  // coordinates are within 1/2: compared without dividing, so parallel lines (det 0) never meet.
  const double det = A[0] * B[1] - A[1] * B[0];
  const double nx = t[1] * B[0] - t[0] * B[1], ny = A[1] * t[0] - A[0] * t[1];
  if (std::fabs(nx) <= 0.5 * std::fabs(det) && std::fabs(ny) <= 0.5 * std::fabs(det))
    return clipped_share(2, t, A, B);
  // Nested when the corner deepest outside one line is outside the other too.
  auto deepest_outside = [&](int k, int other) {
    const double x = A[k] > 0 ? -0.5 : 0.5, y = B[k] > 0 ? -0.5 : 0.5;
    return t[other] + A[other] * x + B[other] * y < 0;
  };
  const double a0 = h0.share(t[0]), a1 = h1.share(t[1]);
  if (deepest_outside(0, 1) || deepest_outside(1, 0)) return std::min(a0, a1);
  return std::max(0.0, a0 + a1 - 1);
}

}  // namespace coverage_detail
}  // namespace raster::detail
