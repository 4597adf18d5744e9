// Models in the formats people bring: OBJ, STL (ASCII and binary), PLY (ASCII, binary little and big
// endian), glTF 2.0 (.gltf and .glb) and 3MF. Each reader turns bytes into a Mesh and never reads a file: the
// files a model names (an OBJ's MTL and textures, a glTF's buffers and images) come from `files`, by name.
// Which format a model is in, and what each format is called, is decided by one table (model_formats()).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "raster/scene.h"

namespace raster {

enum class ModelFormat : std::uint8_t { obj, stl, ply, gltf, glb, threemf };

/// Everything rasterd knows about one model format, in one row, so that the service (its media types and
/// ?format=), the CLI (a file's extension and the files beside it) and the scene reader (a model
/// primitive's "format") decide alike, and a format is added in one place.
struct ModelFormatInfo {
  ModelFormat format;  ///< the format this row describes
  /// As the scene's "format" and ?format= take it: "obj", "stl", "ply", "gltf", "glb", "3mf".
  std::string_view name;
  std::span<const std::string_view> extensions;   ///< file name extensions naming it: lower case, no dot
  std::span<const std::string_view> media_types;  ///< Content-Types naming it: lower case, no parameters
  /// True when `bytes` are in this format by their own look (see sniff_model for each test).
  bool (*sniff)(std::string_view bytes);
  /// Reads the model: `files` holds the files it names, by file name; `mtl_text` is an OBJ's materials
  /// (as parse_obj takes them; the other formats ignore it).
  Mesh (*read)(std::string_view bytes, const Limits& limits, const Uploads& files, std::string_view mtl_text);
  /// The files the model names (obj_files, gltf_files), for a program that has its folder at hand; null
  /// for a format that names none (STL, PLY, 3MF).
  std::vector<std::string> (*files)(std::string_view bytes, std::string_view mtl_text, const Uploads& files);
  /// How many times `files` is asked, each time with the files found before: OBJ 2 (the libraries its
  /// mtllib lines name, then the textures those name), glTF 1, STL, PLY and 3MF 0.
  int file_rounds;
  /// The world direction the format's files take as up by their own convention, which a bare model's
  /// picture stands on (see model_scene): glTF's specification says +Y; OBJ (Wavefront, Maya and Blender's
  /// exporters) and PLY (the Stanford scans, the bunny among them) are +Y in practice; STL, the format of
  /// CAD and 3D printing, is +Z, as slicers and CAD programs place a part on the build plate; 3MF too (its
  /// specification's build platform is the XY plane, +Z up).
  Vec3 up;
};

/// The table, one row per ModelFormat, in the enum's order.
std::span<const ModelFormatInfo> model_formats();
inline constexpr std::size_t kModelFormatCount = 6;  ///< rows of model_formats()
/// The row of `format`.
const ModelFormatInfo& model_format(ModelFormat format);
/// The rows' names, in the table's order ("obj", "stl", "ply", "gltf", "glb", "3mf"): what a scene's "format"
/// may be, in the order its error lists them.
const std::array<std::string_view, kModelFormatCount>& format_names();

/// The format's name as the scene's "format" and the service's ?format= take it: "obj", "stl",
/// "ply", "gltf", "glb", "3mf".
std::string_view format_name(ModelFormat format);
/// The inverse of format_name (ASCII case ignored); nullopt for any other word.
std::optional<ModelFormat> format_named(std::string_view name);
/// "OBJ, STL (ASCII or binary), PLY (ASCII or binary), glTF 2.0 (.gltf or .glb) and 3MF": for errors.
std::string_view accepted_formats();

/// The UTF-8 byte order mark some editors (Windows') put before text: sniff_model passes over it before a
/// glTF document or an OBJ's first statement, and the service and the CLI read it as whitespace.
inline constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
/// `text` after its byte order mark, when it starts with one.
constexpr std::string_view without_bom(std::string_view text) {
  return text.starts_with(kUtf8Bom) ? text.substr(kUtf8Bom.size()) : text;
}

/// True when `word` is a statement of OBJ 3.0 (geometry, grouping, display and free-form: "v", "vt", "f",
/// "usemtl", "curv2", ...), what an OBJ line that is not a comment starts with; case matters.
bool is_obj_statement(std::string_view word);

/// The format `bytes` are in, by the bytes alone, or nullopt when they are in none. The tests are tried
/// from the most particular to the loosest (glb, 3mf, ply, stl, gltf, obj):
/// - glb: the magic "glTF" and version 2;
/// - 3mf: a ZIP archive's magic "PK\3\4";
/// - ply: "ply" and a line break;
/// - stl: "solid" followed by "facet" or "endsolid" (ASCII), else a size of exactly 84 + 50 x the count
///   the header gives (binary; some binary files start with "solid" too);
/// - gltf: a JSON object whose first key is a glTF top-level property ("asset", "scene", "nodes", ...);
///   only that key is read, so a scene document of any size is told apart at once;
/// - obj: text whose first statement (after blank lines and '#' comments) is an OBJ keyword
///   (is_obj_statement); a file of nothing but comments too, which parse_obj then calls empty.
std::optional<ModelFormat> sniff_model(std::string_view bytes);

/// The format a file name's extension names (.obj, .stl, .ply, .gltf, .glb, .3mf; ASCII case ignored), or
/// nullopt.
std::optional<ModelFormat> format_of_file_name(std::string_view file_name);

/// The format a media type names (model/stl, model/gltf-binary, model/gltf+json, model/obj,
/// application/sla, model/ply, ...; a Content-Type's parameters after ';' and ASCII case ignored), or
/// nullopt.
std::optional<ModelFormat> format_of_media_type(std::string_view media_type);

/// What a model may build is bounded by the bytes sent (the model and the files it names, together): at most
/// kModelBuiltPerByte vertices and as many faces (triangles and line segments) per byte, or kModelBuiltFloor
/// of each whatever the size, so that tiny valid files always read. A glTF's nodes may draw one mesh many
/// times (instancing): without this bound a few megabytes of nodes naming one large mesh reach the vertex
/// limit (~1.5 GB while parsing); the count is made from the document before anything is built, and over it
/// is SceneError(limit). The other formats are already within it by their syntax, so they are not counted:
/// an OBJ vertex is a `v` line (>= 8 bytes) and each triangle of a face one more corner (>= 2 bytes); a PLY
/// vertex has three properties (>= 3 bytes) and each triangle of a face one more index (>= 1 byte); an STL
/// facet is 50 bytes (binary) or more (ASCII). Core glTF data is within it too (a position is 12 bytes, a
/// triangle of a strip of byte indices 1 byte): only a mesh drawn again and again goes over it.
inline constexpr std::uint64_t kModelBuiltPerByte = 1;
inline constexpr std::uint64_t kModelBuiltFloor = std::uint64_t{1} << 20;

/// Parses an OBJ model (and optional MTL text) into a mesh. Throws SceneError(model) naming the line.
/// `files` are the uploaded files by file name (a name differing only in case is accepted); nothing is
/// ever read from disk. Without `mtl_text`, the materials are the files the model's `mtllib` lines name,
/// found there by file name without folders (left out if not sent). Textures the MTL names (map_Kd) are
/// looked up there the same way (a missing one is SceneError(model) naming it and the names there are);
/// `limits.max_texture_pixels` bounds them all together. Faces of more than three corners are split as
/// parse_ply splits them: quads on their shorter diagonal, larger polygons by ear clipping in their plane.
/// A material's Kd colours its faces; its Ks above 0 (with Ns) makes a Blinn-Phong Mesh::materials entry.
Mesh parse_obj(std::string_view obj_text, std::string_view mtl_text = {}, const Limits& limits = {},
               const Uploads& files = {});

/// The files an OBJ model names, as parse_obj looks for them (file names without folders, each once, in the
/// order named): the libraries of its `mtllib` lines (a line's whole text as one name, and each word of it),
/// and the textures (map_Kd) of the materials in `mtl_text` or, without it, in those libraries as `files`
/// holds them. For a program that has the model's folder at hand (the CLI) to gather them as uploads, in two
/// rounds: libraries first, then the textures they name. Never throws for a bad MTL: parse_obj reports it.
std::vector<std::string> obj_files(std::string_view obj_text, std::string_view mtl_text = {},
                                   const Uploads& files = {});

/// STL, ASCII or binary (told apart as sniff_model does). Each facet is a triangle; its corners, which STL
/// writes out in full for every facet, are welded into shared vertices as they are read (exactly equal
/// positions, 0 and -0 alike, are one vertex, numbered in the order first seen; the pixels are those of the
/// facets apart). Shading is flat, from each facet's plane: the stored facet normals are not read,
/// as writers often leave them zero or stale, and one that disagreed with the corners' order would light
/// the face from behind. The solid's name and the attribute bytes are ignored. The binary triangle count is
/// checked against the size before anything is allocated; `limits.max_model_faces` bounds the facets.
/// Throws SceneError(model) naming the line (ASCII) or byte (binary), SceneError(limit) over the limit.
Mesh parse_stl(std::string_view bytes, const Limits& limits = {});

/// PLY 1.0, ASCII or binary of either byte order: the "vertex" element's x, y, z, optional normals
/// (nx, ny, nz) and colours (red, green, blue and alpha: uchar 0..255, ushort 0..65535 or float 0..1), and
/// the "face" element's index list ("vertex_indices" or "vertex_index", any list and index types). Faces of
/// more than three corners are triangulated as OBJ faces are (quads on their shorter diagonal, as
/// tinyobjloader splits them; larger polygons by ear clipping in their own plane, exact for any simple
/// polygon, convex or not; the face element may come before the vertex element). Other elements and
/// properties are skipped. Every element count and list length is checked against the bytes left before
/// anything is allocated; `limits.max_model_faces` bounds the triangles.
Mesh parse_ply(std::string_view bytes, const Limits& limits = {});

/// glTF 2.0 through tinygltf: a .gltf document (buffers and images as data: URIs, or as `files` named by
/// their URI's file name) or a .glb. Every mesh of the default scene (or the first) is drawn under its
/// node's transform; triangles, strips and fans, lines, line strips and loops; indices of every component
/// type; POSITION, NORMAL (a primitive without normals is flat, as glTF says: face normals beside others'
/// given ones, Shading::flat when none has any), COLOR_0, TEXCOORD_n; a material's baseColorFactor and
/// baseColorTexture with its alphaMode (OPAQUE: texel alpha 255; MASK: 255 or 0 at alphaCutoff, and
/// the renderer draws a texel of alpha 0 as a hole: neither colour nor depth; BLEND: kept),
/// metallicFactor, roughnessFactor and metallicRoughnessTexture (Mesh::materials, metallic_roughness; a
/// material that gives none of the three stays Lambert), and KHR_materials_unlit (the mesh is unlit when
/// all its materials are). Every accessor is checked to lie within its buffer view and buffer before it is
/// read; what tinygltf would build from the document is bounded before it runs, and so are the primitives
/// drawn (nodes x their meshes' primitives) and the vertices and faces they build (kModelBuiltPerByte).
/// Nothing is read from disk or the network.
Mesh parse_gltf(std::string_view bytes, const Limits& limits = {}, const Uploads& files = {});

/// The files a glTF document (or a GLB's JSON chunk) names: the URIs of its buffers and images that are not
/// data: URIs, as file names without folders, percent-decoded, each once. For a program that has the
/// model's folder at hand (the CLI) to gather them as uploads. Never throws: parse_gltf reports a bad model.
std::vector<std::string> gltf_files(std::string_view bytes);

/// 3MF (the 3D Manufacturing Format of slicers and CAD): the ZIP package's root model part, found through
/// _rels/.rels, and the parts it names. Every <build> item is placed with its transform, and every object's
/// <mesh> and <components> (with their transforms, nested up to 32 deep) within it, into one mesh in
/// millimetres (the model's `unit` converted); a transform of negative determinant has its triangles'
/// winding flipped back. Colours: a triangle's pid/p1 (or its object's pid/pindex) naming <basematerials>
/// (displaycolor) or the materials extension's <colorgroup> gives the face its colour (p1's: a triangle
/// whose corners differ is drawn in its first corner's). The production extension's p:path components are
/// read from the parts they name, as Bambu Studio, Orca and PrusaSlicer write them. A model whose
/// requiredextensions names one rasterd does not read (anything but core, materials and production) is
/// SceneError(model) naming it. Normals are computed, creased at kModelCreaseDeg. The ZIP's directory is
/// checked before anything is inflated: an entry's size beyond DEFLATE's 1032:1 or kZipMaxEntryBytes, or
/// refused by the budget, costs nothing; XML nesting is bounded, a DOCTYPE refused, and the vertices and
/// faces the build places are bounded as glTF's are (kModelBuiltPerByte, limits.max_model_faces). Errors
/// name the part and the XML line. Nothing is read from disk.
Mesh parse_3mf(std::string_view bytes, const Limits& limits = {});

/// The format parse_model reads `bytes` as: sniff_model(bytes), else `hint` (from a file name or the
/// request), else SceneError(model): the model is empty, or in no format rasterd reads.
ModelFormat model_format_of(std::string_view bytes, std::optional<ModelFormat> hint);
/// The same for bytes a caller has sniffed already: `sniffed` is what sniff_model(bytes) gave, so the bytes
/// are not read again.
ModelFormat model_format_of(std::string_view bytes, std::optional<ModelFormat> hint,
                            std::optional<ModelFormat> sniffed);

/// Any of the formats: model_format_of(bytes, hint), then that format's reader. OBJ takes `mtl_text` as
/// parse_obj does; OBJ and glTF find the files they name in `files`.
Mesh parse_model(std::string_view bytes, std::optional<ModelFormat> hint, const Limits& limits = {},
                 const Uploads& files = {}, std::string_view mtl_text = {});

/// The picture of a bare model (a model sent without a scene) where the request asks nothing else: the
/// service's and the CLI's default scene. Each value was chosen by measurement over a corpus of real models
/// (`make bench-accuracy`, bench/model_defaults.cpp; docs/accuracy.md gives the numbers): the background is
/// the grey that keeps the worst-shown model of the corpus most visible, the anti-aliasing the cheapest
/// level whose edges are smooth. A scene document keeps its own documented defaults.
struct ModelPicture {
  int width = 512, height = 512;           ///< pixels
  Rgba8 background{255, 255, 255, 255};    ///< straight RGBA, opaque: white
  Antialias antialias = Antialias::msaa4;  ///< 4 samples a pixel
};
inline constexpr ModelPicture kModelPicture{};

/// The scene a bare model is drawn in: kModelPicture's size, background and anti-aliasing, one mesh
/// primitive drawing `mesh`, and a thumbnailer's camera: the three-quarter view (View::three_quarter, from
/// the front-right and above) fitted to the model's vertices as projected (CameraFit::vertices: the longer
/// side fills 90% of the picture; a flat model is seen face on), standing on `format`'s up axis (the
/// camera's up is given only when that axis is not +Y).
Scene model_scene(Mesh mesh, ModelFormat format);

/// Decodes a PNG or JPEG texture to RGBA8. The size is read from the header and checked first: over
/// kMaxTextureSide a side, or over `texel_budget` texels, is SceneError(limit) before any pixel is decoded.
/// Anything else that is not a whole PNG or JPEG is SceneError(model). `name` is quoted in the errors.
Texture decode_texture(std::string_view bytes, std::string_view name, std::int64_t texel_budget);

}  // namespace raster
