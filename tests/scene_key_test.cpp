// The scene's canonical bytes (raster/scene_fields.h), which the service's ETag hashes: changing any field of
// any struct of a scene changes them, so two different scenes cannot share a tag through a field left out.
#include <gtest/gtest.h>

#include <string>
#include <type_traits>

#include "raster/scene_fields.h"

namespace {

using raster::Scene;

std::string canonical(const Scene& scene) {
  std::string out;
  auto append = [&](const void* data, std::size_t n) { out.append(static_cast<const char*>(data), n); };
  raster::write_canonical(scene, append);
  return out;
}

// A scene with one of everything, so that every vector has an element whose fields can change.
Scene one_of_everything() {
  Scene s;
  s.width = 8, s.height = 8, s.background = {1, 2, 3, 4};
  s.points = {{1, 2}, {3, 4}};
  s.colors = {{5, 6, 7, 8}};
  s.primitives = {raster::Primitive{}};
  raster::Mesh m;
  m.positions = {{1, 2, 3}};
  m.triangles = {{0, 0, 0}};
  m.segments = {{0, 0}};
  m.points = {0};
  m.normals = {{0, 0, 1}};
  m.normal_triangles = {{0, 0, 0}};
  m.colors = {{9, 9, 9, 9}};
  m.face_colors = {{2, 2, 2, 2}};
  m.uvs = {{0.5f, 0.25f}};
  m.uv_triangles = {{0, 0, 0}};
  raster::Texture t;
  t.width = t.height = 1, t.rgba = {1, 2, 3, 4}, t.name = "brick.png";
  m.textures = {t};
  m.face_textures = {0};
  m.materials = {raster::Material{}};
  m.face_materials = {0};
  s.meshes = {m};
  s.lights = {raster::Light{}};
  raster::ShaderPrimitive shader;
  shader.source = "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }";
  shader.textures = {t};
  shader.channels = {0, -1, -1, -1};
  shader.uniforms = {{"tint", {0.5, 0.25}}};
  s.shaders = {shader};
  return s;
}

// Changes each field reachable from `x` (inside `scene`) in turn, checks that the canonical bytes change,
// and puts it back. Counts the changes made.
template <class T>
void vary_each_field(T& x, Scene& scene, const std::string& base, const std::string& where, int& changes) {
  auto check = [&](const char* how) {
    ++changes;
    EXPECT_NE(canonical(scene), base) << where << ": " << how;
  };
  if constexpr (std::is_same_v<T, bool>) {
    x = !x, check("flipped"), x = !x;
  } else if constexpr (std::is_arithmetic_v<T>) {
    const T saved = x;
    x = static_cast<T>(x + 1), check("plus one"), x = saved;
  } else if constexpr (std::is_enum_v<T>) {
    const T saved = x;
    x = static_cast<T>(static_cast<std::underlying_type_t<T>>(x) + 1), check("the next value"), x = saved;
  } else if constexpr (std::is_same_v<T, std::string>) {
    x += "x", check("longer"), x.pop_back();
  } else if constexpr (requires {
                         x.first;
                         x.second;
                       }) {  // a pair
    vary_each_field(x.first, scene, base, where + ".first", changes);
    vary_each_field(x.second, scene, base, where + ".second", changes);
  } else if constexpr (requires { x.push_back(x.front()); }) {  // a vector
    x.push_back(x.front()), check("one more element"), x.pop_back();
    vary_each_field(x.front(), scene, base, where + "[0]", changes);
  } else if constexpr (requires { std::tuple_size<T>::value; }) {  // a std::array
    for (std::size_t i = 0; i < x.size(); ++i)
      vary_each_field(x[i], scene, base, where + "[" + std::to_string(i) + "]", changes);
  } else {
    int k = 0;
    std::apply(
        [&](auto&... f) {
          (vary_each_field(f, scene, base, where + "." + std::to_string(k++), changes), ...);
        },
        raster::fields(x));
  }
}

TEST(SceneKey, ChangingAnyFieldOfAnyStructChangesTheCanonicalBytes) {
  Scene scene = one_of_everything();
  const std::string base = canonical(scene);
  int changes = 0;
  vary_each_field(scene, scene, base, "scene", changes);
  EXPECT_EQ(canonical(scene), base) << "every change was put back";
  // The fields of Scene, Primitive, Mesh, Camera, Light, Texture, Edges and Material, each vector's extra
  // element, and the numbers inside points, colours, matrices and index arrays: 146 changes as the structs
  // stand (136 before materials, 137 while "antialias" was two fields, samples and area), and a shader
  // primitive's.
  EXPECT_GE(changes, 180);
}

TEST(SceneKey, AVectorsLengthIsPartOfItsBytes) {
  // [a][bc] and [ab][c]: the same colours split differently between two vectors that lie side by side in
  // the bytes (Mesh::colors, then Mesh::face_colors), so only their lengths tell the scenes apart.
  Scene a = one_of_everything(), b = a;
  const raster::Rgba8 c1{1, 2, 3, 4}, c2{5, 6, 7, 8}, c3{9, 10, 11, 12};
  a.meshes[0].colors = {c1};
  a.meshes[0].face_colors = {c2, c3};
  b.meshes[0].colors = {c1, c2};
  b.meshes[0].face_colors = {c3};
  EXPECT_NE(canonical(a), canonical(b));
}

}  // namespace
