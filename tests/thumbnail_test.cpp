// A bare model's picture as thumbnailers draw it (issue 51): the three-quarter view, the camera fitted to
// the vertices as projected, a flat model seen face on, and normals as each format says (creases kept in
// OBJ and PLY without normals, glTF without normals flat).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <string>

#include "model_files.h"
#include "raster/model.h"
#include "raster/raster.h"
#include "support.h"

namespace {

using raster::ModelFormat;

// A box of sides sx, sy, sz about the origin, its faces as quads (counter-clockwise outside) with no normals.
std::string box_obj(double sx = 2, double sy = 2, double sz = 2) {
  std::string out;
  for (int k = 0; k < 8; ++k)
    out += "v " + test::num((k & 1 ? 0.5 : -0.5) * sx) + " " + test::num((k & 2 ? 0.5 : -0.5) * sy) + " " +
           test::num((k & 4 ? 0.5 : -0.5) * sz) + "\n";
  // Corners: bit 0 x, bit 1 y, bit 2 z (1-based below).
  return out + "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
}

// The same box with each face its own colour (unlit, so each colour is exact): +x red, -x cyan, +y green,
// -y magenta, +z blue, -z yellow.
raster::Mesh coloured_box() {
  const std::string obj = box_obj();
  const std::string faces =
      "usemtl nz\nf 1 3 4 2\nusemtl pz\nf 5 6 8 7\nusemtl ny\nf 1 2 6 5\n"
      "usemtl py\nf 3 7 8 4\nusemtl nx\nf 1 5 7 3\nusemtl px\nf 2 4 8 6\n";
  const std::string mtl =
      "newmtl px\nKd 1 0 0\nnewmtl nx\nKd 0 1 1\nnewmtl py\nKd 0 1 0\n"
      "newmtl ny\nKd 1 0 1\nnewmtl pz\nKd 0 0 1\nnewmtl nz\nKd 1 1 0\n";
  raster::Mesh mesh = raster::parse_obj("mtllib c.mtl\n" + obj.substr(0, obj.find("f ")) + faces, mtl);
  mesh.shading = raster::Shading::unlit;
  return mesh;
}

// A bare model's scene at `width` x `height`, aliased, so that each pixel is its face's shade.
raster::Scene bare(raster::Mesh mesh, ModelFormat format, int width = 128, int height = 128) {
  if (mesh.colors.empty()) mesh.colors = {{204, 204, 204, 255}};  // a bare model's grey (model_mesh's)
  raster::Scene scene = raster::model_scene(std::move(mesh), format);
  scene.width = width, scene.height = height, scene.antialias = raster::Antialias::none;
  return scene;
}

std::map<std::uint32_t, int> histogram(const raster::Image& image, raster::Rgba8 background) {
  std::map<std::uint32_t, int> counts;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const raster::Rgba8 p = test::pixel(image, x, y);
      if (!(p == background)) ++counts[p.r | p.g << 8 | p.b << 16];
    }
  return counts;
}

// The covered pixels' box: [x0, x1] x [y0, y1], inclusive; x0 > x1 when nothing is covered.
struct Covered {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
Covered covered(const raster::Image& image) {
  Covered c;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!(test::pixel(image, x, y) == raster::kModelPicture.background))
        c.x0 = std::min(c.x0, x), c.x1 = std::max(c.x1, x), c.y0 = std::min(c.y0, y),
        c.y1 = std::max(c.y1, y);
  return c;
}

TEST(Thumbnail, TheDefaultViewShowsTheTopFrontAndRightSide) {
  const std::map<std::uint32_t, int> seen =
      histogram(test::render(bare(coloured_box(), ModelFormat::obj)), raster::kModelPicture.background);
  auto count = [&](raster::Rgba8 c) {
    const auto it = seen.find(c.r | c.g << 8 | c.b << 16);
    return it == seen.end() ? 0 : it->second;
  };
  const int front = count({0, 0, 255, 255}), right = count({255, 0, 0, 255}), top = count({0, 255, 0, 255});
  EXPECT_GT(top, 1000);
  EXPECT_GT(front, right) << "from the front-right: more of the front than of the side";
  EXPECT_GT(right, top) << "and 30 degrees above: less of the top than of either side";
  EXPECT_EQ(front + right + top,
            std::accumulate(seen.begin(), seen.end(), 0, [](int s, const auto& kv) { return s + kv.second; }))
      << "no back, left or bottom face";
  // A Z-up format (STL) turns the view with its up axis: its top (+z, blue) is on top, its front is -y.
  raster::Mesh z_up = coloured_box();
  const std::map<std::uint32_t, int> stl =
      histogram(test::render(bare(std::move(z_up), ModelFormat::stl)), raster::kModelPicture.background);
  EXPECT_GT(stl.count(0xff0000u), 0u) << "top +z (blue)";
  EXPECT_GT(stl.count(0xff00ffu), 0u) << "front -y (magenta)";
  EXPECT_GT(stl.count(0x0000ffu), 0u) << "right +x (red)";
  EXPECT_EQ(stl.size(), 3u);
}

TEST(Thumbnail, EveryNamedViewStillShowsItsFace) {
  const std::pair<raster::View, raster::Rgba8> cases[] = {
      {raster::View::front, {0, 0, 255, 255}}, {raster::View::back, {255, 255, 0, 255}},
      {raster::View::right, {255, 0, 0, 255}}, {raster::View::left, {0, 255, 255, 255}},
      {raster::View::top, {0, 255, 0, 255}},   {raster::View::bottom, {255, 0, 255, 255}}};
  for (const auto& [view, colour] : cases) {
    raster::Scene scene = bare(coloured_box(), ModelFormat::obj, 65, 65);
    scene.camera.view = view, scene.camera.has_view = true;
    const raster::Image image = test::render(scene);
    EXPECT_EQ(test::pixel(image, 32, 32), colour) << static_cast<int>(view);
    EXPECT_EQ(histogram(image, raster::kModelPicture.background).size(), 1u) << "square on: one face";
    // Fitted to the vertices: the face fills 90% of the frame (58.5 of 65 pixels), centred.
    const Covered c = covered(image);
    EXPECT_NEAR(c.x1 - c.x0 + 1, 58.5, 1.5) << static_cast<int>(view);
    EXPECT_NEAR(c.x0, 64 - c.x1, 1) << static_cast<int>(view);
  }
}

// The extreme vertices lie within the margin of the frame: the longer side spans 90% of its axis, centred,
// and the other side no more than 90% of its own, centred too; in perspective and orthographic, for a tall,
// a wide and a flat model, in a square and a wide picture.
TEST(Thumbnail, TheFitPutsTheModelWithinTheMarginOfTheFrame) {
  struct Case {
    const char* name;
    std::string obj;
  };
  const Case cases[] = {{"tall", box_obj(1, 4, 1)},
                        {"wide", box_obj(4, 1, 1)},
                        {"flat", "v -2 0 -1\nv 2 0 -1\nv 2 0 1\nv -2 0 1\nf 1 4 3 2\n"}};
  for (const Case& c : cases)
    for (const raster::Projection projection :
         {raster::Projection::perspective, raster::Projection::orthographic})
      for (const auto& [w, h] : {std::pair{160, 160}, std::pair{240, 160}}) {
        raster::Scene scene = bare(raster::parse_obj(c.obj), ModelFormat::obj, w, h);
        scene.camera.projection = projection;
        const Covered box = covered(test::render(scene));
        const std::string what =
            std::string(c.name) +
            (projection == raster::Projection::perspective ? " perspective " : " orthographic ") +
            std::to_string(w) + "x" + std::to_string(h);
        ASSERT_LE(box.x0, box.x1) << what << ": nothing drawn";
        const double span_x = box.x1 - box.x0 + 1, span_y = box.y1 - box.y0 + 1;
        const double fill = std::max(span_x / w, span_y / h);
        EXPECT_NEAR(fill, 0.9, 2.0 / h) << what << ": the tighter axis fills the frame less the margins";
        EXPECT_LE(span_x, 0.9 * w + 1) << what;
        EXPECT_LE(span_y, 0.9 * h + 1) << what;
        EXPECT_NEAR(box.x0, w - 1 - box.x1, 1.5) << what << ": centred across";
        EXPECT_NEAR(box.y0, h - 1 - box.y1, 1.5) << what << ": centred up and down";
      }
}

TEST(Thumbnail, AFlatModelIsSeenFaceOn) {
  // Three flat models as the assimp corpus has them, each exactly edge-on from the front: a triangle in the
  // XY plane of a Z-up STL (flat along up: seen from above), a square in the YZ plane and one in the XZ
  // plane of a Y-up OBJ.
  const std::string stl =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid t\n";
  struct Case {
    const char* name;
    raster::Mesh mesh;
    ModelFormat format;
  };
  Case cases[] = {
      {"triangle in XY, Z up", raster::parse_stl(stl), ModelFormat::stl},
      {"square in YZ", raster::parse_obj("v 0 -1 -1\nv 0 1 -1\nv 0 1 1\nv 0 -1 1\nf 1 2 3 4\n"),
       ModelFormat::obj},
      {"square in XZ, faces down", raster::parse_obj("v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 2 3 4\n"),
       ModelFormat::obj}};
  for (Case& c : cases) {
    raster::Scene scene = bare(c.mesh, c.format, 100, 100);
    const raster::Image image = test::render(scene);
    const int drawn = test::count_not(image, raster::kModelPicture.background);
    // Face on, a square fills 90% x 90% of the frame; a right triangle half of that.
    EXPECT_GT(drawn, std::string(c.name).starts_with("triangle") ? 3500 : 7500) << c.name;
    const raster::RenderPlan plan = raster::plan(scene);
    const raster::Vec3 d{plan.view.eye.x - plan.view.target.x, plan.view.eye.y - plan.view.target.y,
                         plan.view.eye.z - plan.view.target.z};
    // Seen from the side its face's normal points to (the front is lit, not the back).
    const raster::Mesh& m = c.mesh;
    const raster::Vec3f a = m.positions[m.triangles[0][0]], b = m.positions[m.triangles[0][1]],
                        e = m.positions[m.triangles[0][2]];
    const raster::Vec3 n{(b.y - a.y) * (e.z - a.z) - (b.z - a.z) * (e.y - a.y),
                         (b.z - a.z) * (e.x - a.x) - (b.x - a.x) * (e.z - a.z),
                         (b.x - a.x) * (e.y - a.y) - (b.y - a.y) * (e.x - a.x)};
    EXPECT_GT(n.x * d.x + n.y * d.y + n.z * d.z, 0) << c.name;
    // A named view is kept as asked, even edge-on.
    scene.camera.view = raster::View::front, scene.camera.has_view = true;
    if (std::string(c.name) == "square in YZ") {
      EXPECT_LT(test::count_not(test::render(scene), raster::kModelPicture.background), 300) << c.name;
    }
  }
}

// A UV sphere of `rings` x `segments` quads (no normals): neighbouring faces turn 360 / segments degrees.
std::string sphere_obj(int rings, int segments) {
  std::string out;
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double t = std::numbers::pi * i / rings, p = 2 * std::numbers::pi * j / segments;
      out += "v " + std::to_string(std::sin(t) * std::cos(p)) + " " + std::to_string(std::cos(t)) + " " +
             std::to_string(-std::sin(t) * std::sin(p)) + "\n";
    }
  out += "v 0 1 0\nv 0 -1 0\n";
  const int top = (rings - 1) * segments + 1, bottom = top + 1;
  auto at = [&](int i, int j) { return std::to_string((i - 1) * segments + (j % segments) + 1); };
  for (int j = 0; j < segments; ++j) {
    out += "f " + std::to_string(top) + " " + at(1, j) + " " + at(1, j + 1) + "\n";
    out += "f " + std::to_string(bottom) + " " + at(rings - 1, j + 1) + " " + at(rings - 1, j) + "\n";
    for (int i = 1; i + 1 < rings; ++i)
      out += "f " + at(i, j) + " " + at(i + 1, j) + " " + at(i + 1, j + 1) + " " + at(i, j + 1) + "\n";
  }
  return out;
}

TEST(Thumbnail, ABoxWithoutNormalsKeepsItsEdgesASphereStaysSmooth) {
  const raster::Mesh box = raster::parse_obj(box_obj());
  EXPECT_EQ(box.crease_deg, raster::kModelCreaseDeg);
  const raster::Image creased = test::render(bare(box, ModelFormat::obj));
  const std::map<std::uint32_t, int> shades = histogram(creased, raster::kModelPicture.background);
  ASSERT_EQ(shades.size(), 3u) << "three faces, each one flat shade";
  std::vector<int> greys;
  for (const auto& [rgb, n] : shades) {
    greys.push_back(static_cast<int>(rgb & 0xff));
    EXPECT_GT(n, 1000);
  }
  std::sort(greys.begin(), greys.end());
  EXPECT_GE(greys[1] - greys[0], 10);
  EXPECT_GE(greys[2] - greys[1], 10);
  raster::Mesh smooth = box;
  smooth.crease_deg = 180;
  EXPECT_GT(histogram(test::render(bare(smooth, ModelFormat::obj)), raster::kModelPicture.background).size(),
            50u)
      << "without the crease the box is shaded as a ball";

  // 32 segments: faces turn 11.25 degrees, within the crease, so no vertex is split: the same bytes as
  // smooth everywhere. 6 segments (60 degrees) keeps its edges.
  for (const auto& [segments, same] : {std::pair{32, true}, std::pair{6, false}}) {
    const raster::Mesh sphere = raster::parse_obj(sphere_obj(16, segments));
    raster::Mesh everywhere = sphere;
    everywhere.crease_deg = 180;
    EXPECT_EQ(test::render(bare(sphere, ModelFormat::obj)).pixels ==
                  test::render(bare(everywhere, ModelFormat::obj)).pixels,
              same)
        << segments << " segments";
  }
  // PLY without normals is creased as OBJ is; normals given in the file win.
  EXPECT_EQ(raster::parse_ply(test::write_ply_ascii(test::make_mesh(3))).crease_deg, raster::kModelCreaseDeg);
  std::string with_normals = box_obj();
  with_normals = with_normals.substr(0, with_normals.find("f "));
  for (int k = 0; k < 8; ++k)  // each corner's normal along its diagonal: a box shaded as a ball
    with_normals +=
        std::string("vn ") + (k & 1 ? "1" : "-1") + (k & 2 ? " 1" : " -1") + (k & 4 ? " 1\n" : " -1\n");
  with_normals +=
      "f 1//1 3//3 4//4 2//2\nf 5//5 6//6 8//8 7//7\nf 1//1 2//2 6//6 5//5\n"
      "f 3//3 7//7 8//8 4//4\nf 1//1 5//5 7//7 3//3\nf 2//2 4//4 8//8 6//6\n";
  EXPECT_GT(histogram(test::render(bare(raster::parse_obj(with_normals), ModelFormat::obj)),
                      raster::kModelPicture.background)
                .size(),
            50u)
      << "the file's normals win over the crease";
}

TEST(Thumbnail, CreasedNormalsAreTheSameAtEveryThreadCount) {
  // A dense, bumpy mesh with creases everywhere (random radii): the split vertices found and grouped on
  // several threads give the bytes of one.
  const raster::Mesh mesh = raster::parse_ply(test::write_ply_ascii(test::make_mesh(11, 120, 40)));
  // 256 x 256: every vertex's normal; 64 x 64 (fewer pixels than triangles): only where drawn.
  for (const int side : {256, 64}) {
    raster::Scene scene = bare(mesh, ModelFormat::ply, side, side);
    const raster::Image one = test::render(scene, 1);
    for (const int threads : {2, 3, 7})
      EXPECT_EQ(test::render(scene, threads).pixels, one.pixels) << side << " px, " << threads << " threads";
    raster::Mesh smooth = mesh;
    smooth.crease_deg = 180;
    EXPECT_NE(test::render(bare(smooth, ModelFormat::ply, side, side)).pixels, one.pixels)
        << "some vertex is split";
  }
}

TEST(Thumbnail, AGltfWithoutNormalsIsFlat) {
  test::TestMesh box;
  for (int k = 0; k < 8; ++k) box.v.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
  box.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const raster::Mesh mesh = raster::parse_gltf(test::write_glb(test::make_gltf(box, "", false)));
  EXPECT_EQ(mesh.shading, raster::Shading::flat);
  EXPECT_EQ(histogram(test::render(bare(mesh, ModelFormat::glb)), raster::kModelPicture.background).size(),
            3u)
      << "three faces, each one flat shade";
}

}  // namespace
