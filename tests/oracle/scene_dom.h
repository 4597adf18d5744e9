// The test oracle: rasterd 0.2's scene reader, which builds nlohmann's document tree and walks it. It is
// kept, unchanged in what it accepts, only to check the library's streaming reader against: both must
// accept the same documents and read them into equal scenes (tests/scene_reader_test.cpp and
// fuzz/scene_fuzzer.cpp). It is not linked into the library or the server. It has learnt one primitive
// since, the shader (issue 61: read_shader, written from the README's field table, not from the streaming
// reader), so that the two readers are compared on it too.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "raster/scene.h"

namespace raster::scene_json {

using nlohmann::json;

// A JSON pointer that is spelled out only when an error needs it: a chain of parent links on the stack,
// so reading a million points builds no strings. Keys must outlive the Path (they always do: literals,
// or a key of the document being read).
class Path {
 public:
  Path() = default;  // the document root, pointer ""
  Path(const Path& parent, const char* key) : parent_(&parent), key_(key) {}
  Path(const Path& parent, const std::string& key) : parent_(&parent), key_(key.c_str()) {}
  Path(const Path& parent, std::size_t index) : parent_(&parent), index_(index) {}

  // RFC 6901: '~' and '/' inside a key are escaped.
  std::string str() const;

 private:
  const Path* parent_ = nullptr;
  const char* key_ = nullptr;
  std::size_t index_ = 0;
};

inline const Path kRoot;

/// The default colour of meshes and models: light grey.
inline constexpr Rgba8 kMeshGrey{204, 204, 204, 255};

/// "#rgb", "#rgba", "#rrggbb" or "#rrggbbaa"; false for anything else.
bool parse_hex_color(std::string_view s, Rgba8& out);

/// Parses JSON text (a document or one value of it) with nesting cut at `max_depth`; SceneError(syntax)
/// with a byte offset into `text` otherwise.
json parse_document(std::string_view text, int max_depth);

/// Everything of the root object except "primitives": size, background, antialias, camera, light, and
/// the check that no unknown field is present.
void read_scene_fields(const json& root, Scene& scene, const Limits& limits);

/// One entry of "primitives", appended to the scene.
void read_primitive(const json& v, const Path& pointer, Scene& scene, const Limits& limits,
                    const Uploads& uploads);

/// "fill", "closed" and "width" of a triangle, line or polyline (absent fields keep their defaults).
void read_line_options(const json& v, const Path& pointer, Primitive& p);

/// "color" / "colors" of a primitive with n points, appended to `out`; true when one per point.
bool read_colors(const json& v, const Path& pointer, std::size_t n, Rgba8 fallback, std::vector<Rgba8>& out);

/// "shading", "cull", "wireframe" and "transform" of a mesh or model.
void read_mesh_options(const json& v, const Path& pointer, Mesh& mesh);

/// Appends a triangle, line or polyline whose fields are read and checked: `coords` holds dims (2: image
/// space; 3: world space, drawn as an unlit mesh) numbers per point, `colors` one flat colour or one per
/// point.
void add_drawn_primitive(Scene& scene, Primitive p, std::size_t dims, std::span<const double> coords,
                         std::span<const Rgba8> colors, bool per_vertex);

/// The DOM reader: every document, every error.
Scene parse_scene_dom(std::string_view text, const Limits& limits, const Uploads& uploads);

/// The oracle's parse_scene: UTF-8 first, then the DOM reader, then validate(), as the library's
/// parse_scene did before the one streaming reader (renderer/src/scene/scene_reader.cpp) replaced it.
Scene parse_scene_oracle(std::string_view text, const Limits& limits = {}, const Uploads& uploads = {});

}  // namespace raster::scene_json
