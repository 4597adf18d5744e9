#include "etag.h"

#include <openssl/evp.h>

#include <array>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <type_traits>

namespace rasterd {
namespace {

// A new field in any of these must be hashed below; the sizes catch one that is not (update both).
static_assert(sizeof(raster::Point2) == 2 * sizeof(double), "Point2 is hashed as raw bytes: no padding");
static_assert(sizeof(raster::Vec3) == 3 * sizeof(double), "Vec3 is hashed as raw bytes: no padding");
static_assert(sizeof(raster::Rgba8) == 4, "Rgba8 is hashed as raw bytes");
static_assert(sizeof(raster::Primitive) == 24, "Primitive changed: hash its new field in scene_etag");
static_assert(sizeof(raster::Edges) == 16, "Edges changed: hash its new field in scene_etag");
static_assert(sizeof(raster::Mesh) == 11 * sizeof(std::vector<int>) + 8 + sizeof(raster::Edges) + sizeof(raster::Mat4),
              "Mesh changed: hash its new field in scene_etag");
static_assert(sizeof(raster::Texture) == 8 + sizeof(std::vector<int>) + 24 + sizeof(std::string),
              "Texture changed: hash its new field in scene_etag");
static_assert(sizeof(raster::Camera) == 16 + 3 * sizeof(raster::Vec3) + 4 * sizeof(double),
              "Camera changed: hash its new field in scene_etag");
static_assert(sizeof(raster::Light) == 8 + 3 * sizeof(raster::Vec3) + sizeof(double),
              "Light changed: hash its new field in scene_etag");
static_assert(sizeof(raster::Scene) ==
                  16 + 5 * sizeof(std::vector<int>) + sizeof(raster::Camera) + 8,
              "Scene changed: hash its new field in scene_etag");

// SHA-256 fed through a 64 KiB buffer: a scene is millions of small fields, and one EVP call per field
// would cost more than the hashing.
class Digest {
 public:
  Digest() : ctx_(EVP_MD_CTX_new(), EVP_MD_CTX_free) {
    if (!ctx_ || EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) != 1) throw std::bad_alloc();
  }
  void bytes(const void* data, std::size_t n) {
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy must not get
    if (used_ + n > buffer_.size()) {
      flush();
      if (n > buffer_.size()) {
        EVP_DigestUpdate(ctx_.get(), data, n);
        return;
      }
    }
    std::memcpy(buffer_.data() + used_, data, n);
    used_ += n;
  }
  template <class T>
  requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  void value(T v) { bytes(&v, sizeof v); }
  // Raw elements of a vector of padding-free structs, preceded by the count, so that [a][bc] != [ab][c].
  template <class T>
  void vector(const std::vector<T>& v) {
    value(static_cast<std::uint64_t>(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
  void vec3(const raster::Vec3& v) { bytes(&v, sizeof v); }
  std::array<unsigned char, 32> finish() {
    flush();
    std::array<unsigned char, 32> out{};
    unsigned int n = 0;
    EVP_DigestFinal_ex(ctx_.get(), out.data(), &n);
    return out;
  }

 private:
  void flush() {
    if (used_) EVP_DigestUpdate(ctx_.get(), buffer_.data(), used_);
    used_ = 0;
  }
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx_;
  std::array<unsigned char, 1 << 16> buffer_;
  std::size_t used_ = 0;
};

}  // namespace

std::string scene_etag(const raster::Scene& scene, int render_version) {
  Digest d;
  // The render version, not the release: a tag names bytes, and only a change of render changes them.
  const std::string version = "rasterd render " + std::to_string(render_version);
  d.bytes(version.data(), version.size() + 1);  // with its NUL, so it cannot run into the scene's bytes
  d.value(scene.width), d.value(scene.height), d.value(scene.samples), d.value(scene.area);
  d.bytes(&scene.background, sizeof scene.background);
  // Primitives field by field: bools and a float share the struct, and only the fields are defined bytes.
  d.value(static_cast<std::uint64_t>(scene.primitives.size()));
  for (const raster::Primitive& p : scene.primitives) {
    d.value(p.kind), d.value(p.per_vertex_color), d.value(p.fill), d.value(p.closed);
    d.value(p.first_point), d.value(p.point_count), d.value(p.first_color), d.value(p.width), d.value(p.mesh);
  }
  d.vector(scene.points);
  d.vector(scene.colors);
  d.value(static_cast<std::uint64_t>(scene.meshes.size()));
  for (const raster::Mesh& m : scene.meshes) {
    d.vector(m.positions), d.vector(m.triangles), d.vector(m.segments), d.vector(m.normals);
    d.vector(m.normal_triangles), d.vector(m.colors), d.vector(m.face_colors);
    d.vector(m.uvs), d.vector(m.uv_triangles), d.vector(m.face_textures);
    d.value(static_cast<std::uint64_t>(m.textures.size()));
    for (const raster::Texture& t : m.textures) {  // the name does not change a pixel: not hashed
      d.value(t.width), d.value(t.height), d.vector(t.rgba), d.value(t.clamp);
      d.value(t.scale[0]), d.value(t.scale[1]), d.value(t.offset[0]), d.value(t.offset[1]);
    }
    d.value(m.shading), d.value(m.cull), d.value(m.wireframe);
    d.value(m.edges.enabled), d.value(m.edges.color.r), d.value(m.edges.color.g), d.value(m.edges.color.b);
    d.value(m.edges.color.a), d.value(m.edges.width), d.value(m.edges.crease_deg);
    for (double x : m.transform.m) d.value(x);
  }
  const raster::Camera& c = scene.camera;
  d.value(c.projection), d.value(c.has_eye), d.value(c.has_target), d.value(c.has_near), d.value(c.has_far);
  d.value(c.has_height), d.value(c.view), d.value(c.has_view), d.value(c.has_up);
  d.vec3(c.eye), d.vec3(c.target), d.vec3(c.up);
  d.value(c.fov_deg), d.value(c.near), d.value(c.far), d.value(c.height);
  d.value(static_cast<std::uint64_t>(scene.lights.size()));
  for (const raster::Light& l : scene.lights) {
    d.value(l.kind), d.value(l.camera_space), d.vec3(l.direction), d.vec3(l.position), d.vec3(l.color);
    d.value(l.intensity);
  }

  const auto hash = d.finish();
  static const char* hex = "0123456789abcdef";
  std::string tag = "\"";
  for (std::size_t i = 0; i < 16; ++i) tag += hex[hash[i] >> 4], tag += hex[hash[i] & 15];
  return tag + "\"";
}

bool none_match_hits(std::string_view field, std::string_view etag) {
  // A list of entity tags separated by commas and optional whitespace; W/ marks a weak one, and weak
  // comparison ignores it. A comma cannot appear inside an entity tag's quotes (etagc excludes it).
  const std::string_view opaque = etag;
  std::size_t at = 0;
  while (at < field.size()) {
    std::size_t end = field.find(',', at);
    if (end == std::string_view::npos) end = field.size();
    std::string_view item = field.substr(at, end - at);
    while (!item.empty() && (item.front() == ' ' || item.front() == '\t')) item.remove_prefix(1);
    while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) item.remove_suffix(1);
    if (item == "*") return true;
    if (item.starts_with("W/")) item.remove_prefix(2);
    if (item == opaque) return true;
    at = end + 1;
  }
  return false;
}

}  // namespace rasterd
