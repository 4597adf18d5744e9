// Issue 39: what a render reserves from a raster::Budget against what it really takes. Each model is parsed,
// planned, rendered and encoded in a forked child, so that the resident peak measured (VmHWM less VmRSS
// once the input is in memory) is that render's alone; the parent compares it with the bytes the child's
// recording budget was asked for. The service keeps a process within its cgroup only if the reservation
// is never under what is used, and it admits as much as it can only if the reservation is not far over.
#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>

#include "model_files.h"
#include "raster/raster.h"

namespace {

// What a reservation may be over the peak it covers (issue 50: within 1.3x). Measured 2026-12-02 (x86-64,
// glibc, Release, 2 render threads; estimate / peak): OBJ face-dense 1M 1.01, OBJ vertex-dense 300k 1.04,
// OBJ heightfield 600x600 1.03, STL binary 400k 1.06, STL ASCII 200k 1.24, PLY binary vertex-dense 300k 1.03,
// PLY binary face-dense 1M 1.01, GLB vertex-dense 300k 1.05, GLB face-dense 1M 1.02 (docs/memory.md).
// A reservation more than this over what is used wastes the budget: fewer requests are admitted than fit.
constexpr double kFactor = 1.3;

// Grants every ask, takes back what is released, and remembers the most it held at once: the estimate of
// the render's peak (what the service's pool would have had to have free).
class RecordingBudget final : public raster::Budget {
 public:
  bool reserve(std::int64_t bytes) noexcept override {
    const std::int64_t now = held_ += bytes;
    for (std::int64_t most = most_.load(); now > most && !most_.compare_exchange_weak(most, now);) {
    }
    ++asks_;
    return true;
  }
  void release(std::int64_t bytes) noexcept override { held_ -= bytes; }
  bool expired() const noexcept override { return false; }
  std::int64_t asked() const { return most_.load(); }
  int asks() const { return asks_.load(); }

 private:
  std::atomic<std::int64_t> held_{0}, most_{0};
  std::atomic<int> asks_{0};
};

// A /proc/self/status field in bytes ("VmRSS:     1234 kB"), -1 when absent.
std::int64_t status_bytes(const std::string& key) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.starts_with(key + ":")) return std::strtoll(line.c_str() + key.size() + 1, nullptr, 10) * 1024;
  return -1;
}

struct Measurement {
  std::int64_t estimate = 0;  ///< bytes the budget was asked for
  std::int64_t peak = 0;      ///< VmHWM - VmRSS at the start, bytes
  std::int64_t png = 0;       ///< bytes of the PNG (that the render really happened)
  /// After parse, plan, render and encode: the estimate so far and the peak so far (bytes), to tell which
  /// stage's cost a shortfall is in.
  std::int64_t stage_estimate[4] = {}, stage_peak[4] = {};
  char error[400] = {};  ///< what the child threw, if it did
};

const std::string kScene =
    R"({"width": 512, "height": 512, "primitives": [{"type": "model", "source": "model"}]})";

// Parses, plans, renders and encodes `uploads` with `scene` in a child process, as the service does (its
// malloc settings, the scene freed before the PNG is made), and returns the estimate and the peak.
Measurement measure(const raster::Uploads& uploads, const std::string& scene = kScene) {
  malloc_trim(0);  // what the parent freed is not the child's to reuse unseen
  int fds[2];
  if (::pipe(fds) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    Measurement m;
    // server/main.cpp's settings (rasterd::kMmapBytes, kTrimBytes, kArenas): the allocator the costs are for.
    mallopt(M_MMAP_THRESHOLD, 16 << 20);
    mallopt(M_TRIM_THRESHOLD, 32 << 20);
    mallopt(M_ARENA_MAX, 4);
    // The peak so far is the parent's (the input's making); "5" resets it to the resident size now.
    if (std::FILE* f = std::fopen("/proc/self/clear_refs", "w")) {
      std::fputs("5", f);
      std::fclose(f);
    }
    const std::int64_t start = status_bytes("VmRSS");
    try {
      RecordingBudget budget;
      raster::Limits limits;
      limits.budget = &budget;
      const auto stage = [&](int i) {
        m.stage_estimate[i] = budget.asked();
        m.stage_peak[i] = status_bytes("VmHWM") - start;
      };
      raster::Scene parsed = raster::parse_scene(scene, limits, uploads);
      stage(0);
      const raster::RenderPlan plan = raster::plan(parsed, limits, {2});
      stage(1);
      raster::RenderControl control;
      control.budget = &budget;
      raster::Image image = raster::render(parsed, plan, control);
      stage(2);
      parsed = {};
      m.png = static_cast<std::int64_t>(raster::encode_png(std::move(image), plan.png).size());
      stage(3);
      m.estimate = budget.asked();
    } catch (const std::exception& e) {
      std::snprintf(m.error, sizeof m.error, "%s", e.what());
    }
    m.peak = status_bytes("VmHWM") - start;
    const bool sent = ::write(fds[1], &m, sizeof m) == static_cast<ssize_t>(sizeof m);
    ::_exit(sent ? 0 : 1);
  }
  ::close(fds[1]);
  Measurement m;
  std::size_t got = 0;
  for (ssize_t n;
       got < sizeof m && (n = ::read(fds[0], reinterpret_cast<char*>(&m) + got, sizeof m - got)) > 0;)
    got += static_cast<std::size_t>(n);
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (got != sizeof m || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    std::snprintf(m.error, sizeof m.error, "the child ended without its measurement (status %d)", status);
  return m;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;  // g++ -fsanitize=address (make test-asan)
#else
constexpr bool kAddressSanitizer = false;
#endif

// The verdict for one model: the reservation covers the peak, and is within kFactor of it.
void expect_estimate_holds(const std::string& name, const std::string& bytes,
                           const std::string& scene = kScene) {
  // The reservations are for the Release build the service runs: under AddressSanitizer every allocation
  // carries redzones and freed memory is quarantined (the 1M-face OBJ peaked at 547 MB there, 229 here).
  if (kAddressSanitizer) GTEST_SKIP() << "peaks under AddressSanitizer are not the service's";
  const Measurement m = measure({{"model", bytes}}, scene);
  ASSERT_EQ(m.error[0], '\0') << name << ": " << m.error;
  ASSERT_GT(m.png, 0) << name;
  const double ratio = static_cast<double>(m.estimate) / static_cast<double>(m.peak);
  std::printf("[estimate] %-26s input %6.1f MB  estimate %7.1f MB  peak %7.1f MB  estimate/peak %.2f\n",
              name.c_str(), static_cast<double>(bytes.size()) / 1e6, static_cast<double>(m.estimate) / 1e6,
              static_cast<double>(m.peak) / 1e6, ratio);
  ::testing::Test::RecordProperty("estimate_bytes", std::to_string(m.estimate));
  ::testing::Test::RecordProperty("peak_bytes", std::to_string(m.peak));
  std::string stages;  // which stage's cost falls short, when one does
  const char* names[] = {"parse", "plan", "render", "encode"};
  for (int i = 0; i < 4; ++i) {
    char line[160];
    std::snprintf(line, sizeof line, "\n  after %-6s estimate %7.1f MB  peak %7.1f MB", names[i],
                  static_cast<double>(m.stage_estimate[i]) / 1e6, static_cast<double>(m.stage_peak[i]) / 1e6);
    stages += line;
  }
  std::printf("%s\n", stages.c_str() + 1);
  EXPECT_LE(m.peak, m.estimate) << name
                                << ": the render used more than it reserved; the service would let "
                                   "a process grow past its cgroup's limit";
  EXPECT_LE(static_cast<double>(m.estimate), kFactor * static_cast<double>(m.peak))
      << name << ": the reservation is more than " << kFactor << "x what is used";
  // The reader's own reservation, by the time the mesh is made, is what it holds: with what the render
  // reserves for its two threads (what no stage counts), it covers the reader's peak, and is within the
  // factor of it.
  const double parse = static_cast<double>(m.stage_estimate[0] + 2 * raster::cost::kRenderPerThread);
  EXPECT_LE(static_cast<double>(m.stage_peak[0]), parse) << name << ": the reader used more than it reserved";
  EXPECT_LE(parse, kFactor * static_cast<double>(m.stage_peak[0]) +
                       static_cast<double>(2 * raster::cost::kRenderPerThread))
      << name << ": the reader reserved more than " << kFactor << "x what it used";
}

// ---- Models, made by seeded code: big enough that a few MB of baseline noise do not matter ----

// Face-dense: four vertices and `faces` copies of one tiny triangle (plus one large one, so the camera
// frames a body much larger than the tiny triangle and drawing the copies stays cheap).
test::TestMesh face_dense(std::size_t faces) {
  test::TestMesh m;
  m.v = {{0, 0, 0}, {1.0 / 32, 0, 0}, {0, 1.0 / 32, 0}, {1, 1, 1}};
  m.faces.assign(faces, {0, 1, 2});
  m.faces.push_back({0, 1, 3});
  return m;
}

// Vertex-dense: `triangles` small triangles, each with three vertices of its own, scattered over a sphere.
test::TestMesh triangle_soup(std::size_t triangles, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), height(-1, 1), jitter(-0.01, 0.01);
  test::TestMesh m;
  m.v.reserve(3 * triangles);
  m.faces.reserve(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const double a = angle(rng), z = height(rng), r = std::sqrt(1 - z * z);
    const std::array<double, 3> c{r * std::cos(a), r * std::sin(a), z};
    const auto base = static_cast<std::uint32_t>(m.v.size());
    for (int k = 0; k < 3; ++k)
      m.v.push_back(
          {test::grid(c[0] + jitter(rng)), test::grid(c[1] + jitter(rng)), test::grid(c[2] + jitter(rng))});
    m.faces.push_back({base, base + 1, base + 2});
  }
  return m;
}

// Vertex-dense with shared vertices, as scanned and CAD meshes are: a bumpy heightfield of side x side
// vertices, two triangles per cell.
test::TestMesh heightfield(std::uint32_t side, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> bump(-0.02, 0.02);
  test::TestMesh m;
  for (std::uint32_t i = 0; i < side; ++i)
    for (std::uint32_t j = 0; j < side; ++j)
      m.v.push_back({static_cast<double>(i) / side, bump(rng), static_cast<double>(j) / side});
  for (std::uint32_t i = 0; i + 1 < side; ++i)
    for (std::uint32_t j = 0; j + 1 < side; ++j) {
      const std::uint32_t a = i * side + j;
      m.faces.push_back({a, a + 1, a + side + 1});
      m.faces.push_back({a, a + side + 1, a + side});
    }
  return m;
}

std::string obj_of(const test::TestMesh& m) {
  return test::write_obj(m);
}

// The face-dense OBJ written directly: "f 1 2 3" a million times is 8 MB, and is what issue 39's repro
// sent (4M lines of it).
std::string face_dense_obj(std::size_t faces) {
  std::string s = "v 0 0 0\nv 0.03125 0 0\nv 0 0.03125 0\nv 1 1 1\n";
  s.reserve(s.size() + 8 * faces + 16);
  for (std::size_t i = 0; i < faces; ++i) s += "f 1 2 3\n";
  return s + "f 1 2 4\n";
}

// ---- The cases: face-dense and vertex-dense in every format ----

// What would break: kObjPerCorner (tinyobjloader's index per corner and ours) set below what a face of a
// face-dense OBJ costs; issue 39's 33 MB OBJ of "f 1 2 3" peaked at 1.1 GB.
TEST(MemoryEstimate, FaceDenseObj) {
  expect_estimate_holds("OBJ face-dense 1M", face_dense_obj(1'000'000));
}

// What would break: kObjPerVertex (tinyobjloader's doubles, our floats) under a v line's cost.
TEST(MemoryEstimate, VertexDenseObj) {
  expect_estimate_holds("OBJ vertex-dense soup 300k", obj_of(triangle_soup(300'000, 39)));
}

// What would break: the per-vertex and per-corner costs together, for a mesh sharing its vertices.
TEST(MemoryEstimate, HeightfieldObj) {
  expect_estimate_holds("OBJ heightfield 600x600", obj_of(heightfield(600, 39)));
}

// What would break: kStlPerFacet under a binary facet's three corners and triangle.
TEST(MemoryEstimate, BinaryStl) {
  expect_estimate_holds("STL binary 400k", test::write_stl_binary(triangle_soup(400'000, 40)));
}

// What would break: the ASCII reader's reservation, grown in steps from the text's size, falling behind
// the facets it stores.
TEST(MemoryEstimate, AsciiStl) {
  expect_estimate_holds("STL ASCII 200k", test::write_stl_ascii(triangle_soup(200'000, 41)));
}

// What would break: kPlyPerVertex under a vertex's position (and the room for normal and colour).
TEST(MemoryEstimate, VertexDenseBinaryPly) {
  expect_estimate_holds("PLY binary vertex-dense 300k",
                        test::write_ply_binary(triangle_soup(300'000, 42), false));
}

// What would break: kPlyPerFace under a face's index list and triangle, or kRenderPerTriangle under what
// the render holds per triangle of a mesh whose triangles share few vertices.
// It found kRenderPerTriangle at 96 too low: the render adds 173 MB for 1M triangles over 4 vertices (about
// 169 bytes a triangle, where the other cases' readers had covered the shortfall); 192 since.
TEST(MemoryEstimate, FaceDenseBinaryPly) {
  expect_estimate_holds("PLY binary face-dense 1M", test::write_ply_binary(face_dense(1'000'000), false));
}

// What would break: kGltfPerVertex and kGltfPerByte (tinygltf's copy of the buffer) under what a GLB of
// many vertices costs.
TEST(MemoryEstimate, VertexDenseGlb) {
  expect_estimate_holds("GLB vertex-dense 300k",
                        test::write_glb(test::make_gltf(triangle_soup(300'000, 43), "", true)));
}

// What would break: kGltfPerTriangle under a triangle's cost when indices repeat four vertices.
TEST(MemoryEstimate, FaceDenseGlb) {
  expect_estimate_holds("GLB face-dense 1M",
                        test::write_glb(test::make_gltf(face_dense(1'000'000), "", true)));
}

// ---- Refusals and the deadline, asked of the readers and the render ----

// Grants asks until `grants` of them were granted, then refuses; remembers the refused ask.
class RefusingBudget final : public raster::Budget {
 public:
  explicit RefusingBudget(int grants) : grants_(grants) {}
  bool reserve(std::int64_t bytes) noexcept override {
    if (refusing.load() || grants_.fetch_sub(1) <= 0) {
      refused = bytes;
      return false;
    }
    return true;
  }
  bool expired() const noexcept override { return false; }
  std::atomic<bool> refusing{false};
  std::atomic<std::int64_t> refused{0};

 private:
  std::atomic<int> grants_;
};

// A refused reservation stops the OBJ reader before it builds anything: the exception names the bytes asked
// (what the first pass counted, as the mesh holds it: 4 positions and 1M + 1 triangles here), and the child
// that was refused took almost none of them. What would break: the reservation moved after the mesh is
// made, or a refusal ignored.
TEST(MemoryEstimate, ARefusedObjReservationThrowsBeforeTheModelIsBuilt) {
  constexpr std::size_t kFaces = 1'000'000;
  const std::string obj = face_dense_obj(kFaces);
  const auto asked = static_cast<std::int64_t>(sizeof(std::array<std::uint32_t, 3>) * (kFaces + 1) +
                                               sizeof(raster::Vec3f) * 4);
  {
    RefusingBudget budget(1);  // the scene's own ask is granted, the model's refused
    raster::Limits limits;
    limits.budget = &budget;
    try {
      raster::parse_scene(kScene, limits, {{"model", obj}});
      FAIL() << "a refused reservation must stop the parse";
    } catch (const raster::MemoryRefused& e) {
      EXPECT_EQ(e.bytes(), asked);
      EXPECT_EQ(budget.refused.load(), asked);
    }
  }
  // The same refusal in a child of its own: its peak is a small part of what the mesh would have taken
  // (12 bytes a triangle, 12 MB here).
  const raster::Uploads uploads{{"model", obj}};  // the request's bytes, in memory before the start
  malloc_trim(0);
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    if (std::FILE* f = std::fopen("/proc/self/clear_refs", "w")) std::fputs("5", f), std::fclose(f);
    const std::int64_t start = status_bytes("VmRSS");
    std::int64_t peak = -1;
    RefusingBudget budget(1);
    raster::Limits limits;
    limits.budget = &budget;
    try {
      raster::parse_scene(kScene, limits, uploads);
    } catch (const raster::MemoryRefused&) {
      peak = status_bytes("VmHWM") - start;
    } catch (...) {
    }
    ::_exit(::write(fds[1], &peak, sizeof peak) == sizeof peak ? 0 : 1);
  }
  ::close(fds[1]);
  std::int64_t peak = -2;
  const bool got = ::read(fds[0], &peak, sizeof peak) == sizeof peak;
  ::close(fds[0]);
  ::waitpid(pid, nullptr, 0);
  ASSERT_TRUE(got);
  ASSERT_GE(peak, 0) << "the child's parse did not throw MemoryRefused";
  std::printf("[estimate] refused OBJ reader: peak %.1f MB of %.1f MB asked\n",
              static_cast<double>(peak) / 1e6, static_cast<double>(asked) / 1e6);
  EXPECT_LT(peak, std::int64_t{4} << 20) << "the refused reader built " << peak << " bytes first";
}

// A budget that grants the parse and the plan but refuses the bins makes render() throw MemoryRefused,
// not return an image drawn without them, and not RenderCancelled (the service answers the two
// differently). What would break: bin_part's refusal taken for a deadline, or ignored.
TEST(MemoryEstimate, ARefusedBinReservationStopsTheRender) {
  RefusingBudget budget(1 << 30);
  raster::Limits limits;
  limits.budget = &budget;
  const std::string obj = obj_of(heightfield(64, 7));
  raster::Scene scene = raster::parse_scene(kScene, limits, {{"model", obj}});
  const raster::RenderPlan plan = raster::plan(scene, limits, {2});
  budget.refusing = true;  // from here: the render's own asks, the bins
  raster::RenderControl control;
  control.budget = &budget;
  try {
    raster::render(scene, plan, control);
    FAIL() << "the render went on without its bins' memory";
  } catch (const raster::MemoryRefused& e) {
    EXPECT_GT(e.bytes(), 0);
    EXPECT_EQ(e.bytes() % raster::cost::kRenderPerBinEntry, 0)
        << "what was refused is a count of bin entries";
  }
}

// Expired from the start: the OBJ reader looks every 65,536 lines, so a longer OBJ stops with
// RenderCancelled while it is read, not after. What would break: the readers no longer asking the budget,
// so a parse of a huge model runs on past the request's deadline.
TEST(MemoryEstimate, AnExpiredBudgetStopsTheObjReader) {
  class Expired final : public raster::Budget {
   public:
    bool reserve(std::int64_t) noexcept override { return true; }
    bool expired() const noexcept override { return true; }
  } budget;
  raster::Limits limits;
  limits.budget = &budget;
  const std::string obj = face_dense_obj(70'000);  // 70,005 lines
  EXPECT_THROW(raster::parse_scene(kScene, limits, {{"model", obj}}), raster::RenderCancelled);
  // Without a budget the same OBJ is read: it is the budget that stopped it.
  EXPECT_NO_THROW(raster::parse_scene(kScene, {}, {{"model", obj}}));
}

}  // namespace
