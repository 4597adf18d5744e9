// rasterd's own OBJ reader (renderer/src/model/obj.cpp) against its oracle, the reader it replaced, which
// read through tinyobjloader (tests/oracle/obj_tinyobj.cpp): on every OBJ of Debian's assimp-testmodels, on
// seeded generated files of every statement the reader knows, and on those files spoiled, the two give the
// same mesh or the same error. The reader's pieces (text split at line ends, read on several threads) give
// the same mesh however the text is cut and however many threads read it.
//
// The differences that are the oracle's own (documented in docs/memory.md's reader section and here): it
// keeps a model's normals when it has no faces to use them on (the new reader drops them, as it does for any
// face without them); a line or point statement after a material change is given again by tinyobjloader at
// each later change, and those of a group ("g") without faces are lost; the generator below writes neither.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "model/obj_text.h"
#include "oracle/obj_tinyobj.h"
#include "raster/model.h"
#include "support.h"

namespace {

using raster::Mesh;
using raster::SceneError;

// The meshes, field by field, with the oracle's normals of a faceless model left out.
void expect_same(const Mesh& ours, Mesh oracle, const std::string& what) {
  if (oracle.triangles.empty()) oracle.normals.clear(), oracle.normal_triangles.clear();
  EXPECT_EQ(ours.positions, oracle.positions) << what;
  EXPECT_EQ(ours.triangles, oracle.triangles) << what;
  EXPECT_EQ(ours.segments, oracle.segments) << what;
  EXPECT_EQ(ours.points, oracle.points) << what;
  EXPECT_EQ(ours.normals, oracle.normals) << what;
  EXPECT_EQ(ours.normal_triangles, oracle.normal_triangles) << what;
  EXPECT_EQ(ours.colors, oracle.colors) << what;
  EXPECT_EQ(ours.face_colors, oracle.face_colors) << what;
  EXPECT_EQ(ours.uvs, oracle.uvs) << what;
  EXPECT_EQ(ours.uv_triangles, oracle.uv_triangles) << what;
  EXPECT_EQ(ours.textures, oracle.textures) << what;
  EXPECT_EQ(ours.face_textures, oracle.face_textures) << what;
  EXPECT_EQ(ours.materials, oracle.materials) << what;
  EXPECT_EQ(ours.face_materials, oracle.face_materials) << what;
  oracle.crease_deg = raster::kModelCreaseDeg;  // the readers' rule (tinyobjloader computes no normals)
  EXPECT_EQ(ours == oracle, true) << what << ": a field not compared above differs";
}

struct Outcome {
  bool read = false;
  Mesh mesh;
  std::string error;  ///< what(), kind and line, when not read
};

template <typename Read>
Outcome outcome(Read&& read) {
  Outcome o;
  try {
    o.mesh = read();
    o.read = true;
  } catch (const SceneError& e) {
    o.error = std::string(e.what()) + " [kind " + std::to_string(static_cast<int>(e.kind())) + ", line " +
              std::to_string(e.where().line) + ", byte " + std::to_string(e.where().byte) + "]";
  }
  return o;
}

// The two readers on the same text: both read it alike, or both refuse it in the same words at the same
// place.
void expect_agree(const std::string& obj, const std::string& mtl, const raster::Uploads& files,
                  const std::string& what, const raster::Limits& limits = {}) {
  const Outcome ours = outcome([&] { return raster::parse_obj(obj, mtl, limits, files); });
  const Outcome oracle = outcome([&] { return raster::oracle::parse_obj_tinyobj(obj, mtl, limits, files); });
  ASSERT_EQ(ours.read, oracle.read) << what << ": ours " << (ours.read ? "read it" : ours.error)
                                    << "; oracle " << (oracle.read ? "read it" : oracle.error);
  if (ours.read)
    expect_same(ours.mesh, oracle.mesh, what);
  else
    EXPECT_EQ(ours.error, oracle.error) << what;
}

// Every OBJ of assimp's test models, with the files of its folder as a user would upload them.
TEST(ObjReader, TheCorpusReadsAsTheOracleReadsIt) {
  const std::filesystem::path root = "/usr/share/assimp/models/OBJ";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << "assimp-testmodels is not installed";
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root)) {
    if (entry.path().extension() != ".obj") continue;
    raster::Uploads files;
    for (const auto& f : std::filesystem::directory_iterator(root))
      if (f.is_regular_file() && f.path() != entry.path() && f.file_size() < (8 << 20))
        files[f.path().filename().string()] = test::read_file(f.path().string());
    expect_agree(test::read_file(entry.path().string()), {}, files, entry.path().filename().string());
    ++compared;
  }
  EXPECT_GE(compared, 20);
  expect_agree(test::read_file(RASTERD_EXAMPLES_DIR "/models/knot.obj"), {}, {}, "knot.obj");
}

// A seeded OBJ of every statement: vertices (some with colours, numbers in every form exporters print),
// texture coordinates, normals, faces of three to seven corners with every kind of reference (relative
// ones too), materials with textures, comments, blank lines, CRLF and tabs, and lines and points at the end.
struct Generated {
  std::string obj, mtl;
  raster::Uploads files;
};

std::string number_text(std::mt19937& rng, double v) {
  char s[64];
  switch (rng() % 6) {
    case 0:
      std::snprintf(s, sizeof s, "%.6f", v);
      break;
    case 1:
      std::snprintf(s, sizeof s, "%.9g", v);
      break;
    case 2:
      std::snprintf(s, sizeof s, "%e", v);
      break;
    case 3:
      std::snprintf(s, sizeof s, "%+.4f", v);  // a leading '+'
      break;
    case 4:
      std::snprintf(s, sizeof s, "%.17g", v);
      break;
    default:
      std::snprintf(s, sizeof s, "%.3f", v);
      break;
  }
  return s;
}

Generated generate(unsigned seed, bool colours, bool textured) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-3, 3), unit(0, 1);
  Generated g;
  if (textured) {
    g.files["t.png"] = test::read_file(RASTERD_EXAMPLES_DIR "/../docs/images/gradient.png");
    g.mtl =
        "newmtl red\nKd 1 0 0\nnewmtl skin\nKd 0.5 0.5 0.5\nmap_Kd t.png\nnewmtl shiny\nKd 0 0 1\nKs 0.5 0.5 "
        "0.5\nNs 40\n";
  }
  std::string& s = g.obj;
  const char* eol = rng() % 4 ? "\n" : "\r\n";
  s += "# generated\r\n\n";
  if (textured) s += "mtllib m.mtl\n";
  int v = 0, vt = 0, vn = 0;
  auto vertex = [&] {
    s += rng() % 5 ? "v " : "v\t";
    for (int k = 0; k < 3; ++k) s += number_text(rng, coord(rng)) + (k < 2 ? "  " : "");
    if (colours)
      for (int k = 0; k < 3; ++k) s += " " + number_text(rng, unit(rng));
    s += eol;
    ++v;
  };
  for (int i = 0; i < 8; ++i) vertex();
  const char* materials[] = {"red", "skin", "shiny", "nowhere"};
  for (int round = 0; round < 40; ++round) {
    const unsigned what = rng() % 10;
    if (what < 3) {
      vertex();
    } else if (what == 3) {
      s += "vt " + number_text(rng, unit(rng)) + " " + number_text(rng, unit(rng)) + eol;
      ++vt;
    } else if (what == 4) {
      s += "vn " + number_text(rng, coord(rng)) + " " + number_text(rng, coord(rng)) + " " +
           number_text(rng, coord(rng)) + eol;
      ++vn;
    } else if (what == 5 && textured) {
      s += std::string("usemtl ") + materials[rng() % 4] + eol;
    } else if (what == 6) {
      s += rng() % 2 ? "o part\n" : "s 1\n# a comment\n\n";
    } else {
      const int n = 3 + static_cast<int>(rng() % 5);
      const unsigned kind =
          rng() % 4;  // v, v/vt, v//vn, v/vt/vn: the same for a whole face, as files have it
      s += "f";
      for (int k = 0; k < n; ++k) {
        auto ref = [&](int count) {
          const int i = 1 + static_cast<int>(rng() % static_cast<unsigned>(count));
          return rng() % 3 ? std::to_string(i) : std::to_string(i - count - 1);  // some relative
        };
        s += ' ', s += ref(v);  // (not " " + ref(v): g++ 12 warns of an overlap that cannot be, -Wrestrict)
        if ((kind == 1 || kind == 3) && vt > 0) s += '/', s += ref(vt);
        if (kind == 2 && vn > 0) s += "//", s += ref(vn);
        if (kind == 3 && vn > 0) s += (vt > 0 ? "/" : "//") + ref(vn);
      }
      s += eol;
    }
  }
  s += "l 1 2 3" + std::string(eol) + "p 4 5" + eol + "p -1";  // the last line without a line end
  return g;
}

TEST(ObjReader, GeneratedFilesReadAsTheOracleReadsThem) {
  for (unsigned seed = 1; seed <= 300; ++seed) {
    const Generated g = generate(seed, seed % 3 == 0, seed % 2 == 0);
    raster::Uploads files = g.files;
    if (!g.mtl.empty()) files["m.mtl"] = g.mtl;
    expect_agree(g.obj, {}, files, "seed " + std::to_string(seed));
    if (HasFailure()) return;
  }
}

// Spoiled copies of the generated files (a word replaced, a number made too large, a reference pointed past
// what is defined, a line cut): both readers refuse each at the same line, in the same words.
TEST(ObjReader, SpoiledFilesAreRefusedAsTheOracleRefusesThem) {
  const char* spoils[] = {"x", "1e400", "nan", "0", "99999", "-99999", "1//", "/",      "1/2/3/4",
                          "+", "1.5",   "",    "v", "f",     "vt",     "vn",  "3.5e38", "\xff"};
  std::mt19937 rng(7);
  int refused = 0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const Generated g = generate(seed, seed % 2 == 0, false);
    std::string obj = g.obj;
    // A random word of a random line (not the first, a comment) becomes a spoil.
    std::vector<std::size_t> starts;
    for (std::size_t i = 1; i < obj.size(); ++i)
      if (obj[i - 1] == ' ') starts.push_back(i);
    const std::size_t at = starts[rng() % starts.size()];
    std::size_t end = obj.find_first_of(" \r\n", at);
    if (end == std::string::npos) end = obj.size();
    obj.replace(at, end - at, spoils[rng() % std::size(spoils)]);
    expect_agree(obj, {}, {}, "seed " + std::to_string(seed) + ":\n" + obj);
    if (HasFailure()) return;
    refused += outcome([&] { return raster::parse_obj(obj); }).read ? 0 : 1;
  }
  EXPECT_GT(refused, 100);
}

// MTL text sent with a model is checked whether or not the model names a library (obj_fuzzer's finding: an
// MTL error was reported by the oracle alone when no `mtllib` line named it), and its materials are used only
// where a library is named.
TEST(ObjReader, GivenMaterialsAreCheckedWhenNoLibraryNamesThem) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string bad_mtl = "newmtl m\nmap_Kd -o x\n";
  for (const std::string& obj : {triangle, "usemtl mtllib a.mtl\n" + triangle, "mtllib a.mtl\n" + triangle}) {
    expect_agree(obj, bad_mtl, {}, obj);
    EXPECT_FALSE(outcome([&] { return raster::parse_obj(obj, bad_mtl); }).read) << obj;
  }
  const std::string red = "newmtl m\nKd 1 0 0\n";
  // "mtllib " with no name loads the given text too (tinyobjloader: a blank after the keyword); "mtllib"
  // alone does not.
  for (const std::string& obj : {"usemtl m\n" + triangle, "mtllib a.mtl\nusemtl m\n" + triangle,
                                 "mtllib \nusemtl m\n" + triangle, "mtllib\nusemtl m\n" + triangle})
    expect_agree(obj, red, {}, obj);
  EXPECT_FALSE(raster::parse_obj("mtllib \nusemtl m\n" + triangle, red).face_colors.empty());
  // A `newmtl` without a name starts no material (tinyobjloader's rule): the map after it is the material
  // before's (obj_fuzzer's finding: with two mtllib lines the oracle asked for the texture, the reader not).
  const std::string nameless = "newmtl a\nKd 1 0 0\nnewmtl\nmap_Kd x.png\n";
  for (const std::string& obj :
       {std::string("mtllib m\nmtllib \nv 0 0 0\n"), "mtllib a.mtl\nusemtl a\n" + triangle}) {
    expect_agree(obj, nameless, {}, obj);
    EXPECT_NE(outcome([&] { return raster::parse_obj(obj, nameless); }).error.find("x.png"),
              std::string::npos);
  }
}

// A CR with more of its line after it (classic Mac OS line ends, which tinyobjloader takes for line ends) is
// refused at its line, not read as more of the statement; CR LF, and a CR before the line's end, are blanks.
TEST(ObjReader, ACarriageReturnInsideALineIsRefusedAtItsLine) {
  const std::string triangle = "v 0 0 0\r\nv 1 0 0 \r \nv 0 1 0\r\r\nf 1 2 3\r\n";
  EXPECT_TRUE(outcome([&] { return raster::parse_obj(triangle); }).read);
  expect_agree(triangle, {}, {}, "CR LF");
  for (const char* obj :
       {"v 0 0 0\nv 0 03 \r-2 -1\nv 0 1 0\nf 1 2 3\n", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\n# a\rb\nf 1 2 3\n"}) {
    const Outcome o = outcome([&] { return raster::parse_obj(obj); });
    EXPECT_FALSE(o.read) << obj;
    EXPECT_NE(o.error.find("a carriage return (CR)"), std::string::npos) << o.error;
  }
  EXPECT_NE(outcome([&] { return raster::parse_obj("v 0 0 0\nv 0 03 \r-2 -1\n"); }).error.find("line 2"),
            std::string::npos);
}

// The limits on faces and points name the line that passed them, as the oracle does.
TEST(ObjReader, LimitsAreRefusedAtTheLineThatPassesThem) {
  raster::Limits limits;
  limits.max_model_faces = 5, limits.max_model_points = 3;
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 7; ++i) obj += "f 1 2 3\n";
  expect_agree(obj, {}, {}, "faces", limits);
  expect_agree("v 0 0 0\nv 1 0 0\np 1 2\np 1 2\n", {}, {}, "points", limits);
  expect_agree("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n", {}, {}, "a cloud", limits);
  // A syntax error before the line that passes the limit is the one reported.
  expect_agree("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n" + obj.substr(24), {}, {}, "error first", limits);
}

// The pieces: the same mesh, and the same first error, whatever size the pieces are (down to a line each,
// so a piece boundary falls between every two statements of the file) and however many threads read them.
TEST(ObjReader, TheMeshDoesNotDependOnPiecesOrThreads) {
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const Generated g = generate(seed, seed % 2 == 0, seed % 3 == 0);
    raster::Uploads files = g.files;
    if (!g.mtl.empty()) files["m.mtl"] = g.mtl;
    const Mesh whole = raster::parse_obj(g.obj, {}, {}, files);
    for (const int threads : {1, 2, 3, 7})
      for (const std::size_t piece :
           {std::size_t{1}, std::size_t{5}, std::size_t{64}, std::size_t{1} << 20}) {
        raster::Limits limits;
        limits.threads = threads;
        EXPECT_EQ(raster::obj::read_obj_text(g.obj, {}, limits, files, piece), whole)
            << "seed " << seed << ", " << threads << " threads, pieces of " << piece << " bytes";
      }
    // Two errors, the later one found by an earlier pass: the first in the file is reported.
    std::string spoiled = g.obj;
    spoiled.insert(spoiled.find("\nf ") + 1, "f 1 2 999999\n");
    spoiled.insert(spoiled.rfind("\nv ") + 1, "v 1 2 x\n");
    const Outcome one = outcome([&] { return raster::parse_obj(spoiled); });
    ASSERT_FALSE(one.read);
    for (const int threads : {1, 3})
      for (const std::size_t piece : {std::size_t{1}, std::size_t{64}}) {
        raster::Limits limits;
        limits.threads = threads;
        EXPECT_EQ(outcome([&] { return raster::obj::read_obj_text(spoiled, {}, limits, {}, piece); }).error,
                  one.error);
      }
    if (HasFailure()) return;
  }
}

// A budget whose deadline passes at its `at`-th question, counting every thread's.
class Deadline final : public raster::Budget {
 public:
  explicit Deadline(std::int64_t at) : at_(at) {}
  bool reserve(std::int64_t) noexcept override { return true; }
  bool expired() const noexcept override { return ++asked >= at_; }
  mutable std::atomic<std::int64_t> asked{0};

 private:
  std::int64_t at_;
};

// Read on several threads, the reader stops once the deadline passes: each thread at its next question (so
// at most one question more than the threads), in every pass.
TEST(ObjReader, StopsOnceTheDeadlinePassesOnEveryThread) {
  std::string obj;
  for (int i = 0; i < 200'000; ++i)
    obj += "v " + std::to_string(i % 97) + " 0.5 " + std::to_string(i % 89) + "\n";
  for (int i = 1; i + 2 <= 200'000; i += 2)
    obj += "f " + std::to_string(i) + " " + std::to_string(i + 1) + " 1\n";
  Deadline never(INT64_MAX);
  raster::Limits limits;
  limits.budget = &never, limits.threads = 2;
  raster::obj::read_obj_text(obj, {}, limits, {}, 64 << 10);
  const std::int64_t questions = never.asked.load();
  ASSERT_GT(questions, 8);
  for (const std::int64_t at : {std::int64_t{1}, questions / 3, questions / 2, questions}) {
    Deadline d(at);
    limits.budget = &d;
    EXPECT_THROW(raster::obj::read_obj_text(obj, {}, limits, {}, 64 << 10), raster::RenderCancelled) << at;
    EXPECT_LE(d.asked.load(), at + 1) << "questions after the deadline passed at question " << at;
  }
}

}  // namespace
