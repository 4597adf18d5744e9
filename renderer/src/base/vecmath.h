// Small vector and matrix helpers for the 3D path (double precision throughout).
#pragma once

#include <cmath>

#include "raster/scene.h"

namespace raster::detail {

inline Vec3 operator+(Vec3 a, Vec3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(Vec3 a, Vec3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator*(Vec3 a, double k) {
  return {a.x * k, a.y * k, a.z * k};
}
inline double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) {
  return std::sqrt(dot(a, a));
}
/// Unit vector along `a`; the zero vector stays zero (callers treat it as "no direction").
inline Vec3 normalize(Vec3 a) {
  const double n = length(a);
  return n > 0 && std::isfinite(n) ? a * (1.0 / n) : Vec3{};
}

inline Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += a(i, k) * b(k, j);
      r(i, j) = sum;
    }
  return r;
}

/// M (x, y, z, 1), all four components.
struct Vec4 {
  double x = 0, y = 0, z = 0, w = 0;
};
inline Vec4 transform(const Mat4& m, Vec3 p) {
  return {m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2) * p.z + m(0, 3),
          m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2) * p.z + m(1, 3),
          m(2, 0) * p.x + m(2, 1) * p.y + m(2, 2) * p.z + m(2, 3),
          m(3, 0) * p.x + m(3, 1) * p.y + m(3, 2) * p.z + m(3, 3)};
}
/// A point through an affine model matrix (w assumed 1).
inline Vec3 transform_point(const Mat4& m, Vec3 p) {
  const Vec4 r = transform(m, p);
  return {r.x, r.y, r.z};
}

/// The matrix that carries normals: the inverse transpose of M's upper 3x3 (adjugate transposed; the
/// determinant's magnitude does not matter for directions, its sign does).
inline Mat4 normal_matrix(const Mat4& m) {
  Mat4 n;
  auto c = [&](int r0, int c0, int r1, int c1) { return m(r0, c0) * m(r1, c1) - m(r0, c1) * m(r1, c0); };
  n(0, 0) = c(1, 1, 2, 2), n(0, 1) = -c(1, 0, 2, 2), n(0, 2) = c(1, 0, 2, 1);
  n(1, 0) = -c(0, 1, 2, 2), n(1, 1) = c(0, 0, 2, 2), n(1, 2) = -c(0, 0, 2, 1);
  n(2, 0) = c(0, 1, 1, 2), n(2, 1) = -c(0, 0, 1, 2), n(2, 2) = c(0, 0, 1, 1);
  const double det = m(0, 0) * n(0, 0) + m(0, 1) * n(0, 1) + m(0, 2) * n(0, 2);
  if (det < 0)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) n(i, j) = -n(i, j);
  n(3, 3) = 1;
  return n;
}

}  // namespace raster::detail
