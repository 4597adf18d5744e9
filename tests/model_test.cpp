// The model formats (issue 32): one generated mesh written as OBJ, STL (ASCII, binary), PLY (ASCII, binary
// of both byte orders) and glTF (.gltf with an embedded or uploaded buffer, .glb) renders to the same
// pixels; each reader's counts are checked against its bytes before anything is sized; the formats are
// told by their bytes; and the real models of Debian's assimp-testmodels each render or get a SceneError.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "model_files.h"
#include "support.h"

namespace {

using raster::ErrorKind;
using raster::ModelFormat;
using raster::SceneError;

using test::Gltf;
using test::TestMesh;
using namespace test;  // the writers of model_files.h

// `read()` throws a SceneError of `kind` whose message holds `words`.
template <typename Read>
void expect_refused(Read read, ErrorKind kind, const std::string& words) {
  try {
    read();
    ADD_FAILURE() << "accepted; expected: " << words;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

raster::Image render_model(const std::string& bytes, const std::string& shading, raster::Uploads files = {},
                           const std::string& extra = "") {
  files["m"] = bytes;
  const raster::Scene scene = raster::parse_scene(
      R"({"width": 96, "height": 80, "camera": {"view": "iso"}, "primitives": [{"type": "model", "source": "m",
          "shading": ")" +
          shading + "\"" + extra + "}]}",
      {}, files);
  return test::render(scene);
}

struct Written {
  const char* name;
  std::string bytes;
  raster::Uploads files;
  ModelFormat format;
  bool shares_corners;  // STL repeats each corner per facet
};

std::vector<Written> every_format(const TestMesh& m) {
  const Gltf embedded = make_gltf(m, "data:application/octet-stream;base64,", false);
  Gltf with_data = make_gltf(m, "data:application/octet-stream;base64," + base64(embedded.buffer), false);
  const Gltf uploaded = make_gltf(m, "buffers/torus%20data.bin", true);
  return {
      {"OBJ", write_obj(m), {}, ModelFormat::obj, true},
      {"ASCII STL", write_stl_ascii(m), {}, ModelFormat::stl, false},
      {"binary STL", write_stl_binary(m), {}, ModelFormat::stl, false},
      // Some binary writers start the header with "solid": still binary by its size.
      {"binary STL, \"solid\" header",
       write_stl_binary(m, "solid torus, binary"),
       {},
       ModelFormat::stl,
       false},
      {"ASCII PLY", write_ply_ascii(m), {}, ModelFormat::ply, true},
      {"little-endian PLY", write_ply_binary(m, false), {}, ModelFormat::ply, true},
      {"big-endian PLY", write_ply_binary(m, true), {}, ModelFormat::ply, true},
      {"glTF, data: buffer", with_data.json, {}, ModelFormat::gltf, true},
      {"glTF, uploaded buffer",
       uploaded.json,
       {{"torus data.bin", uploaded.buffer}},
       ModelFormat::gltf,
       true},
      {"GLB", write_glb(make_gltf(m, "", true)), {}, ModelFormat::glb, true},
  };
}

TEST(Models, EveryFormatOfOneMeshRendersTheSamePixels) {
  const TestMesh m = make_mesh(7);
  const std::vector<Written> files = every_format(m);
  const raster::Image flat = render_model(files[0].bytes, "flat");
  const raster::Image smooth = render_model(files[0].bytes, "smooth");
  ASSERT_GT(test::count_not(flat, test::kBlack), 1000);  // the torus is in the picture
  ASSERT_NE(flat.pixels, smooth.pixels);
  for (const Written& w : files) {
    SCOPED_TRACE(w.name);
    EXPECT_EQ(raster::sniff_model(w.bytes), w.format);
    EXPECT_EQ(render_model(w.bytes, "flat", w.files).pixels, flat.pixels);
    // Smooth normals are computed per shared corner: the same wherever corners are shared.
    if (w.shares_corners) {
      EXPECT_EQ(render_model(w.bytes, "smooth", w.files).pixels, smooth.pixels);
    }
  }
}

// STL has no better normals than its facets': it is drawn flat unless the scene says otherwise.
TEST(Models, StlIsFlatShadedAndOthersSmooth) {
  const TestMesh m = make_mesh(3);
  EXPECT_EQ(raster::parse_stl(write_stl_binary(m)).shading, raster::Shading::flat);
  EXPECT_EQ(raster::parse_stl(write_stl_ascii(m)).shading, raster::Shading::flat);
  EXPECT_EQ(raster::parse_ply(write_ply_ascii(m)).shading, raster::Shading::smooth);
  const raster::Mesh stl = raster::parse_stl(write_stl_binary(m));
  EXPECT_EQ(stl.triangles.size(), triangles_of(m).size());
}

// STL lists every corner of every facet in full; the reader welds equal positions into one vertex, numbered
// in the order first seen, so the torus's facets share its m.v.size() vertices again, each facet keeping its
// corners' exact coordinates. What would break: corners left apart (six times the vertices to transform), or
// a weld that merged a position with another (the wrong triangle), in either variant.
TEST(Models, StlCornersAreWeldedIntoSharedVertices) {
  const TestMesh m = make_mesh(3);
  const auto tris = triangles_of(m);
  for (const std::string& bytes : {write_stl_binary(m), write_stl_ascii(m)}) {
    const raster::Mesh stl = raster::parse_stl(bytes);
    ASSERT_EQ(stl.triangles.size(), tris.size());
    EXPECT_EQ(stl.positions.size(), m.v.size());
    std::vector<std::uint32_t> first_seen;  // the file's vertices in the order its facets name them
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const raster::Vec3f& p = stl.positions[stl.triangles[t][k]];
        const auto& v = m.v[tris[t][k]];
        EXPECT_EQ(p, raster::Vec3f(raster::Vec3{v[0], v[1], v[2]})) << "facet " << t << " corner " << k;
        if (std::find(first_seen.begin(), first_seen.end(), tris[t][k]) == first_seen.end())
          first_seen.push_back(tris[t][k]);
      }
    for (std::size_t i = 0; i < first_seen.size(); ++i) {
      const auto& v = m.v[first_seen[i]];
      EXPECT_EQ(stl.positions[i], raster::Vec3f(raster::Vec3{v[0], v[1], v[2]})) << "vertex " << i;
    }
  }
}

// Welding is by value: 0 and -0 are one vertex; the next float up is another. A table that grows (a soup of
// facets with no corner in common, three vertices each) keeps every vertex it had.
TEST(Models, StlWeldsEqualNumbersOnly) {
  TestMesh m;
  const double up = std::nextafter(1.0f, 2.0f);
  m.v = {{0, 0, 0}, {-0.0, 0, -0.0}, {1, 0, 0}, {up, 0, 0}, {0, 1, 0}};
  m.faces = {{0, 2, 4}, {1, 3, 4}};
  raster::Mesh stl = raster::parse_stl(write_stl_binary(m));
  EXPECT_EQ(stl.positions.size(), 4u);  // (0,0,0) and (-0,0,-0) are one
  EXPECT_EQ(stl.triangles[0][0], stl.triangles[1][0]);
  EXPECT_NE(stl.triangles[0][1], stl.triangles[1][1]);
  EXPECT_EQ(stl.triangles[0][2], stl.triangles[1][2]);
  TestMesh soup;
  for (std::uint32_t t = 0; t < 5000; ++t) {
    for (int k = 0; k < 3; ++k) soup.v.push_back({grid(t * 0.01), grid(k * 0.5), grid(t * 0.003 + k)});
    soup.faces.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  stl = raster::parse_stl(write_stl_binary(soup));
  ASSERT_EQ(stl.positions.size(), soup.v.size());
  for (std::size_t i = 0; i < soup.v.size(); ++i)
    ASSERT_EQ(stl.positions[i], raster::Vec3f(raster::Vec3{soup.v[i][0], soup.v[i][1], soup.v[i][2]})) << i;
}

// A large STL is welded on several threads (its facets in ranges, merged in order): the same vertices in the
// same order, the same triangles, and the same first wrong corner, at any thread count. What would break: a
// vertex of two ranges made twice, numbered out of the file's order, or a wrong corner of a later range
// reported before an earlier one.
TEST(Models, StlWeldsAlikeOnAnyThreadCount) {
  const TestMesh m = make_mesh(9, 230, 160);  // 36,800 vertices, ~66,000 facets: over the threshold
  std::string big = write_stl_binary(m);
  // And every facet again, reversed: a second half naming the first half's vertices.
  std::uint32_t facets = 0;
  std::memcpy(&facets, big.data() + 80, 4);
  std::string twice = big.substr(0, 80);
  test::put<std::uint32_t>(twice, 2 * facets);
  twice += big.substr(84);
  for (std::uint32_t t = facets; t-- > 0;) twice += big.substr(84 + 50 * std::size_t{t}, 50);
  const auto read = [&](const std::string& bytes, int threads) {
    raster::Limits limits;
    limits.threads = threads;
    return raster::parse_stl(bytes, limits);
  };
  const raster::Mesh one = read(twice, 1);
  EXPECT_EQ(one.positions.size(), m.v.size());
  for (const int threads : {2, 3, 7}) EXPECT_EQ(read(twice, threads), one) << threads << " threads";
  std::string wrong = twice;
  const float nan = std::nanf("");
  std::memcpy(&wrong[84 + 50 * std::size_t{facets + 100} + 12 + 12 + 4], &nan,
              4);                                                            // facet facets+101, corner 2
  std::memcpy(&wrong[84 + 50 * std::size_t{2 * facets - 5} + 12], &nan, 4);  // a later one
  std::string first;
  for (const int threads : {1, 2, 3}) try {
      read(wrong, threads);
      ADD_FAILURE() << "a corner that is not a number was read";
    } catch (const SceneError& e) {
      if (first.empty()) first = std::string(e.what()) + " @" + std::to_string(e.where().byte);
      EXPECT_EQ(std::string(e.what()) + " @" + std::to_string(e.where().byte), first)
          << threads << " threads";
    }
  EXPECT_NE(first.find("triangle " + std::to_string(facets + 101)), std::string::npos) << first;
}

// Welding changes no pixel: the welded mesh draws what the same facets with three corners each draw.
TEST(Models, WeldedStlDrawsAsItsFacetsDo) {
  const TestMesh m = make_mesh(5, 40, 24);
  raster::Mesh welded = raster::parse_stl(write_stl_binary(m));
  raster::Mesh apart = welded;
  apart.positions.clear();
  for (auto& t : apart.triangles)
    for (std::uint32_t& i : t) {
      apart.positions.push_back(welded.positions[i]);
      i = static_cast<std::uint32_t>(apart.positions.size() - 1);
    }
  ASSERT_LT(welded.positions.size(), apart.positions.size() / 5);
  auto draw = [](raster::Mesh mesh, raster::Antialias aa) {
    mesh.colors = {{204, 204, 204, 255}};
    raster::Scene scene = raster::model_scene(std::move(mesh), ModelFormat::stl);
    scene.antialias = aa;
    return raster::render(scene).pixels;
  };
  for (const raster::Antialias aa : {raster::Antialias::none, raster::Antialias::msaa4})
    EXPECT_EQ(draw(welded, aa), draw(apart, aa));
}

// A quad's diagonal is OBJ's: a bent quad split the other way would show other pixels.
TEST(Models, PlyQuadsAreSplitAsObjQuadsAre) {
  TestMesh bent;
  bent.v = {{0, 0, 0}, {1, 0, 0.5}, {0.75, 0.75, 0}, {0, 1, 0.5}};  // 0-2 is the shorter diagonal
  bent.faces = {{0, 1, 2, 3}};
  const raster::Mesh ply = raster::parse_ply(write_ply_ascii(bent));
  const raster::Mesh obj = raster::parse_obj(write_obj(bent));
  EXPECT_EQ(ply.triangles, obj.triangles);
  bent.v[1][2] = bent.v[3][2] = 0, bent.v[2][0] = 1.5;  // now 1-3 is the shorter diagonal
  EXPECT_EQ(raster::parse_ply(write_ply_ascii(bent)).triangles, raster::parse_obj(write_obj(bent)).triangles);
  EXPECT_NE(raster::parse_ply(write_ply_ascii(bent)).triangles, ply.triangles);
}

// The common binary face list (one "list uchar int" property, this machine's byte order) is read by a path
// of its own, the rest value by value: both give the same triangles, quads and larger polygons split alike,
// and refuse a bad index or a list past the data in the same words at the same byte. What would break: the
// direct path reading a face other than the one the header lays out, or skipping a check.
TEST(Models, PlyFacesReadAlikeInEveryByteOrder) {
  TestMesh m = make_mesh(7);
  m.faces.push_back({0, 3, 9, 17, 11});  // a pentagon among the quads and triangles
  const raster::Mesh ascii = raster::parse_ply(write_ply_ascii(m));
  EXPECT_EQ(raster::parse_ply(write_ply_binary(m, false)).triangles, ascii.triangles);
  EXPECT_EQ(raster::parse_ply(write_ply_binary(m, true)).triangles, ascii.triangles);
  auto one_face = [](bool big, std::uint8_t corners, std::int32_t index) {
    std::string s = std::string("ply\nformat binary_") + (big ? "big" : "little") +
                    "_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
    for (int v = 0; v < 9; ++v) put<float>(s, static_cast<float>(v % 4 == 0), big);
    put<std::uint8_t>(s, 3);
    for (std::int32_t v : {0, 1, 2}) put<std::int32_t>(s, v, big);
    put<std::uint8_t>(s, corners);
    for (std::int32_t v : {2, index, 0}) put<std::int32_t>(s, v, big);
    return s;
  };
  for (const std::int32_t bad : {3, -1, 7}) {
    std::string words[2];
    std::size_t byte[2] = {};
    for (int big = 0; big < 2; ++big) try {
        raster::parse_ply(one_face(big, 3, bad));
        ADD_FAILURE() << "index " << bad << " was read";
      } catch (const SceneError& e) {
        // The headers differ in length ("big", "little"): the byte is counted from the data's start.
        const std::string file = one_face(big, 3, bad);
        words[big] = e.what(), byte[big] = e.where().byte - (file.find("end_header\n") + 11);
      }
    EXPECT_EQ(words[0], words[1]);
    EXPECT_NE(words[0].find("face 1 refers to vertex " + std::to_string(bad)), std::string::npos) << words[0];
    EXPECT_EQ(byte[0], byte[1]);
    EXPECT_GT(byte[0], 0u);
  }
  std::string past[2];
  for (int big = 0; big < 2; ++big) try {
      raster::parse_ply(one_face(big, 4, 1));  // four corners, three written
      ADD_FAILURE() << "a list past the data was read";
    } catch (const SceneError& e) {
      past[big] = e.what();
    }
  EXPECT_EQ(past[0], past[1]);
  EXPECT_NE(past[0].find("longer than the data left"), std::string::npos) << past[0];
}

// Normals, uchar colours and properties rasterd does not use, beside an element of its own before the
// vertices: ASCII and binary of both byte orders read alike, each value from its own property.
TEST(Models, PlyVertexPropertiesAreReadInEveryEncoding) {
  auto header = [](const std::string& format) {
    return "ply\nformat " + format +
           " 1.0\nelement camera 2\nproperty float view\nproperty uchar red\nelement vertex 3\n"
           "property short quality\nproperty float x\nproperty float y\nproperty float z\n"
           "property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\n"
           "property uchar green\nproperty uchar blue\nproperty double confidence\n"
           "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
  };
  const float position[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0.5f}};
  std::string ascii = header("ascii") + "1 9\n2 9\n";
  for (int i = 0; i < 3; ++i)
    ascii += "-7 " + std::to_string(position[i][0]) + " " + std::to_string(position[i][1]) + " " +
             std::to_string(position[i][2]) + " 0 0 1 " + std::to_string(10 * i) + " 128 255 0.5\n";
  ascii += "3 0 1 2\n";
  auto binary = [&](bool big) {
    std::string s = header(big ? "binary_big_endian" : "binary_little_endian");
    for (int k = 0; k < 2; ++k) put<float>(s, 1.f + k, big), put<std::uint8_t>(s, 9);
    for (int i = 0; i < 3; ++i) {
      put<std::int16_t>(s, -7, big);
      for (float v : position[i]) put<float>(s, v, big);
      for (float v : {0.f, 0.f, 1.f}) put<float>(s, v, big);
      for (int c : {10 * i, 128, 255}) put<std::uint8_t>(s, static_cast<std::uint8_t>(c));
      put<double>(s, 0.5, big);
    }
    put<std::uint8_t>(s, 3);
    for (std::uint32_t v : {0u, 1u, 2u}) put<std::uint32_t>(s, v, big);
    return s;
  };
  const raster::Mesh mesh = raster::parse_ply(ascii);
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.positions[2], (raster::Vec3{0, 3, 0.5}));
  EXPECT_EQ(mesh.normals, std::vector<raster::Vec3f>(3, raster::Vec3f{0, 0, 1}));
  EXPECT_EQ(mesh.colors,
            (std::vector<raster::Rgba8>{{0, 128, 255, 255}, {10, 128, 255, 255}, {20, 128, 255, 255}}));
  EXPECT_EQ(mesh.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}}));
  EXPECT_EQ(raster::parse_ply(binary(false)), mesh);
  EXPECT_EQ(raster::parse_ply(binary(true)), mesh);
  // One byte short of the vertices (3 x 37 bytes after the cameras' 2 x 5): the element is refused.
  const std::string cut = binary(false).substr(0, header("binary_little_endian").size() + 10 + 3 * 37 - 1);
  expect_refused([&] { raster::parse_ply(cut); }, ErrorKind::model, "element \"vertex\" ends after the data");
}

// A polygon of more than four corners, concave: a fan from its first corner would cover the notch of the U.
TEST(Models, PlyPolygonsAreSplitAsObjPolygonsAre) {
  TestMesh u;
  u.v = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {3, 4, 0}, {3, 1, 0}, {1, 1, 0}, {1, 4, 0}, {0, 4, 0}};
  u.faces = {{0, 1, 2, 3, 4, 5, 6, 7}};
  const raster::Mesh obj = raster::parse_obj(write_obj(u));
  ASSERT_EQ(obj.triangles.size(), 6u);
  EXPECT_EQ(raster::parse_ply(write_ply_ascii(u)).triangles, obj.triangles);
  EXPECT_EQ(raster::parse_ply(write_ply_binary(u, true)).triangles, obj.triangles);
  // The same file with the face element first (legal PLY): split once the vertices are read.
  std::string faces_first = write_ply_ascii(u);
  const std::size_t vertex_header = faces_first.find("element vertex"),
                    face_header = faces_first.find("element face");
  const std::size_t end_header = faces_first.find("end_header\n") + 11;
  const std::size_t face_data = faces_first.find("\n8 ", end_header) + 1;
  faces_first = faces_first.substr(0, vertex_header) +
                faces_first.substr(face_header, end_header - 11 - face_header) +
                faces_first.substr(vertex_header, face_header - vertex_header) + "end_header\n" +
                faces_first.substr(face_data) + faces_first.substr(end_header, face_data - end_header);
  EXPECT_EQ(raster::parse_ply(faces_first).triangles, obj.triangles) << faces_first;
  // No triangle covers the notch's middle (2, 2.5).
  for (const auto& t : obj.triangles) {
    auto side = [&](int a, int b) {
      const auto &p = u.v[t[a]], &q = u.v[t[b]];
      return (q[0] - p[0]) * (2.5 - p[1]) - (q[1] - p[1]) * (2 - p[0]);
    };
    const double a = side(0, 1), b = side(1, 2), c = side(2, 0);
    EXPECT_FALSE((a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0));
  }
}

TEST(Models, FormatsAreToldByTheirBytesThenByName) {
  EXPECT_EQ(raster::sniff_model("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), ModelFormat::obj);
  EXPECT_EQ(raster::sniff_model("# only a comment\n\n# and another\no box\nv 0 0 0\n"), ModelFormat::obj);
  // The longest statements are still statements; a first word that merely starts like one is not.
  EXPECT_EQ(raster::sniff_model("shadow_obj shadow.obj\nv 0 0 0\n"), ModelFormat::obj);
  EXPECT_EQ(raster::sniff_model("trace_obj\n"), ModelFormat::obj);
  EXPECT_EQ(raster::sniff_model("shadow_objects 1\n"), std::nullopt);
  EXPECT_EQ(raster::sniff_model("vvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvv 0 0 0\n"), std::nullopt);
  EXPECT_EQ(raster::sniff_model("solid x\nendsolid x\n"), ModelFormat::stl);
  EXPECT_EQ(raster::sniff_model("ply\r\nformat ascii 1.0\r\n"), ModelFormat::ply);
  EXPECT_EQ(raster::sniff_model(R"( {"asset": {"version": "2.0"}})"), ModelFormat::gltf);
  EXPECT_EQ(raster::sniff_model(R"({"accessors": [], "asset": {"version": "2.0"}})"), ModelFormat::gltf);
  // A scene document is not a model: its first key is no glTF property.
  EXPECT_EQ(raster::sniff_model(R"({"width": 10, "asset": 1})"), std::nullopt);
  EXPECT_EQ(raster::sniff_model("hello world"), std::nullopt);
  EXPECT_EQ(raster::sniff_model(std::string(84, '\0')), ModelFormat::stl);  // a binary STL of 0 facets
  EXPECT_EQ(raster::sniff_model(std::string(85, '\0')), std::nullopt);
  EXPECT_EQ(raster::format_of_file_name("Models/Part.STL"), ModelFormat::stl);
  EXPECT_EQ(raster::format_of_file_name("scan.ply"), ModelFormat::ply);
  EXPECT_EQ(raster::format_of_file_name("a.glb"), ModelFormat::glb);
  EXPECT_EQ(raster::format_of_file_name("a.json"), std::nullopt);
  EXPECT_EQ(raster::format_named("GLTF"), ModelFormat::gltf);

  // Bytes that are no format: the hint decides, and without one the error names the formats.
  try {
    raster::parse_model("\x01\x02 not a model", std::nullopt);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::model);
    EXPECT_NE(std::string(e.what()).find("STL"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("glTF"), std::string::npos) << e.what();
  }
  expect_refused([] { raster::parse_model("\x01\x02 not a model", ModelFormat::ply); }, ErrorKind::model,
                 "PLY");
}

// The table is the one place a format is described: every name, extension and media type in a row leads
// back to that row, and the scene's "format" lists the names in the table's order.
TEST(Models, EveryFormatIsOneRowOfTheTable) {
  ASSERT_EQ(raster::model_formats().size(), raster::kModelFormatCount);
  for (std::size_t i = 0; i < raster::model_formats().size(); ++i) {
    const raster::ModelFormatInfo& row = raster::model_formats()[i];
    EXPECT_EQ(&raster::model_format(row.format), &row);
    EXPECT_EQ(raster::format_names()[i], row.name);
    EXPECT_EQ(raster::format_named(row.name), row.format);
    EXPECT_EQ(raster::format_name(row.format), row.name);
    EXPECT_NE(row.read, nullptr) << row.name;
    EXPECT_EQ(row.files != nullptr, row.file_rounds > 0) << row.name;
    for (const std::string_view e : row.extensions)
      EXPECT_EQ(raster::format_of_file_name("dir/part." + std::string(e)), row.format) << e;
    for (const std::string_view t : row.media_types) {
      EXPECT_EQ(raster::format_of_media_type(t), row.format) << t;
      EXPECT_EQ(raster::format_of_media_type(std::string(t) + " ; charset=utf-8"), row.format) << t;
    }
  }
  EXPECT_EQ(raster::format_of_media_type("Model/GLTF-Binary"), ModelFormat::glb);
  EXPECT_EQ(raster::format_of_media_type("application/json"), std::nullopt);
  EXPECT_EQ(raster::format_of_media_type(""), std::nullopt);
}

// The readers' clock, injected: a budget that never refuses memory (it adds up what was asked) and says the
// deadline passed from its `expire_at`-th question on (1-based; 0: never), counting the questions.
class ReadClock : public raster::Budget {
 public:
  explicit ReadClock(std::int64_t expire_at = 0) : expire_at_(expire_at) {}
  bool reserve(std::int64_t bytes) noexcept override {
    reserved += bytes;
    return true;
  }
  bool expired() const noexcept override { return ++asked >= expire_at_ && expire_at_ > 0; }
  mutable std::int64_t asked = 0;  ///< questions so far
  std::int64_t reserved = 0;       ///< bytes asked for so far

 private:
  std::int64_t expire_at_;
};

// Every reader asks the deadline as its work goes (at least once per 2^16 vertices and triangles read, in
// whatever shape: lines, binary entries, list items, JSON values, accessors), and stops with RenderCancelled
// at the first question after it passed: already passed, passing half way, passing at the last question.
TEST(Models, EveryReaderStopsOnceTheDeadlinePasses) {
  const TestMesh m = make_mesh(11, 300, 200);  // 60,000 vertices; 60,000 faces, ~108,000 triangles
  const Gltf g = make_gltf(m, "m.bin", true);
  const Written models[] = {
      {"OBJ", write_obj(m), {}, ModelFormat::obj, true},
      {"ASCII STL", write_stl_ascii(m), {}, ModelFormat::stl, false},
      {"binary STL", write_stl_binary(m), {}, ModelFormat::stl, false},
      {"ASCII PLY", write_ply_ascii(m), {}, ModelFormat::ply, true},
      {"binary PLY", write_ply_binary(m, false), {}, ModelFormat::ply, true},
      {"glTF", g.json, {{"m.bin", g.buffer}}, ModelFormat::gltf, true},
      {"GLB", write_glb(make_gltf(m, "", true)), {}, ModelFormat::glb, true},
  };
  const std::int64_t work = static_cast<std::int64_t>(m.v.size() + triangles_of(m).size());
  for (const Written& w : models) {
    SCOPED_TRACE(w.name);
    auto read = [&](raster::Budget& clock) {
      raster::Limits limits;
      limits.budget = &clock;
      limits.threads = 1;  // one thread asks in turn (ObjReader.StopsOnceTheDeadlinePassesOnEveryThread)
      return raster::parse_model(w.bytes, w.format, limits, w.files);
    };
    ReadClock never;
    EXPECT_FALSE(read(never).triangles.empty());
    EXPECT_GE(never.asked, work / std::int64_t{1 << 16}) << "asked " << never.asked << " times";
    for (const std::int64_t at : {std::int64_t{1}, std::max<std::int64_t>(1, never.asked / 2), never.asked}) {
      ReadClock expires(at);
      EXPECT_THROW(read(expires), raster::RenderCancelled) << "deadline passing at question " << at;
      EXPECT_EQ(expires.asked, at) << "stopped at the first question after it passed";
    }
  }
}

// glTF instancing: what a model may build is bounded by the bytes sent (raster::kModelBuiltPerByte, with a
// floor for small files). 1,000 nodes drawing one mesh of 3,000 vertices (3 million vertices from ~60 kB)
// are refused, from the document's counts, before any vertex is asked for or built; ten nodes read.
TEST(Models, GltfInstancingIsBoundedByTheBytesSent) {
  std::string buffer;
  for (int i = 0; i < 3000; ++i)
    for (float v : {static_cast<float>(i % 7), static_cast<float>(i % 5), static_cast<float>(i % 3)})
      test::put<float>(buffer, v);
  auto doc = [&](int nodes) {
    std::string list, scene;
    for (int i = 0; i < nodes; ++i) {
      list += std::string(i ? ", " : "") + R"({"mesh": 0})";
      scene += (i ? ", " : "") + std::to_string(i);
    }
    return R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [)" + scene + R"(]}], "nodes": [)" + list +
           R"(], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3000, "type": "VEC3"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36000}],
      "buffers": [{"byteLength": 36000, "uri": "b.bin"}]})";
  };
  const raster::Uploads files{{"b.bin", buffer}};
  const std::string many = doc(1000);
  const std::uint64_t sent = many.size() + buffer.size();
  ASSERT_LT(sent * raster::kModelBuiltPerByte, 3'000'000u);
  ASSERT_LT(raster::kModelBuiltFloor, 3'000'000u);
  ReadClock clock;
  raster::Limits limits;
  limits.budget = &clock;
  expect_refused([&] { raster::parse_gltf(many, limits, files); }, ErrorKind::limit,
                 "the model would build 3000000 vertices from " + std::to_string(sent) + " bytes; at most " +
                     std::to_string(raster::kModelBuiltPerByte) + " per byte");
  // Only the document was asked for (the bytes sent, which its copies cannot pass, and its objects), no
  // vertex or triangle (3M vertices would be 36 MB).
  EXPECT_LT(clock.reserved, static_cast<std::int64_t>(sent) + (std::int64_t{1} << 20));
  const raster::Mesh ten = raster::parse_gltf(doc(10), {}, files);
  EXPECT_EQ(ten.positions.size(), 30'000u);
  EXPECT_EQ(ten.triangles.size(), 10'000u);
}

// Each declared count is checked against the bytes before it sizes anything: these would ask for
// terabytes (the test runs under ASan too, whose allocator fails loudly on such sizes).
TEST(Models, DeclaredCountsAreCheckedAgainstTheBytesFirst) {
  auto model_error = [](auto&& read, const std::string& words) {
    expect_refused(read, ErrorKind::model, words);
  };
  // Binary STL: the count must match the size.
  std::string stl = write_stl_binary(make_mesh(1));
  stl[83] = 0x40;  // 2^30 more triangles than the bytes hold; also not a size sniff_model accepts
  model_error([&] { raster::parse_stl(stl); }, "binary STL of");
  // PLY: 2^40 vertices in a few hundred bytes; a face list of 2^32 - 1 entries.
  std::string ply = write_ply_ascii(make_mesh(1));
  ply.replace(ply.find("vertex 112"), 10, "vertex 1099511627776");
  model_error([&] { raster::parse_ply(ply); }, "cannot hold them");
  std::string list =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
  for (int i = 0; i < 9; ++i) put<float>(list, static_cast<float>(i % 2));
  put<std::uint32_t>(list, 0xffffffffu);
  put<std::int32_t>(list, 0);
  model_error([&] { raster::parse_ply(list); }, "longer than the data left");
  // glTF: an accessor of 2^31 elements in a buffer of 12 bytes.
  const TestMesh m = make_mesh(1);
  Gltf g = make_gltf(m, "", false);
  g.json.replace(g.json.find("\"count\": 112"), 12, "\"count\": 2147483647");
  model_error([&] { raster::parse_gltf(write_glb(g)); }, "do not fit in its buffer view");
  // An index beyond the vertices, and a buffer view beyond its buffer.
  Gltf bad_view = make_gltf(m, "", false);
  bad_view.json.replace(bad_view.json.find("\"byteOffset\": 0"), 15, "\"byteOffset\": 4000000");
  model_error([&] { raster::parse_gltf(write_glb(bad_view)); }, "lies outside its buffer");
}

// ply_fuzzer: an element of 6e9 entries and no properties holds no bytes; it is passed over, not counted.
TEST(Models, PlyElementsWithoutPropertiesAreSkipped) {
  std::string ply = write_ply_ascii(make_mesh(1));
  ply.replace(ply.find("element face"), 0, "element nothing 6000000000\n");
  EXPECT_EQ(raster::parse_ply(ply).triangles.size(),
            raster::parse_ply(write_ply_ascii(make_mesh(1))).triangles.size());
}

TEST(Models, TheFaceLimitHoldsForEveryFormat) {
  raster::Limits limits;
  limits.max_model_faces = 10;
  const TestMesh m = make_mesh(2);
  for (const Written& w : every_format(m)) {
    SCOPED_TRACE(w.name);
    try {
      raster::parse_model(w.bytes, std::nullopt, limits, w.files);
      ADD_FAILURE() << "accepted";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::limit) << e.what();
    }
  }
}

// A glTF's URIs name uploaded parts only: nothing is read from disk, whatever the path says.
TEST(Models, GltfReadsNoFileButUploads) {
  const TestMesh m = make_mesh(1);
  for (const std::string uri : {"/etc/hostname", "../../../../etc/hostname", "file:///etc/hostname"}) {
    SCOPED_TRACE(uri);
    const Gltf g = make_gltf(m, uri, false);
    expect_refused([&] { raster::parse_gltf(g.json); }, ErrorKind::model, "hostname");
  }
  EXPECT_EQ(raster::gltf_files(make_gltf(m, "dir/a%20b.bin", false).json),
            std::vector<std::string>{"a b.bin"});
}

// Node transforms, COLOR_0 and baseColorFactor (linear, drawn sRGB-encoded), KHR_materials_unlit.
TEST(Models, GltfNodesAndMaterialsAreRead) {
  const TestMesh m = make_mesh(1);
  Gltf g = make_gltf(m, "", false,
                     R"(, "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.3185, 1, 0, 1]},
                                        "extensions": {"KHR_materials_unlit": {}}}])");
  g.json.replace(
      g.json.find(R"("nodes": [{"mesh": 0}])"), 22,
      R"("nodes": [{"children": [1], "translation": [10, 0, 0]}, {"mesh": 0, "scale": [2, 2, 2]}])");
  g.json.replace(g.json.find(R"("indices": 1})"), 13, R"("indices": 1, "material": 0})");
  const raster::Mesh mesh = raster::parse_gltf(write_glb(g));
  ASSERT_EQ(mesh.positions.size(), m.v.size());
  for (std::size_t i = 0; i < m.v.size(); ++i) {
    EXPECT_FLOAT_EQ(mesh.positions[i].x, 10 + 2 * m.v[i][0]);
    EXPECT_FLOAT_EQ(mesh.positions[i].y, 2 * m.v[i][1]);
  }
  EXPECT_EQ(mesh.shading, raster::Shading::unlit);
  // One material, one colour for the mesh; linear 0.3185 is sRGB 0.6.
  EXPECT_EQ(mesh.colors, std::vector<raster::Rgba8>{(raster::Rgba8{153, 255, 0, 255})});
}

// Review findings (issue 32): normals turn with their node as positions do, also under a mirror; an opaque
// material is opaque whatever COLOR_0's alpha; '+' in a buffer URI finds its upload.
TEST(Models, GltfNormalsFollowRotationsAndMirrors) {
  std::string buffer;
  for (float v : {0.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f}) test::put<float>(buffer, v);  // positions
  for (int i = 0; i < 3; ++i)
    for (float v : {1.f, 0.f, 0.f}) test::put<float>(buffer, v);  // normals: +x
  for (int i = 0; i < 3; ++i)
    for (float v : {1.f, 1.f, 1.f, 0.25f}) test::put<float>(buffer, v);  // COLOR_0 with alpha 0.25
  auto doc = [&](const std::string& node, const std::string& material) {
    return R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, )" + node +
           R"(}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "COLOR_0": 2}, "material": 0}]}],
      "materials": [{)" +
           material + R"(}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC4"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                      {"buffer": 0, "byteOffset": 72, "byteLength": 48}],
      "buffers": [{"byteLength": 120, "uri": "a+b.bin"}]})";
  };
  const raster::Uploads files{{"a+b.bin", buffer}};
  // A quarter turn about z takes +x to +y.
  const raster::Mesh turned =
      raster::parse_gltf(doc(R"("rotation": [0, 0, 0.70710678, 0.70710678])", ""), {}, files);
  ASSERT_EQ(turned.normals.size(), 3u);
  EXPECT_NEAR(turned.normals[0].x, 0, 1e-6);
  EXPECT_NEAR(turned.normals[0].y, 1, 1e-6);
  EXPECT_EQ(turned.colors, std::vector<raster::Rgba8>{(raster::Rgba8{255, 255, 255, 255})});  // opaque
  // A non-uniform scale: the normal goes through the inverse transpose (x scaled by 2: the normal stays +x).
  const raster::Mesh stretched = raster::parse_gltf(doc(R"("scale": [2, 1, 1])", ""), {}, files);
  EXPECT_GT(stretched.normals[0].x, 0);
  // A mirror in x: the normal is mirrored, the winding turned.
  const raster::Mesh mirrored = raster::parse_gltf(doc(R"("scale": [-1, 1, 1])", ""), {}, files);
  EXPECT_LT(mirrored.normals[0].x, 0);
  EXPECT_EQ(mirrored.triangles[0], (std::array<std::uint32_t, 3>{0, 2, 1}));
  // Blended, the vertex alpha is kept.
  const raster::Mesh blended =
      raster::parse_gltf(doc(R"("translation": [0, 0, 0])", R"("alphaMode": "BLEND")"), {}, files);
  EXPECT_EQ(blended.colors[0].a, 64);
}

// Primitives of one mesh share its arrays: the second one's indices are offset by the first one's vertices;
// the mesh keeps one colour while every primitive has the same, and one per vertex, in order, once they
// differ; an index past the primitive's vertices is reported with its element.
TEST(Models, GltfPrimitivesShareTheMeshAndIndicesAreChecked) {
  std::string buffer;
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) test::put<float>(buffer, v);
  for (std::uint16_t i : {0, 1, 2, 0}) test::put<std::uint16_t>(buffer, i);    // 0, 1, 2 and padding
  for (std::uint8_t i : {0, 1, 3, 0}) buffer.push_back(static_cast<char>(i));  // 3: past the vertices
  auto doc = [&](int second_material, int second_indices) {
    return R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [
        {"attributes": {"POSITION": 0}, "indices": 1, "material": 0},
        {"attributes": {"POSITION": 0}, "indices": )" +
           std::to_string(second_indices) + R"(, "material": )" + std::to_string(second_material) + R"(}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}},
                    {"pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 1]}}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                    {"bufferView": 2, "componentType": 5121, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8},
                      {"buffer": 0, "byteOffset": 44, "byteLength": 4}],
      "buffers": [{"byteLength": 48, "uri": "b.bin"}]})";
  };
  const raster::Uploads files{{"b.bin", buffer}};
  const raster::Rgba8 red{255, 0, 0, 255}, green{0, 255, 0, 255};
  const raster::Mesh two = raster::parse_gltf(doc(1, 1), {}, files);
  ASSERT_EQ(two.positions.size(), 6u);
  EXPECT_EQ(two.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(two.colors, (std::vector<raster::Rgba8>{red, red, red, green, green, green}));
  const raster::Mesh one = raster::parse_gltf(doc(0, 1), {}, files);
  EXPECT_EQ(one.triangles.size(), 2u);
  EXPECT_EQ(one.colors, std::vector<raster::Rgba8>{red});
  expect_refused([&] { raster::parse_gltf(doc(0, 2), {}, files); }, ErrorKind::model,
                 "mesh 0 primitive 1 indices (accessor 2) element 2 is 3, but the primitive has 3 vertices");
}

// Documents that would drive tinygltf 2.7.0 into a crash, a read past the input, an exception or a huge
// allocation are refused before it runs.
TEST(Models, GltfDocumentsThatWouldHurtTinygltfAreRefusedFirst) {
  auto refused = [](const std::string& bytes, ErrorKind kind, const std::string& words) {
    expect_refused([&] { raster::parse_gltf(bytes); }, kind, words);
  };
  const std::string head = R"({"asset": {"version": "2.0"}, )";
  // tinygltf reads "extras" recursively: 50,000 nested arrays overflowed the stack.
  refused(head + R"("extras": )" + std::string(50000, '[') + "1" + std::string(50000, ']') + "}",
          ErrorKind::model, "not JSON");
  // A million empty materials: three bytes of text, a tinygltf::Material each.
  std::string materials = head + R"("materials": [{})";
  for (int i = 0; i < 1000000; ++i) materials += ",{}";
  refused(materials + "]}", ErrorKind::limit, "MB of nodes, meshes, materials");
  // Buffers larger than everything sent.
  refused(head + R"("buffers": [{"byteLength": 4000000000, "uri": "data:,"}]})", ErrorKind::model,
          "bytes sent");
  // GLB: a binary chunk whose length runs 8 bytes past the file (tinygltf's bounds check misses its head),
  // two buffers backed by one chunk, and a buffer of 0 bytes (tinygltf's at(0) threw).
  const test::TestMesh m = test::make_mesh(1);
  std::string glb = test::write_glb(test::make_gltf(m, "", false));
  const std::size_t json = static_cast<unsigned char>(glb[12]) | static_cast<unsigned char>(glb[13]) << 8;
  glb[20 + json] = static_cast<char>(glb[20 + json] + 8);
  refused(glb, ErrorKind::model, "runs past");
  // A JSON chunk not padded to 4 bytes (tinygltf reads the binary chunk's head from the wrong place).
  std::string unpadded = test::write_glb(test::make_gltf(m, "", false));
  unpadded[12] = static_cast<char>(unpadded[12] - 1);
  refused(unpadded, ErrorKind::model, "not padded to a multiple of 4");
  test::Gltf two = test::make_gltf(m, "", false);
  two.json.replace(two.json.find(R"("buffers": [)"), 12, R"("buffers": [{"byteLength": 4}, )");
  refused(test::write_glb(two), ErrorKind::model, "more than one buffer has no URI");
  test::Gltf empty = test::make_gltf(m, "", false);
  empty.buffer.clear();
  empty.json.replace(empty.json.find(R"("buffers": [{"byteLength": )"), 27,
                     R"("buffers": [{"byteLength": 0, "x": )");
  refused(test::write_glb(empty), ErrorKind::model, "glTF");
}

// Review findings (issue 32, second review). Values under "extras" become tinygltf Values (~170 bytes for
// two bytes of text): counted before tinygltf runs. Nodes times primitives are bounded. A primitive without
// normals is drawn flat, as glTF says, beside one with normals. OPAQUE and MASK decide the texture's alpha.
// A position beyond +-2^128 names its element.
TEST(Models, GltfReviewFindingsAreRefusedOrDrawnAsGltfSays) {
  auto refused = [](const std::string& bytes, ErrorKind kind, const std::string& words,
                    const raster::Uploads& files = {}) {
    expect_refused([&] { raster::parse_gltf(bytes, {}, files); }, kind, words);
  };
  const std::string head = R"({"asset": {"version": "2.0"}, )";
  std::string zeros = "0";
  for (int i = 0; i < 2000000; ++i) zeros += ",0";
  refused(head + R"("extras": [)" + zeros + "]}", ErrorKind::limit, "MB of nodes, meshes, materials");
  // 1,100 nodes naming one mesh of 1,000 primitives: 1.1 million to read.
  std::string many = head + R"("meshes": [{"primitives": [{"attributes": {}, "mode": 0})";
  for (int i = 1; i < 1000; ++i) many += R"(, {"attributes": {}, "mode": 0})";
  many += R"(]}], "nodes": [{"mesh": 0})";
  for (int i = 1; i < 1100; ++i) many += R"(, {"mesh": 0})";
  refused(many + "]}", ErrorKind::limit, "more than 1048576 mesh primitives");

  // Two triangles side by side in z = 0, the first with a NORMAL, the second without: the first keeps its
  // normals, the second gets its face's; a mesh without any is flat.
  std::string buffer;
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) test::put<float>(buffer, v);
  for (int i = 0; i < 3; ++i)
    for (float v : {0.f, 0.6f, 0.8f}) test::put<float>(buffer, v);
  for (float v : {0.f, 0.f, 1.f, 0.f, 0.f, 1.f}) test::put<float>(buffer, v);  // uvs
  const raster::Uploads files{{"b.bin", buffer}};
  auto doc = [&](const std::string& primitives, const std::string& node, const std::string& material) {
    return head + R"("nodes": [{"mesh": 0)" + node + R"(}], "meshes": [{"primitives": [)" + primitives +
           R"(]}],
      "materials": [{)" +
           material + R"(}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                      {"buffer": 0, "byteOffset": 72, "byteLength": 24}],
      "buffers": [{"byteLength": 96, "uri": "b.bin"}]})";
  };
  const std::string with = R"({"attributes": {"POSITION": 0, "NORMAL": 1}})";
  const std::string without = R"({"attributes": {"POSITION": 0}})";
  const raster::Mesh none = raster::parse_gltf(doc(without, "", ""), {}, files);
  EXPECT_EQ(none.shading, raster::Shading::flat);
  EXPECT_TRUE(none.normals.empty());
  const raster::Mesh mixed = raster::parse_gltf(doc(with + ", " + without, "", ""), {}, files);
  EXPECT_EQ(mixed.shading, raster::Shading::smooth);
  ASSERT_EQ(mixed.normals.size(), 7u);  // 3 given, 3 zeros for the second primitive's corners, 1 face normal
  ASSERT_EQ(mixed.normal_triangles.size(), 2u);
  EXPECT_EQ(mixed.normal_triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(mixed.normal_triangles[1], (std::array<std::uint32_t, 3>{6, 6, 6}));
  EXPECT_NEAR(mixed.normals[0].y, 0.6, 1e-6);
  EXPECT_EQ(mixed.normals[6], (raster::Vec3{0, 0, 1}));  // counter-clockwise seen from +z
  const raster::Mesh given = raster::parse_gltf(doc(with, "", ""), {}, files);
  EXPECT_EQ(given.shading, raster::Shading::smooth);
  EXPECT_EQ(given.normals.size(), 3u);

  // A texture of alphas 255, 200, 100 and 0, under each alpha mode.
  raster::Image texels;
  texels.width = 4, texels.height = 1, texels.format = raster::PixelFormat::rgba8;
  texels.pixels = {9, 9, 9, 255, 9, 9, 9, 200, 9, 9, 9, 100, 9, 9, 9, 0};
  const auto png = raster::encode_png(texels);
  raster::Uploads textured = files;
  textured["t.png"] = std::string(png.begin(), png.end());
  auto alphas = [&](const std::string& material) {
    const std::string gltf = doc(
        R"({"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "material": 0})", "",
        R"("pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "baseColorFactor": [1, 1, 1, 0.5]})" +
            material);
    const std::string with_texture =
        gltf.substr(0, gltf.size() - 1) + R"(, "textures": [{"source": 0}], "images": [{"uri": "t.png"}]})";
    const raster::Mesh mesh = raster::parse_gltf(with_texture, {}, textured);
    std::vector<int> out;
    for (std::size_t k = 3; k < mesh.textures.at(0).rgba.size(); k += 4)
      out.push_back(mesh.textures[0].rgba[k]);
    return out;
  };
  EXPECT_EQ(alphas(""), (std::vector<int>{255, 255, 255, 255}));  // OPAQUE, the default
  EXPECT_EQ(alphas(R"(, "alphaMode": "BLEND")"), (std::vector<int>{255, 200, 100, 0}));
  // MASK keeps a texel where texel alpha x factor alpha (0.5) reaches the cutoff (0.25): 255 and 200 do.
  EXPECT_EQ(alphas(R"(, "alphaMode": "MASK", "alphaCutoff": 0.25)"), (std::vector<int>{255, 255, 0, 0}));

  // A node's scale of 1e30 takes 1e10 past 2^128.
  std::string far;
  for (float v : {0.f, 0.f, 0.f, 1e10f, 0.f, 0.f, 0.f, 1.f, 0.f}) test::put<float>(far, v);
  refused(doc(without, R"(, "scale": [1e30, 1, 1])", ""), ErrorKind::model,
          "POSITION (accessor 0) element 1 is not a finite point within +-2^128",
          {{"b.bin", far + buffer.substr(36)}});
}

// glTF's alphaMode MASK end to end: a textured quad in front, its left texel below the cutoff, and a blue
// quad behind it drawn later (the mesh's second primitive). Through the cut-out half the blue quad shows
// (the cut-out texel wrote no depth), the kept half hides it; aliased and 4x multisampled.
TEST(Models, GltfMaskCutOutsShowWhatIsDrawnBehindThem) {
  std::string buffer;
  for (const float z : {0.5f, -0.5f})  // the front quad's corners, then the back quad's
    for (const float xy : {-1.f, -1.f, 1.f, -1.f, 1.f, 1.f, -1.f, 1.f}) {
      test::put<float>(buffer, xy);
      if (buffer.size() % 12 == 8) test::put<float>(buffer, z);
    }
  for (const float uv : {0.f, 1.f, 1.f, 1.f, 1.f, 0.f, 0.f, 0.f}) test::put<float>(buffer, uv);  // v down
  for (const std::uint16_t i : {0, 1, 2, 0, 2, 3}) test::put<std::uint16_t>(buffer, i);
  ASSERT_EQ(buffer.size(), 140u);
  raster::Image texels;  // left: red, alpha 0 (cut out); right: opaque green
  texels.width = 2, texels.height = 1, texels.format = raster::PixelFormat::rgba8;
  texels.pixels = {255, 0, 0, 0, 0, 255, 0, 255};
  const auto png = raster::encode_png(texels);
  const raster::Uploads files{{"b.bin", buffer}, {"t.png", std::string(png.begin(), png.end())}};
  const std::string gltf =
      R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 3, "material": 0},
                               {"attributes": {"POSITION": 1}, "indices": 3, "material": 1}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}, "alphaMode": "MASK",
                   "extensions": {"KHR_materials_unlit": {}}},
                  {"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 1]},
                   "extensions": {"KHR_materials_unlit": {}}}],
    "textures": [{"source": 0, "sampler": 0}], "samplers": [{"wrapS": 33071, "wrapT": 33071}],
    "images": [{"uri": "t.png"}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                  {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                    {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
    "buffers": [{"byteLength": 140, "uri": "b.bin"}]})";
  raster::Mesh mesh = raster::parse_gltf(gltf, {}, files);
  ASSERT_EQ(mesh.textures.size(), 1u);
  EXPECT_EQ(mesh.textures[0].rgba[3], 0);  // MASK: the left texel is cut out
  for (const int samples : {1, 4}) {
    SCOPED_TRACE(samples == 1 ? "aliased" : "4x multisampled");
    raster::Scene s;  // looking down -z at [-1, 1]^2 exactly
    s.width = s.height = 64;
    s.meshes.push_back(mesh);
    raster::Primitive p;
    p.kind = raster::PrimitiveKind::mesh;
    s.primitives.push_back(p);
    s.camera.projection = raster::Projection::orthographic;
    s.camera.eye = {0, 0, 5}, s.camera.has_eye = true;
    s.camera.target = {0, 0, 0}, s.camera.has_target = true;
    s.camera.height = 2, s.camera.has_height = true;
    s.antialias = test::multisample(samples);
    const raster::Image image = test::render(s);
    // Two texels over 64 pixels: the outer 16 columns of each side sample one texel only (clamped).
    for (int y = 2; y < 62; y += 5) {
      for (int x = 1; x < 14; x += 4) EXPECT_EQ(test::pixel(image, x, y), test::kBlue) << x << ", " << y;
      for (int x = 51; x < 64; x += 4) EXPECT_EQ(test::pixel(image, x, y), test::kGreen) << x << ", " << y;
    }
  }
}

// Coordinates beyond +-2^128 and counts that are no whole number get the reader's own words, with the line.
TEST(Models, StlAndPlyNameWhatIsOutOfRange) {
  auto refused = [](auto parse, const std::string& bytes, const std::string& words) {
    expect_refused([&] { parse(bytes); }, ErrorKind::model, words);
  };
  auto stl = [](const std::string& b) { return raster::parse_stl(b); };
  auto ply = [](const std::string& b) { return raster::parse_ply(b); };
  refused(stl,
          "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1e39 0 0\nvertex 0 1 0\nendloop\n"
          "endfacet\nendsolid s\n",
          "\"1e39\" is beyond +-2^128");
  const std::string ply_head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  refused(ply, ply_head + "0 0 0\n1e300 0 0\n0 1 0\n3 0 1 2\n",
          "vertex 1 has a coordinate that is not a finite number within +-2^128");
  refused(ply, ply_head + "0 0 0\n1 0 0\n0 1 0\n3.5 0 1 2\n", "is not a whole number");
  refused(ply, "ply\nformat ascii 1.0\nelement vertex 99999999999999999999\nend_header\n",
          "declares 99999999999999999999 entries, more than any file holds");
}

// STL writers put "nan" in the facet normal of a sliver; the normal is not read, so the facet is drawn.
TEST(Models, AsciiStlFacetNormalsAreNotRead) {
  const std::string stl =
      "solid s\nfacet normal nan -nan(ind) inf\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
      "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n";
  EXPECT_EQ(raster::parse_stl(stl).triangles.size(), 1u);
}

// A textured model: the test box (OBJ + MTL + PNG) written as a glTF whose image is an uploaded part named by
// its URI renders the pixels the OBJ does: the image is found, decoded and sampled with v turned over.
TEST(Models, ATexturedGltfRendersAsTheSameObjDoes) {
  const std::string dir = RASTERD_TESTS_DIR "/data/textured/";
  const raster::Uploads obj_files{{"box.mtl", test::read_file(dir + "box.mtl")},
                                  {"box_diffuse.png", test::read_file(dir + "box_diffuse.png")}};
  const std::string obj = test::read_file(dir + "box.obj");
  const raster::Mesh box = raster::parse_obj(obj, {}, {}, obj_files);
  ASSERT_EQ(box.textures.size(), 1u);
  // One vertex per corner (glTF has one index for position and uv), the triangles in OBJ's order.
  std::string buffer;
  for (std::size_t t = 0; t < box.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const raster::Vec3& p = box.positions[box.triangles[t][k]];
      for (double c : {p.x, p.y, p.z}) test::put<float>(buffer, static_cast<float>(c));
    }
  const std::size_t positions = buffer.size();
  for (std::size_t t = 0; t < box.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto& uv = box.uvs[box.uv_triangles[t][k]];
      test::put<float>(buffer, uv[0]);
      test::put<float>(buffer, 1 - uv[1]);  // glTF's v runs down from the image's top
    }
  const std::string n = std::to_string(box.triangles.size() * 3);
  const std::string gltf =
      R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
    "textures": [{"source": 0}], "images": [{"uri": "maps/box_diffuse.png"}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
      n + R"(, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5126, "count": )" +
      n + R"(, "type": "VEC2"}],
    "bufferViews": [{"buffer": 0, "byteLength": )" +
      std::to_string(positions) + R"(},
                    {"buffer": 0, "byteOffset": )" +
      std::to_string(positions) + R"(, "byteLength": )" + std::to_string(buffer.size() - positions) + R"(}],
    "buffers": [{"byteLength": )" +
      std::to_string(buffer.size()) + R"(, "uri": "box.bin"}]})";
  const raster::Image from_obj = render_model(obj, "unlit", obj_files);
  const raster::Image from_gltf = render_model(
      gltf, "unlit", {{"box.bin", buffer}, {"box_diffuse.png", obj_files.at("box_diffuse.png")}});
  ASSERT_GT(test::count_not(from_obj, test::kBlack), 1000);
  EXPECT_EQ(from_gltf.pixels, from_obj.pixels);
  // Without the image the model is refused, naming the file and what was sent.
  expect_refused(
      [&] {
        render_model(gltf, "unlit", {{"box.bin", buffer}});
      },
      ErrorKind::model, "\"box_diffuse.png\", which was not sent");
}

// The corpus: every OBJ, STL, PLY and glTF model of assimp's test files (real files from many exporters,
// broken ones among them) either renders or is refused with a SceneError; nothing else, no crash.
TEST(Models, AssimpTestModelsRenderOrGetASceneError) {
  const std::filesystem::path root = "/usr/share/assimp/models";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << "assimp-testmodels is not installed";
  int rendered = 0, refused = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::string path = entry.path().string();
    const auto format = raster::format_of_file_name(path);
    if (!format) continue;
    SCOPED_TRACE(path);
    raster::Uploads files;  // the model's folder, as a user would upload it
    for (const auto& f : std::filesystem::directory_iterator(entry.path().parent_path()))
      if (f.is_regular_file() && f.path() != entry.path() && f.file_size() < (8 << 20))
        files[f.path().filename().string()] = test::read_file(f.path().string());
    files["m"] = test::read_file(path);
    try {
      raster::Scene scene = raster::parse_scene(
          R"({"width": 48, "height": 48, "primitives": [{"type": "model", "source": "m", "format": ")" +
              std::string(raster::format_name(*format)) + "\"}]}",
          {}, files);
      EXPECT_GT(test::render(scene).pixels.size(), 0u);
      ++rendered;
    } catch (const SceneError& e) {
      ++refused;
      // A model that is not what its format says, past a limit, or (OBJ, MTL) text that is not UTF-8.
      EXPECT_TRUE(e.kind() == ErrorKind::model || e.kind() == ErrorKind::limit ||
                  e.kind() == ErrorKind::encoding)
          << e.what();
    }
  }
  EXPECT_GT(rendered, 60);
  EXPECT_GT(refused, 5);
}

}  // namespace
