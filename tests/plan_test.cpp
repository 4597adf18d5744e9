// The render plan: each scene class gets exactly the buffers, formats and modes it needs, and the bytes
// actually allocated for pixels equal what the plan says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

#include "support.h"

namespace {

using raster::Interpolation;
using raster::Varying;
using raster::VaryingLayout;
using raster::Varyings;
using test::SceneBuilder;

raster::RenderPlan plan_of(const raster::Scene& s, int threads = 0) {
  raster::PlanOptions o;
  o.max_threads = threads;
  return raster::plan(s, raster::Limits{}, o);
}

TEST(Plan, FlatLineDrawingIsOneGreyChannelAndNothingElse) {
  SceneBuilder s(64, 64, raster::Rgba8{255, 255, 255, 255});
  s.line({1, 1}, {60, 30}, raster::Rgba8{0, 0, 0, 255})
      .line({1, 60}, {60, 3}, raster::Rgba8{90, 90, 90, 255});
  const auto p = plan_of(s.scene);
  EXPECT_EQ(p.format, raster::PixelFormat::grey8);
  EXPECT_FALSE(p.depth_buffer);
  EXPECT_EQ(p.samples, 1);
  EXPECT_EQ(p.flat_count, 2);
  EXPECT_EQ(p.smooth_count, 0);
  EXPECT_EQ(p.blend_count, 0);
  EXPECT_EQ(p.threads, 1);
  EXPECT_EQ(p.memory.color_bytes, 64 * 64);
  EXPECT_EQ(p.memory.depth_bytes + p.memory.sample_bytes, 0);
  EXPECT_EQ(p.png.color_type, 0);
  const auto img = raster::render(s.scene, p);
  EXPECT_EQ(static_cast<std::int64_t>(img.pixels.size()), p.memory.color_bytes);
  EXPECT_EQ(test::decode_png(raster::encode_png(img, p.png)).channels, 1)
      << "a grey scene is a 1-channel PNG";
}

TEST(Plan, GradientIsRgbAndSmooth) {
  SceneBuilder s(32, 32);
  s.triangle({1, 1}, {30, 2}, {5, 30}, test::kRed, test::kGreen, test::kBlue);
  const auto p = plan_of(s.scene);
  EXPECT_EQ(p.format, raster::PixelFormat::rgb8);
  EXPECT_EQ(p.smooth_count, 1);
  EXPECT_EQ(p.png.color_type, 2);
  EXPECT_EQ(test::decode_png(raster::encode_png(raster::render(s.scene, p), p.png)).channels, 3);
}

TEST(Plan, TranslucentInkOnOpaqueBackgroundStaysOpaqueRgb) {
  SceneBuilder s(16, 16, raster::Rgba8{10, 20, 30, 255});
  s.triangle({1, 1}, {15, 1}, {1, 15}, raster::Rgba8{255, 0, 0, 100});
  const auto p = plan_of(s.scene);
  EXPECT_EQ(p.format, raster::PixelFormat::rgb8)
      << "blending onto opaque pixels cannot make them transparent";
  EXPECT_EQ(p.blend_count, 1);
  EXPECT_TRUE(p.draw_of(0)->mode.blend);
}

TEST(Plan, TransparentBackgroundNeedsAlpha) {
  SceneBuilder rgba(16, 16, raster::Rgba8{0, 0, 0, 0});
  rgba.triangle({1, 1}, {15, 1}, {1, 15}, test::kRed);
  EXPECT_EQ(plan_of(rgba.scene).format, raster::PixelFormat::rgba8);
  SceneBuilder ga(16, 16, raster::Rgba8{0, 0, 0, 0});
  ga.triangle({1, 1}, {15, 1}, {1, 15}, raster::Rgba8{200, 200, 200, 255});
  const auto p = plan_of(ga.scene);
  EXPECT_EQ(p.format, raster::PixelFormat::grey_alpha8);
  EXPECT_EQ(p.png.color_type, 4);
  const auto d = test::decode_png(raster::encode_png(raster::render(ga.scene, p), p.png));
  EXPECT_EQ(d.channels, 2);
  EXPECT_EQ(d.pixels[0], 0);                   // background grey ...
  EXPECT_EQ(d.pixels[1], 0);                   // ... fully transparent
  EXPECT_EQ(d.pixels[(2 * 16 + 2) * 2], 200);  // ink
  EXPECT_EQ(d.pixels[(2 * 16 + 2) * 2 + 1], 255);
}

TEST(Plan, EqualVertexColoursTakeTheFlatPathWithIdenticalPixels) {
  const raster::Rgba8 c{30, 140, 220, 255};
  SceneBuilder s(48, 48);
  s.triangle({1.3, 2.2}, {46.1, 9.7}, {8.8, 45.5}, c, c, c).line({0.5, 40.5}, {47.5, 3.5}, c, c);
  auto p = plan_of(s.scene);
  EXPECT_EQ(p.flat_count, 2);
  EXPECT_FALSE(p.draw_of(0)->mode.smooth);
  const auto flat = raster::render(s.scene, p);
  for (auto& d : p.draws) {  // force the interpolating path
    d.mode.smooth = true;
    d.mode.varyings.add(raster::Varying::color, raster::Interpolation::affine);
  }
  EXPECT_EQ(flat.pixels, raster::render(s.scene, p).pixels);
}

TEST(Plan, PrimitivesOutsideTheImageAreCulled) {
  SceneBuilder s(32, 32);
  s.triangle({-50, -50}, {-10, -40}, {-30, -5}, test::kRed)  // left of and above the image
      .line({40, 0}, {90, 31}, test::kRed)                   // right of it
      .triangle({1, 1}, {30, 1}, {1, 30}, test::kGreen);
  const auto p = plan_of(s.scene);
  EXPECT_EQ(p.culled_count, 2);
  EXPECT_EQ(p.draw_of(0), nullptr);
  EXPECT_EQ(p.draw_of(1), nullptr);
  EXPECT_NE(p.draw_of(2), nullptr);
  // Culled primitives do not decide the format either: only green ink is visible, still RGB.
  EXPECT_EQ(p.format, raster::PixelFormat::rgb8);
}

TEST(Plan, SmallScenesStayOnTheCallingThreadLargeOnesUseBands) {
  SceneBuilder tiny(256, 256);
  for (int i = 0; i < 100; ++i) tiny.line({0, double(i)}, {255, double(i)}, test::kRed);
  EXPECT_EQ(plan_of(tiny.scene, 8).threads, 1);
  // Few large primitives on a small image: the work estimate is over the threshold, the scene is small.
  SceneBuilder thumbnail(256, 256);
  for (int i = 0; i < 4; ++i)
    thumbnail.triangle({0, 0}, {256, 0}, {0, 256}, test::kRed)
        .triangle({256, 0}, {256, 256}, {0, 256}, test::kRed);
  EXPECT_GT(plan_of(thumbnail.scene, 8).work, 100'000);
  EXPECT_EQ(plan_of(thumbnail.scene, 8).threads, 1) << "256x256 with <= 100 primitives never hands off";
  SceneBuilder big(1024, 1024);
  big.triangle({0, 0}, {1024, 0}, {0, 1024}, test::kRed);
  EXPECT_EQ(plan_of(big.scene, 4).threads, 4);
  EXPECT_EQ(plan_of(big.scene, 1).threads, 1) << "the caller's cap wins";
}

TEST(Plan, MemoryIsCheckedBeforeAllocation) {
  SceneBuilder s(4000, 4000, raster::Rgba8{255, 0, 0, 0});  // not grey, not opaque: RGBA
  raster::Limits limits;
  raster::PlanOptions one_thread;
  one_thread.max_threads = 1;
  limits.max_buffer_bytes = 1ll << 40;
  const raster::MemoryPlan need = raster::plan(s.scene, limits, one_thread).memory;
  EXPECT_EQ(need.color_bytes, 4000ll * 4000 * 4);
  EXPECT_EQ(need.tile_bytes, 0) << "2D, aliased, whole blocks wide: tiles draw in place";
  EXPECT_EQ(need.total(), need.color_bytes);
  SceneBuilder odd(4001, 4000, raster::Rgba8{255, 0, 0, 0});  // a block at the right edge is partly outside
  EXPECT_EQ(raster::plan(odd.scene, limits, one_thread).memory.tile_bytes, 128 * 128 * 4)
      << "one thread's tile";
  limits.max_buffer_bytes = need.total() - 1;
  try {
    raster::plan(s.scene, limits, one_thread);
    FAIL() << "a 64 MB RGBA buffer is over a limit one byte short of it";
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind(), raster::ErrorKind::limit);
  }
  limits.max_buffer_bytes += 1;
  EXPECT_EQ(raster::plan(s.scene, limits, one_thread).memory.total(), need.total());
}

TEST(Plan, LinesBecomeRectanglesOnlyWhenWideOrAntialiased) {
  SceneBuilder s(32, 32);
  s.line({1, 1}, {30, 20}, test::kRed).line({1, 5}, {30, 25}, test::kRed);
  s.scene.primitives[1].width = 3;
  auto p = plan_of(s.scene);
  EXPECT_FALSE(p.draw_of(0)->mode.line_rectangles) << "a 1 px aliased line is Bresenham";
  EXPECT_TRUE(p.draw_of(1)->mode.line_rectangles);
  s.scene.antialias = raster::Antialias::msaa4;
  p = plan_of(s.scene);
  EXPECT_TRUE(p.draw_of(0)->mode.line_rectangles) << "anti-aliased lines are rectangles";
}

TEST(Plan, ExplainShowsTheDecisions) {
  SceneBuilder s(20, 10);
  s.triangle({1, 1}, {19, 1}, {1, 9}, test::kRed, test::kGreen, test::kBlue)
      .line({0, 0}, {5, 5}, raster::Rgba8{1, 2, 3, 4});
  const auto p = plan_of(s.scene);
  EXPECT_EQ(raster::explain_line(p), "rgb8 depth=none samples=1 flat=1 smooth=1 blend=1 culled=0 threads=1");
  const std::string j = raster::explain_json(p);
  EXPECT_NE(j.find("\"format\": \"rgb8\""), std::string::npos) << j;
  EXPECT_NE(j.find("\"color\": 600"), std::string::npos) << j;
}

// Issue 61: each shader draw's program in the explain: its size, per-render part, slots (and a thread's
// bytes of them), loops, derivatives and the channels it samples; the count; and their memory.
TEST(Plan, ExplainShowsEachShadersProgram) {
  raster::Scene s;
  s.width = 40, s.height = 20;
  const auto add = [&](const std::string& source) {
    raster::ShaderPrimitive sp;
    sp.source = source;
    s.shaders.push_back(sp);
    raster::Primitive p;
    p.kind = raster::PrimitiveKind::shader;
    p.mesh = static_cast<std::uint32_t>(s.shaders.size() - 1);
    s.primitives.push_back(p);
  };
  add("void mainImage(out vec4 c, in vec2 p) { c = vec4(p / iResolution.xy, 0.5, 1.0); }");
  add("uniform float k;\nvoid mainImage(out vec4 c, in vec2 p) {\n  float a = 0.0;\n"
      "  for (int i = 0; i < int(k); i++) a += fwidth(p.x) * k;\n"
      "  c = texture(iChannel2, p / iResolution.xy) + vec4(a);\n}\n");
  s.shaders[1].whole = false, s.shaders[1].rect = {30, 5, 20, 10};  // half outside: clipped to 10 x 10
  s.shaders[1].opaque = false;
  const auto p = plan_of(s, 2);
  ASSERT_EQ(p.shaders.size(), 2u);
  EXPECT_NE(raster::explain_line(p).find(" shaders=2 "), std::string::npos) << raster::explain_line(p);
  const auto j = nlohmann::json::parse(raster::explain_json(p));
  EXPECT_EQ(j["primitives"]["shaders"], 2);
  ASSERT_EQ(j["shaders"].size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const nlohmann::json& e = j["shaders"][k];
    const raster::CompiledShader& c = *p.shaders[static_cast<std::size_t>(k)].shader;
    EXPECT_EQ(e["primitive"], k);
    EXPECT_EQ(e["instructions"], c.instructions());
    EXPECT_EQ(e["prologue_instructions"], c.prologue_instructions());
    EXPECT_EQ(e["slots"], c.slots());
    EXPECT_EQ(e["register_bytes"], c.slots() * 64 * 4) << "a thread's values for a block of 64 pixels";
    EXPECT_EQ(e["loops"], c.loops());
    EXPECT_EQ(e["program_bytes"], c.bytes());
  }
  EXPECT_EQ(j["shaders"][0]["rect"], nlohmann::json({0, 0, 40, 20}));
  EXPECT_EQ(j["shaders"][1]["rect"], nlohmann::json({30, 5, 10, 10}));
  EXPECT_EQ(j["shaders"][0]["loops"], 0);
  EXPECT_EQ(j["shaders"][1]["loops"], 1);
  EXPECT_EQ(j["shaders"][0]["derivatives"], false);
  EXPECT_EQ(j["shaders"][1]["derivatives"], true);
  EXPECT_EQ(j["shaders"][0]["channels"], nlohmann::json::array());
  EXPECT_EQ(j["shaders"][1]["channels"], nlohmann::json({2}));
  EXPECT_EQ(j["shaders"][1]["opaque"], false);
  EXPECT_GT(j["shaders"][1]["instructions"].get<int>(), j["shaders"][0]["instructions"].get<int>());
  EXPECT_EQ(j["memory_bytes"]["shaders"], p.memory.shader_bytes);
  EXPECT_EQ(p.memory.shader_bytes,
            std::int64_t{p.threads} * (p.shaders[0].register_bytes + p.shaders[1].register_bytes));
  EXPECT_GT(p.memory.shader_bytes, 0);
  // A scene without shaders says nothing of them but their count.
  SceneBuilder plain(8, 8);
  const auto q = nlohmann::json::parse(raster::explain_json(plan_of(plain.scene)));
  EXPECT_FALSE(q.contains("shaders"));
  EXPECT_EQ(q["primitives"]["shaders"], 0);
  EXPECT_EQ(raster::explain_line(plan_of(plain.scene)).find("shaders="), std::string::npos);
}

TEST(Plan, RejectsScenesBuiltInCodeThatReferToMissingData) {
  SceneBuilder s(8, 8);
  s.triangle({1, 1}, {2, 2}, {1, 3}, test::kRed);
  s.scene.primitives[0].point_count = 4;
  EXPECT_THROW(raster::plan(s.scene), raster::SceneError);
  s.scene.primitives[0].point_count = 3;
  s.scene.colors.clear();
  EXPECT_THROW(raster::plan(s.scene), raster::SceneError);
}

// A mesh's indices, normals and coordinates are checked whoever built it: one index past the positions in any
// of its lists, normals without normal_triangles that are not one per position, or a coordinate that is not
// finite, is a SceneError before anything is drawn (the checks run over whole arrays at once; an element
// they skipped would be read out of bounds).
TEST(Plan, RejectsMeshesWhoseIndicesOrCoordinatesAreOutOfRange) {
  raster::Scene base;
  base.width = base.height = 16;
  raster::Mesh m;
  for (int i = 0; i < 40; ++i)
    m.positions.push_back({static_cast<float>(i % 7), static_cast<float>(i / 7), static_cast<float>(i % 3)});
  for (std::uint32_t t = 0; t + 2 < 40; ++t) m.triangles.push_back({t, t + 1, t + 2});
  m.segments = {{0, 39}};
  m.points = {0, 5, 39};
  m.colors = {test::kRed};
  base.meshes.push_back(m);
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  base.primitives.push_back(p);
  EXPECT_NO_THROW(raster::plan(base));
  auto refused = [&](auto&& spoil) {
    raster::Scene s = base;
    spoil(s.meshes[0]);
    EXPECT_THROW(raster::plan(s), raster::SceneError);
  };
  refused([](raster::Mesh& m) { m.triangles[17][1] = 40; });
  refused([](raster::Mesh& m) { m.triangles.back()[2] = 0xFFFFFFFFu; });
  refused([](raster::Mesh& m) { m.segments[0][1] = 40; });
  refused([](raster::Mesh& m) { m.points[1] = 41; });
  refused([](raster::Mesh& m) { m.normals.assign(39, {0, 0, 1}); });  // one short, indexed as positions
  refused([](raster::Mesh& m) {
    m.normals.assign(2, {0, 0, 1});
    m.normal_triangles.assign(m.triangles.size(), {0, 1, 2});  // normal 2 of 2
  });
  refused([](raster::Mesh& m) { m.positions[23].y = INFINITY; });
  refused([](raster::Mesh& m) { m.positions[39].z = NAN; });
}

// The camera fitted to a mesh under the identity is the one fitted to the same world positions reached
// through a transform (the identity's box is found by a pass of its own): the same view, bit for bit.
TEST(Plan, AnUntransformedMeshIsFittedAsItsWorldPositionsAre) {
  raster::Scene direct;
  direct.width = 64, direct.height = 48;
  raster::Mesh m;
  m.positions.push_back({-1.25f, 0.5f, 0.25f});  // the box's extremes first and last: every one is read
  for (int i = 0; i < 300; ++i)  // multiples of 1/64: exact under a translation by whole units
    m.positions.push_back({(i * 37 % 101) / 64.0f - 0.5f, (i * 53 % 97) / 64.0f, -(i * 29 % 89) / 64.0f});
  m.positions.push_back({0.0f, -0.0f, -0.0f});
  m.positions.push_back({2.5f, 1.75f, -2.0f});
  for (std::uint32_t t = 0; t + 2 < m.positions.size(); ++t) m.triangles.push_back({t, t + 1, t + 2});
  m.colors = {test::kRed};
  direct.meshes.push_back(m);
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  direct.primitives.push_back(p);
  raster::Scene moved = direct;
  for (raster::Vec3f& q : moved.meshes[0].positions) q.x -= 3, q.z += 2;
  moved.meshes[0].transform(0, 3) = 3, moved.meshes[0].transform(2, 3) = -2;
  for (const raster::View view : {raster::View::front, raster::View::iso, raster::View::top}) {
    direct.camera.view = moved.camera.view = view;
    const raster::ViewPlan a = raster::plan(direct).view, b = raster::plan(moved).view;
    EXPECT_EQ(a.eye, b.eye);
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.near, b.near);
    EXPECT_EQ(a.far, b.far);
    EXPECT_EQ(a.world_to_clip, b.world_to_clip);
  }
}

// VaryingLayout lays rows out in enum order whatever the order they were added in: a vertex holds every
// row (clipping interpolates those before depth), a record the flat rows once and the others per vertex.
TEST(Plan, VaryingsLayOutRowsInEnumOrder) {
  Varyings v;  // colour alone, flat: the default
  VaryingLayout l = VaryingLayout::of(v);
  EXPECT_EQ(l.floats, 4);
  EXPECT_EQ(l.flat_floats, 4);
  EXPECT_EQ(l.stride, 0);
  EXPECT_EQ(l.record_floats(), 4);
  v.add(Varying::inv_w, Interpolation::affine)
      .add(Varying::normal, Interpolation::perspective)
      .add(Varying::depth, Interpolation::affine);
  l = VaryingLayout::of(v);
  EXPECT_EQ(l.vertex_offset[static_cast<int>(Varying::color)], 0);
  EXPECT_EQ(l.vertex_offset[static_cast<int>(Varying::normal)], 4);
  EXPECT_EQ(l.vertex_offset[static_cast<int>(Varying::uv)], -1);
  EXPECT_EQ(l.vertex_offset[static_cast<int>(Varying::position)], -1);
  EXPECT_EQ(l.vertex_offset[static_cast<int>(Varying::depth)], 7);
  EXPECT_EQ(l.vertex_offset[static_cast<int>(Varying::inv_w)], 8);
  EXPECT_EQ(l.floats, 9);
  EXPECT_EQ(l.clipped_floats, 7) << "depth and 1 / w are written by the viewport, not clipped";
  EXPECT_EQ(l.flat_floats, 4);
  EXPECT_EQ(l.stride, 5);
  EXPECT_EQ(l.record_floats(), 19) << "a flat colour once + 3 x (normal, depth, 1 / w)";
  EXPECT_EQ(l.record_at(Varying::color, 2), 0) << "flat: every vertex reads the one colour";
  EXPECT_EQ(l.record_at(Varying::normal, 0), 4);
  EXPECT_EQ(l.record_at(Varying::normal, 1), 9);
  EXPECT_EQ(l.record_at(Varying::depth, 2), 4 + 2 * 5 + 3);
  EXPECT_EQ(l.record_at(Varying::inv_w, 2), 18);

  Varyings in_order;
  in_order.add(Varying::normal, Interpolation::perspective)
      .add(Varying::depth, Interpolation::affine)
      .add(Varying::inv_w, Interpolation::affine);
  EXPECT_EQ(v, in_order) << "the order of add() does not change the description";

  // Every row, colour re-interpolated: nothing flat, 14 floats a vertex, 12 of them clipped.
  v.add(Varying::uv, Interpolation::perspective)
      .add(Varying::position, Interpolation::perspective)
      .add(Varying::color, Interpolation::perspective);
  l = VaryingLayout::of(v);
  EXPECT_EQ(l.floats, VaryingLayout::kMaxFloats);
  EXPECT_EQ(l.clipped_floats, 12);
  EXPECT_EQ(l.flat_floats, 0);
  EXPECT_EQ(l.stride, 14);
  EXPECT_EQ(l.record_floats(), 42);
  EXPECT_EQ(l.vertex_offset[static_cast<int>(Varying::uv)], 7);
  EXPECT_EQ(l.vertex_offset[static_cast<int>(Varying::position)], 9);
  EXPECT_EQ(l.record_at(Varying::color, 1), 14);
  EXPECT_EQ(l.record_at(Varying::position, 2), 28 + 9);
  // The description is two bits a row: the four modes of every DrawPlan stay as small as the booleans
  // they replaced (a 2D scene has a DrawPlan per primitive).
  EXPECT_LE(sizeof(Varyings), 2u);
}

raster::Scene one_mesh_scene(raster::Mesh mesh) {
  raster::Scene s;
  s.width = s.height = 32;
  s.meshes.push_back(std::move(mesh));
  raster::Primitive p;
  p.kind = raster::PrimitiveKind::mesh;
  s.primitives.push_back(p);
  return s;
}

// The plan gives each mesh the rows its shading reads: a normal for per-pixel light (not for flat or unlit
// shading), uv when textured, the world position when a point light lights it per pixel, colour per vertex
// only when the colours vary, and 1 / w whenever something is interpolated.
TEST(Plan, EachMeshGetsTheVaryingsItsShadingReads) {
  raster::Mesh quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  quad.colors = {test::kRed};
  auto rows = [](const raster::Scene& s) { return raster::plan(s).draws.at(0).mode.varyings; };
  auto has = [](const Varyings& v, std::initializer_list<Varying> want) {
    std::string got;
    for (int i = 0; i < raster::kVaryingCount; ++i) {
      const bool wanted = std::find(want.begin(), want.end(), static_cast<Varying>(i)) != want.end();
      if (v.has(static_cast<Varying>(i)) != wanted) got += " row " + std::to_string(i);
    }
    return got;
  };
  using enum Varying;
  const Varyings smooth = rows(one_mesh_scene(quad));
  EXPECT_EQ(has(smooth, {color, normal, depth, inv_w}), "");
  EXPECT_EQ(smooth.how(normal), Interpolation::perspective);
  EXPECT_EQ(smooth.how(color), Interpolation::flat) << "one colour: stored once";
  EXPECT_EQ(smooth.how(depth), Interpolation::affine);

  raster::Mesh flat = quad;
  flat.shading = raster::Shading::flat;
  EXPECT_EQ(has(rows(one_mesh_scene(flat)), {color, depth}), "") << "flat: lit per face, no normal";
  raster::Mesh unlit = quad;
  unlit.shading = raster::Shading::unlit;
  EXPECT_EQ(has(rows(one_mesh_scene(unlit)), {color, depth}), "");

  raster::Mesh textured = unlit;
  textured.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  textured.uv_triangles = textured.triangles;
  raster::Texture t;
  t.width = t.height = 1, t.rgba = {9, 9, 9, 255};
  textured.textures.push_back(t);
  const Varyings uv_rows = rows(one_mesh_scene(textured));
  EXPECT_EQ(has(uv_rows, {color, uv, depth, inv_w}), "");
  EXPECT_EQ(uv_rows.how(uv), Interpolation::perspective);

  raster::Scene point = one_mesh_scene(quad);
  raster::Light lamp;
  lamp.kind = raster::LightKind::point, lamp.position = {0, 0, 3};
  point.lights = {lamp};
  EXPECT_EQ(has(rows(point), {color, normal, position, depth, inv_w}), "");
  point.meshes[0].shading = raster::Shading::flat;
  EXPECT_EQ(has(rows(point), {color, depth}), "") << "flat: the face's light is worked out in geometry";

  raster::Mesh varied = unlit;
  varied.colors = {test::kRed, test::kGreen, test::kBlue, test::kWhite};
  const Varyings varied_rows = rows(one_mesh_scene(varied));
  EXPECT_EQ(has(varied_rows, {color, depth, inv_w}), "");
  EXPECT_EQ(varied_rows.how(color), Interpolation::perspective);
  EXPECT_EQ(VaryingLayout::of(varied_rows).record_floats(), 3 * 6);
}

}  // namespace

namespace {

// The work estimate counts every sample plane the render draws: a 3D "area" render is drawn at 8 samples
// (area gives way to samples with depth), so its estimate is the 8-sample one, and the thread count follows
// from it. (It was once the 1-sample estimate, 8x too small.)
TEST(Plan, AThreeDAreaRenderIsEstimatedAtTheSamplesItDraws) {
  raster::Mesh quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  quad.colors = {test::kRed};
  raster::Scene s = one_mesh_scene(quad);
  s.width = s.height = 512;
  const raster::RenderPlan aliased = plan_of(s, 4);
  s.antialias = raster::Antialias::area;
  const raster::RenderPlan area = plan_of(s, 4);
  s.antialias = raster::Antialias::msaa8;
  const raster::RenderPlan eight = plan_of(s, 4);
  EXPECT_EQ(area.coverage, raster::Coverage::samples);
  EXPECT_EQ(area.samples, 8);
  EXPECT_GT(aliased.work, 0);
  EXPECT_EQ(area.work, 8 * aliased.work);
  EXPECT_EQ(area.work, eight.work);
  EXPECT_EQ(area.threads, eight.threads);
}

}  // namespace
