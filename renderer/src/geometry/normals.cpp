#include "geometry/normals.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>

#include "base/parallel.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace raster::detail {
namespace {

// Four triangles at a time, in doubles: the same operations, in the same order, as one triangle at a time
// would take (vecmath.h's dot, cross, length, normalize), so every lane width gives the same bits.
constexpr int kTriangles = 4;
using Lanes = double __attribute__((vector_size(8 * kTriangles)));

// sqrt in each lane, exactly rounded (two SSE2 square roots; AVX2 code splits one of four lanes anyway).
// In place: a function compiled without AVX cannot return 32 bytes of lanes the way AVX code would.
[[gnu::always_inline]] inline void square_root(Lanes& x) {
#if defined(__SSE2__)
  using Pair = double __attribute__((vector_size(16)));
  const Pair lo = _mm_sqrt_pd(__builtin_shufflevector(x, x, 0, 1));
  const Pair hi = _mm_sqrt_pd(__builtin_shufflevector(x, x, 2, 3));
  x = __builtin_shufflevector(lo, hi, 0, 1, 2, 3);
#else
  for (int i = 0; i < kTriangles; ++i) x[i] = std::sqrt(x[i]);
#endif
}

// acos to within 2e-8 rad (Abramowitz & Stegun 4.4.46), a square root and a polynomial: three per triangle
// were the costliest part of computing a model's normals (libm's acos), and an error this small is below
// what the float normals the records carry can hold (6e-8 relative).
[[gnu::always_inline]] inline void arc_cosine(Lanes& x) {
  const Lanes a = x < 0 ? -x : x;
  const Lanes p =
      1.5707963050 +
      a * (-0.2145988016 +
           a * (0.0889789874 +
                a * (-0.0501743046 +
                     a * (0.0308918810 + a * (-0.0170881256 + a * (0.0066700901 + a * -0.0012624911))))));
  Lanes r = 1 - a;
  square_root(r);
  r *= p;
  x = x < 0 ? std::numbers::pi - r : r;
}

// vecmath.h's "n > 0 && isfinite(n)" in lanes is 0 < n < infinity (NaN is neither).
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Per triangle of a batch: its unit face normal and the angle at each corner.
struct Corners {
  Lanes face[3];   // x, y, z
  Lanes angle[3];  // at vertex k
};

// Triangles `t[0..kTriangles)` (positions p[corner][axis][lane]) -> their face normals and corner angles.
[[gnu::always_inline]] inline void measure(const Lanes (&p)[3][3], Corners& out) {
  // Edge k runs from vertex k to the next.
  Lanes edge[3][3];
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) edge[k][d] = p[(k + 1) % 3][d] - p[k][d];
  const Lanes* u = edge[0];  // p1 - p0
  Lanes v[3];                // p2 - p0
  for (int d = 0; d < 3; ++d) v[d] = p[2][d] - p[0][d];
  const Lanes face[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  Lanes n = face[0] * face[0] + face[1] * face[1] + face[2] * face[2];
  square_root(n);
  const Lanes scale = 1.0 / n;
  for (int d = 0; d < 3; ++d) out.face[d] = ((n > 0) & (n < kInfinity)) ? face[d] * scale : Lanes{};
  // Each length taken once (a zero-length edge: angle pi/2, as for a zero vector's direction).
  Lanes len[3];
  for (int k = 0; k < 3; ++k) {
    len[k] = edge[k][0] * edge[k][0] + edge[k][1] * edge[k][1] + edge[k][2] * edge[k][2];
    square_root(len[k]);
  }
  for (int k = 0; k < 3; ++k) {
    const int prev = (k + 2) % 3;  // the corner at vertex k is between edge k and the reversed edge before it
    const Lanes norms = len[k] * len[prev];
    const Lanes d = edge[k][0] * edge[prev][0] + edge[k][1] * edge[prev][1] + edge[k][2] * edge[prev][2];
    Lanes cosine = ((norms > 0) & (norms < kInfinity)) ? -d / norms : Lanes{};
    cosine = cosine < -1.0 ? Lanes{} - 1.0 : cosine;  // std::clamp's order: below, then above
    cosine = 1.0 < cosine ? Lanes{} + 1.0 : cosine;
    arc_cosine(cosine);
    out.angle[k] = cosine;
  }
}

// What every thread's accumulate reads, and the normals they write (each its own vertices).
struct NormalsJob {
  const Mesh& mesh;
  std::span<const Vec3> world;  ///< as vertex_normals takes it
  const std::uint8_t* needed;   ///< as vertex_normals takes it
  /// With more than one thread: the lowest and highest corner of each kSpan triangles in order, so that a
  /// thread skips the spans that cannot touch its vertices (in a scan's or a generator's order, most of
  /// them). Null with one thread, whose vertices are all.
  const std::array<std::uint32_t, 2>* spans;
  PodArray<Vec3>& normals;
};
constexpr std::size_t kSpan = 256;

// The normals of vertices [v0, v1) (those marked in `needed`, with kMarked): every triangle with a corner
// there adds its face normal times that corner's angle, in triangle order; batches of kTriangles measure
// their triangles together.
template <bool kIdentity, bool kMarked>
[[gnu::always_inline]] inline void accumulate(const NormalsJob& job, std::uint32_t v0, std::uint32_t v1,
                                              StopMeter& own) {
  const Mesh& mesh = job.mesh;
  PodArray<Vec3>& normals = job.normals;
  auto mine = [&](std::uint32_t v) { return v >= v0 && v < v1 && (!kMarked || job.needed[v]); };
  const std::size_t count = mesh.triangles.size();
  std::size_t batch[kTriangles];
  for (std::size_t t = 0; t < count;) {
    if (own.add(StopMeter::kRowWork)) return;  // the caller sees meter.stopped() and draws nothing
    int n = 0;
    for (; t < count && n < kTriangles; ++t) {
      if (job.spans && t % kSpan == 0) {  // a span none of whose corners can be mine is passed whole
        const auto [lo, hi] = job.spans[t / kSpan];
        if (hi < v0 || lo >= v1) {
          t += kSpan - 1;
          continue;
        }
      }
      const auto& tri = mesh.triangles[t];
      if (mine(tri[0]) || mine(tri[1]) || mine(tri[2])) batch[n++] = t;
    }
    if (n == 0) continue;
    // The lanes are built whole from the corners (a lane written into a vector in memory and the vector
    // read back stalled on each of the nine, a third of the time); spare lanes repeat a triangle, unused.
    for (int i = n; i < kTriangles; ++i) batch[i] = batch[n - 1];
    static_assert(kTriangles == 4);
    Lanes p[3][3] = {};  // each written below (the zeros are dead stores)
    for (int k = 0; k < 3; ++k) {
      Vec3 q[kTriangles];
      for (int i = 0; i < kTriangles; ++i) {
        const std::uint32_t v = mesh.triangles[batch[i]][k];
        if constexpr (kIdentity) {  // MeshView::world_at's bits
          const Vec3f& f = mesh.positions[v];
          q[i] = {f.x + 0.0, f.y + 0.0, f.z + 0.0};
        } else {
          q[i] = job.world[v];
        }
      }
      p[k][0] = Lanes{q[0].x, q[1].x, q[2].x, q[3].x};
      p[k][1] = Lanes{q[0].y, q[1].y, q[2].y, q[3].y};
      p[k][2] = Lanes{q[0].z, q[1].z, q[2].z, q[3].z};
    }
    Corners c;
    measure(p, c);
    for (int i = 0; i < n; ++i) {
      const auto& tri = mesh.triangles[batch[i]];
      const Vec3 face{c.face[0][i], c.face[1][i], c.face[2][i]};
      for (int k = 0; k < 3; ++k)
        if (mine(tri[k])) normals[tri[k]] = normals[tri[k]] + face * c.angle[k][i];
    }
  }
  for (std::uint32_t v = v0; v < v1; ++v) normals[v] = normalize(normals[v]);
}

// The four kinds of accumulate: under the identity or a transform, every vertex or the marked ones.
#define RASTER_ACCUMULATE_KINDS                                    \
  if (job.world.empty())                                           \
    return job.needed ? accumulate<true, true>(job, v0, v1, own)   \
                      : accumulate<true, false>(job, v0, v1, own); \
  return job.needed ? accumulate<false, true>(job, v0, v1, own) : accumulate<false, false>(job, v0, v1, own);

void accumulate_sse2(const NormalsJob& job, std::uint32_t v0, std::uint32_t v1, StopMeter& own) {
  RASTER_ACCUMULATE_KINDS
}
#if defined(__x86_64__)
__attribute__((target("avx2"))) void accumulate_avx2(const NormalsJob& job, std::uint32_t v0,
                                                     std::uint32_t v1, StopMeter& own) {
  RASTER_ACCUMULATE_KINDS
}
#endif
#undef RASTER_ACCUMULATE_KINDS

// A triangle's unit normal (zero when it has no area) and the angle at its corner `k`, in doubles, one
// triangle at a time: what a split vertex's groups are made of.
struct Corner {
  Vec3 face;
  double angle = 0;
};
Vec3 world_of(const Mesh& mesh, std::span<const Vec3> world, std::uint32_t v) {
  if (!world.empty()) return world[v];
  const Vec3f& f = mesh.positions[v];
  return Vec3{f.x + 0.0, f.y + 0.0, f.z + 0.0};
}
// The triangle's unit normal alone, as corner_of gives it: what marking the split vertices needs.
Vec3 face_of(const Mesh& mesh, std::span<const Vec3> world, const std::array<std::uint32_t, 3>& tri) {
  const Vec3 a = world_of(mesh, world, tri[0]);
  return normalize(cross(world_of(mesh, world, tri[1]) - a, world_of(mesh, world, tri[2]) - a));
}
Corner corner_of(const Mesh& mesh, std::span<const Vec3> world, const std::array<std::uint32_t, 3>& tri,
                 int k) {
  auto at = [&](std::uint32_t v) { return world_of(mesh, world, v); };
  const Vec3 p = at(tri[k]), a = at(tri[(k + 1) % 3]) - p, b = at(tri[(k + 2) % 3]) - p;
  Corner c;
  c.face = face_of(mesh, world, tri);
  const double norms = length(a) * length(b);
  c.angle = norms > 0 && std::isfinite(norms) ? std::acos(std::clamp(dot(a, b) / norms, -1.0, 1.0)) : 0;
  return c;
}

// Union-find over a vertex's faces, with path halving.
std::uint32_t root_of(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The corner normals of split vertex `v`, whose faces are entries [begin, end) of `out`: faces joined by an
// edge (v, w) of at most the crease (consecutive faces sharing w, in triangle order) are one group, and each
// entry takes the normalised sum of its group's face normals x corner angles (in triangle order); a face
// without area, or a group summing to zero, takes the vertex normal. `scratch` is reused between vertices.
struct SplitScratch {
  std::vector<Corner> corners;
  std::vector<std::array<std::uint32_t, 2>> edges;  // (other vertex, entry)
  std::vector<std::uint32_t> parent;
  std::vector<Vec3> sums;
};
void split_vertex(const Mesh& mesh, std::span<const Vec3> world, std::uint32_t v, const Vec3& vertex_normal,
                  double cos_crease, std::uint32_t begin, std::uint32_t end, CornerNormals& out,
                  SplitScratch& s) {
  const std::uint32_t d = end - begin;
  s.corners.resize(d), s.edges.clear(), s.parent.resize(d), s.sums.assign(d, Vec3{});
  for (std::uint32_t i = 0; i < d; ++i) {
    const auto& tri = mesh.triangles[out.triangle[begin + i]];
    const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
    s.corners[i] = corner_of(mesh, world, tri, k);
    s.parent[i] = i;
    s.edges.push_back({tri[(k + 1) % 3], i}), s.edges.push_back({tri[(k + 2) % 3], i});
  }
  std::sort(s.edges.begin(), s.edges.end());
  auto has_area = [&](std::uint32_t i) { return s.corners[i].face != Vec3{}; };
  for (std::size_t e = 1; e < s.edges.size(); ++e) {
    const std::uint32_t i = s.edges[e - 1][1], j = s.edges[e][1];
    if (s.edges[e - 1][0] != s.edges[e][0] || i == j || !has_area(i) || !has_area(j)) continue;
    if (dot(s.corners[i].face, s.corners[j].face) >= cos_crease) {
      const std::uint32_t a = root_of(s.parent, i), b = root_of(s.parent, j);
      s.parent[std::max(a, b)] = std::min(a, b);
    }
  }
  for (std::uint32_t i = 0; i < d; ++i) {
    Vec3& sum = s.sums[root_of(s.parent, i)];
    sum = sum + s.corners[i].face * s.corners[i].angle;
  }
  for (std::uint32_t i = 0; i < d; ++i) {
    const Vec3 n = has_area(i) ? normalize(s.sums[root_of(s.parent, i)]) : Vec3{};
    const Vec3 chosen = n == Vec3{} ? vertex_normal : n;
    out.normal[begin + i] = {static_cast<float>(chosen.x), static_cast<float>(chosen.y),
                             static_cast<float>(chosen.z)};
  }
}

// Step 1 of crease_normals: `split`, a byte a vertex, marks the vertices some face around which lies more
// than half the crease from the vertex normal: at every other vertex all faces lie within the crease of each
// other, one group, the vertex normal. False when none is marked (or the render stopped).
bool mark_splits(const Mesh& mesh, std::span<const Vec3> world, const PodArray<Vec3>& normals,
                 double cos_half, int threads, StopMeter& meter, const std::uint8_t* needed,
                 PodArray<std::uint8_t>& split) {
  const std::size_t nv = mesh.positions.size(), count = mesh.triangles.size();
  split.resize_uninitialized(nv);
  std::fill_n(split.data(), nv, std::uint8_t{0});
  constexpr std::size_t kPiece = 16384;
  std::atomic<bool> any{false};
  parallel_for(threads, (count + kPiece - 1) / kPiece, meter.stop(),
               [&](std::size_t piece, StopMeter& own, int) {
                 bool found = false;
                 for (std::size_t t = piece * kPiece; t < std::min(count, (piece + 1) * kPiece); ++t) {
                   if (own.add(StopMeter::kPrimitiveWork)) return;
                   const auto& tri = mesh.triangles[t];
                   if (needed && !(needed[tri[0]] | needed[tri[1]] | needed[tri[2]])) continue;
                   const Vec3 face = face_of(mesh, world, tri);
                   if (face == Vec3{}) continue;  // no area: no direction, part of no group
                   for (const std::uint32_t v : tri)
                     if ((!needed || needed[v]) && !(dot(face, normals[v]) >= cos_half)) {
                       std::atomic_ref<std::uint8_t>(split[v]).store(1, std::memory_order_relaxed);
                       found = true;
                     }
                 }
                 if (found) any.store(true, std::memory_order_relaxed);
               });
  return !meter.check() && any.load();
}

}  // namespace

const Vec3f* CornerNormals::at(std::uint32_t v, std::uint32_t t) const {
  if (slot.empty() || slot[v] == kSmooth) return nullptr;
  const std::uint32_t* b = triangle.data() + first[slot[v]];
  const std::uint32_t* e = triangle.data() + first[slot[v] + 1];
  const std::uint32_t* found = std::lower_bound(b, e, t);
  return found != e && *found == t ? &normal[static_cast<std::size_t>(found - triangle.data())] : nullptr;
}

CornerNormals crease_normals(const Mesh& mesh, std::span<const Vec3> world, const PodArray<Vec3>& normals,
                             int threads, StopMeter& meter, const std::uint8_t* needed) {
  CornerNormals out;
  if (!(mesh.crease_deg < 180)) return out;
  const double crease = mesh.crease_deg * std::numbers::pi / 180;
  const double cos_half = std::cos(crease / 2), cos_crease = std::cos(crease);
  const std::size_t nv = mesh.positions.size(), count = mesh.triangles.size();
  if (!meter.stop().reserve(static_cast<std::int64_t>(nv))) return out;
  PodArray<std::uint8_t> split;
  if (!mark_splits(mesh, world, normals, cos_half, threads, meter, needed, split)) return out;
  // 2. Each split vertex's faces, in triangle order (a counting sort by vertex).
  std::uint32_t splits = 0;
  if (!meter.stop().reserve(static_cast<std::int64_t>(nv * sizeof(std::uint32_t)))) return out;
  out.slot.resize_uninitialized(nv);
  for (std::size_t v = 0; v < nv; ++v) out.slot[v] = split[v] ? splits++ : CornerNormals::kSmooth;
  out.first.resize_uninitialized(splits + 1);
  std::fill_n(out.first.data(), splits + 1, 0u);
  for (const auto& tri : mesh.triangles)
    for (const std::uint32_t v : tri)
      if (out.slot[v] != CornerNormals::kSmooth) ++out.first[out.slot[v] + 1];
  for (std::uint32_t i = 0; i < splits; ++i) out.first[i + 1] += out.first[i];
  const std::uint32_t entries = out.first[splits];
  if (!meter.stop().reserve(static_cast<std::int64_t>(entries) * 16 + splits * 4)) return CornerNormals{};
  out.triangle.resize_uninitialized(entries), out.normal.resize_uninitialized(entries);
  {
    PodArray<std::uint32_t> fill;
    fill.resize_uninitialized(splits);
    std::copy_n(out.first.data(), splits, fill.data());
    for (std::size_t t = 0; t < count; ++t)
      for (const std::uint32_t v : mesh.triangles[t])
        if (out.slot[v] != CornerNormals::kSmooth)
          out.triangle[fill[out.slot[v]]++] = static_cast<std::uint32_t>(t);
  }
  // 3. The groups of each split vertex, on the render's threads, each with scratch for its largest vertex
  // (a face-dense model can have a vertex of a million faces).
  std::uint32_t most = 0;
  for (std::uint32_t i = 0; i < splits; ++i) most = std::max(most, out.first[i + 1] - out.first[i]);
  constexpr std::int64_t kScratchPerFace =
      sizeof(Corner) + 2 * sizeof(std::array<std::uint32_t, 2>) + sizeof(std::uint32_t) + sizeof(Vec3);
  constexpr std::size_t kVertices = 256;  // split vertices a piece
  const std::size_t pieces = (splits + kVertices - 1) / kVertices;
  const std::int64_t workers =
      std::min<std::int64_t>(std::max(threads, 1), static_cast<std::int64_t>(pieces));
  if (!meter.stop().reserve(workers * most * kScratchPerFace + splits * 8)) return CornerNormals{};
  PodArray<std::uint32_t> vertices;
  vertices.resize_uninitialized(splits);
  for (std::size_t v = 0; v < nv; ++v)
    if (out.slot[v] != CornerNormals::kSmooth) vertices[out.slot[v]] = static_cast<std::uint32_t>(v);
  parallel_for(threads, pieces, meter.stop(), [&](std::size_t piece, StopMeter& own, int) {
    SplitScratch scratch;
    for (std::size_t i = piece * kVertices; i < std::min<std::size_t>(splits, (piece + 1) * kVertices); ++i) {
      if (own.add((out.first[i + 1] - out.first[i]) * StopMeter::kPrimitiveWork)) return;
      const std::uint32_t v = vertices[i];
      split_vertex(mesh, world, v, normals[v], cos_crease, out.first[i], out.first[i + 1], out, scratch);
    }
  });
  meter.check();
  return out;
}

PodArray<Vec3> vertex_normals(const Mesh& mesh, std::span<const Vec3> world, int threads, Simd simd,
                              StopMeter& meter, const std::uint8_t* needed) {
  const std::size_t nv = mesh.positions.size(), count = mesh.triangles.size();
  PodArray<Vec3> normals;
  normals.resize_uninitialized(nv);
  const std::size_t pieces = static_cast<std::size_t>(std::max(threads, 1));
  PodArray<std::array<std::uint32_t, 2>> spans;
  if (pieces > 1) {
    spans.resize_uninitialized((count + kSpan - 1) / kSpan);
    parallel_for(threads, pieces, meter.stop(), [&](std::size_t piece, StopMeter&, int) {
      for (std::size_t s = spans.size() * piece / pieces; s < spans.size() * (piece + 1) / pieces; ++s) {
        std::uint32_t lo = 0xffffffffu, hi = 0;
        for (std::size_t t = s * kSpan; t < std::min(count, (s + 1) * kSpan); ++t)
          for (std::uint32_t v : mesh.triangles[t]) lo = std::min(lo, v), hi = std::max(hi, v);
        spans[s] = {lo, hi};
      }
    });
  }
  const NormalsJob job{mesh, world, needed, spans.empty() ? nullptr : spans.data(), normals};
  parallel_for(threads, pieces, meter.stop(), [&](std::size_t piece, StopMeter& own, int) {
    const std::uint32_t v0 = static_cast<std::uint32_t>(nv * piece / pieces),
                        v1 = static_cast<std::uint32_t>(nv * (piece + 1) / pieces);
    std::fill(normals.data() + v0, normals.data() + v1, Vec3{});
#if defined(__x86_64__)
    if (simd == Simd::avx2) return accumulate_avx2(job, v0, v1, own);
#endif
    (void)simd;
    accumulate_sse2(job, v0, v1, own);
  });
  meter.check();
  return normals;
}

}  // namespace raster::detail
