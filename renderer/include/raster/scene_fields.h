// Every field of the Scene's structs, in a fixed order, for code that must see each one of them: the scene's
// canonical bytes (the service's ETag hashes them) and the test that changing any field changes those bytes.
//
// The list is checked against the structs: each static_assert below counts a struct's fields (as aggregate
// initialisation sees them, not its size), so a field added to scene.h and not listed here fails the build,
// even a flag that fits into padding and leaves sizeof unchanged.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "raster/scene.h"

namespace raster {

/// The fields of `s` (const or not) as a tuple of references, in declaration order.
template <class T>
constexpr auto fields(T& s) {
  using U = std::remove_const_t<T>;
  if constexpr (std::is_same_v<U, Rgba8>)
    return std::tie(s.r, s.g, s.b, s.a);
  else if constexpr (std::is_same_v<U, Point2>)
    return std::tie(s.x, s.y);
  else if constexpr (std::is_same_v<U, Vec3> || std::is_same_v<U, Vec3f>)
    return std::tie(s.x, s.y, s.z);
  else if constexpr (std::is_same_v<U, Mat4>)
    return std::tie(s.m);
  else if constexpr (std::is_same_v<U, Texture>)
    return std::tie(s.width, s.height, s.rgba, s.clamp, s.scale, s.offset, s.name);
  else if constexpr (std::is_same_v<U, Edges>)
    return std::tie(s.enabled, s.color, s.width, s.crease_deg);
  else if constexpr (std::is_same_v<U, Material>)
    return std::tie(s.model, s.metallic, s.roughness, s.metallic_roughness_texture, s.specular, s.shininess);
  else if constexpr (std::is_same_v<U, Mesh>)
    return std::tie(s.positions, s.triangles, s.segments, s.points, s.point_size, s.normals,
                    s.normal_triangles, s.colors, s.face_colors, s.uvs, s.uv_triangles, s.textures,
                    s.face_textures, s.materials, s.face_materials, s.shading, s.crease_deg, s.cull,
                    s.wireframe, s.edges, s.transform);
  else if constexpr (std::is_same_v<U, Camera>)
    return std::tie(s.projection, s.view, s.fit, s.has_eye, s.has_target, s.has_near, s.has_far, s.has_height,
                    s.has_view, s.has_up, s.eye, s.target, s.up, s.fov_deg, s.near, s.far, s.height);
  else if constexpr (std::is_same_v<U, Light>)
    return std::tie(s.kind, s.camera_space, s.direction, s.position, s.color, s.intensity);
  else if constexpr (std::is_same_v<U, Primitive>)
    return std::tie(s.kind, s.per_vertex_color, s.fill, s.closed, s.first_point, s.point_count, s.first_color,
                    s.width, s.mesh);
  else if constexpr (std::is_same_v<U, ShaderPrimitive>)
    return std::tie(s.source, s.time, s.frame, s.mouse, s.date, s.channels, s.textures, s.uniforms, s.whole,
                    s.rect, s.opaque);
  else if constexpr (std::is_same_v<U, Scene>)
    return std::tie(s.width, s.height, s.background, s.primitives, s.points, s.colors, s.meshes, s.camera,
                    s.lights, s.antialias, s.shaders);
}

namespace fields_detail {

template <class T>
inline constexpr bool kListed = !std::is_void_v<decltype(fields(std::declval<T&>()))>;

// Converts to any field type, so T{AnyField{}, ...} tells how many fields initialise T.
struct AnyField {
  template <class T>
  operator T() const;
};
template <class T, class... A>
consteval std::size_t count() {
  if constexpr (requires { T{A{}..., AnyField{}}; })
    return count<T, A..., AnyField>();
  else
    return sizeof...(A);
}
template <class T>
consteval bool complete() {
  return std::tuple_size_v<decltype(fields(std::declval<T&>()))> == count<T>();
}
static_assert(complete<Rgba8>() && complete<Point2>() && complete<Vec3>() && complete<Mat4>() &&
                  complete<Texture>() && complete<Edges>() && complete<Material>() && complete<Mesh>() &&
                  complete<Camera>() && complete<Light>() && complete<Primitive>() && complete<Scene>() &&
                  complete<ShaderPrimitive>(),
              "a struct of scene.h has a field that raster::fields() does not list");
// Vec3f has constructors, so the count above cannot see its fields; it is three floats and nothing else.
static_assert(sizeof(Vec3f) == 3 * sizeof(float));

// Values whose bytes are their whole content: numbers, enums, and structs or arrays of them without padding.
template <class T>
consteval bool raw() {
  if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
    return true;
  } else if constexpr (requires {
                         std::tuple_size<T>::value;
                         typename T::value_type;
                       }) {  // std::array
    return raw<typename T::value_type>() &&
           sizeof(T) == std::tuple_size_v<T> * sizeof(typename T::value_type);
  } else if constexpr (kListed<T>) {
    using Fields = decltype(fields(std::declval<T&>()));
    return []<std::size_t... I>(std::index_sequence<I...>) {
      return (raw<std::remove_reference_t<std::tuple_element_t<I, Fields>>>() && ...) &&
             (sizeof(std::remove_reference_t<std::tuple_element_t<I, Fields>>) + ... + 0) == sizeof(T);
    }
    (std::make_index_sequence<std::tuple_size_v<Fields>>{});
  } else {
    return false;
  }
}

}  // namespace fields_detail

/// Writes `v` as canonical bytes through `out(const void*, std::size_t)`: each field in the order above,
/// numbers as their bytes, and every vector and string led by its length, so no two different values give the
/// same bytes ([a][bc] and [ab][c] differ). Padding is never written: a struct is written field by field
/// unless it has none.
/// Antialias is written as the two fields it replaced (the samples as an int, then whether it is area), so
/// that every scene keeps the ETag it had before they became one value; the shaders, added last, are
/// written only when there are some, for the same reason.
template <class T, class Out>
void write_canonical(const T& v, Out& out) {
  if constexpr (std::is_same_v<T, Antialias>) {
    const int samples = v == Antialias::automatic ? -1 : sample_count(v);  // "auto": a count of its own
    const bool area = v == Antialias::area;
    out(&samples, sizeof samples), out(&area, sizeof area);
  } else if constexpr (std::is_same_v<T, std::vector<ShaderPrimitive>>) {
    if (v.empty()) return;
    const std::uint64_t n = v.size();
    out(&n, sizeof n);
    for (const auto& e : v) write_canonical(e, out);
  } else if constexpr (requires {
                         v.first;
                         v.second;
                       }) {  // a pair
    write_canonical(v.first, out), write_canonical(v.second, out);
  } else if constexpr (fields_detail::raw<T>()) {
    out(&v, sizeof v);
  } else if constexpr (std::is_same_v<T, std::string>) {
    const std::uint64_t n = v.size();
    out(&n, sizeof n), out(v.data(), v.size());
  } else if constexpr (requires {
                         typename T::value_type;
                         v.size();
                       }) {  // a vector (or an array of vectors)
    const std::uint64_t n = v.size();
    out(&n, sizeof n);
    if constexpr (fields_detail::raw<typename T::value_type>()) {
      if (n) out(v.data(), n * sizeof(typename T::value_type));
    } else {
      for (const auto& e : v) write_canonical(e, out);
    }
  } else {
    std::apply([&](const auto&... f) { (write_canonical(f, out), ...); }, fields(v));
  }
}

}  // namespace raster
