// What a render request means: a scene JSON, or a bare model (OBJ, STL, PLY, glTF, 3MF) with query
// parameters, plus uploads. Shared by the HTTP routes and the CLI so both accept exactly the same inputs.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "raster/model.h"
#include "raster/scene.h"

namespace rasterd {

/// Query parameters (HTTP) or --key=value options (CLI) that shape the default scene of a bare model:
/// width, height, background, projection, fov, eye, target, up (vectors as "x,y,z", or an axis), antialias,
/// point_size, and format (the model's, when its bytes do not tell it: obj, stl, ply, gltf, glb or 3mf).
using Params = std::map<std::string, std::string, std::less<>>;

/// A query parameter (HTTP) or option (CLI) that is wrong: unknown, or a value that is not what it takes.
/// A SceneError of kind invalid, so a caller that knows only those still reports it; the service answers
/// 400 `invalid-query` naming `parameter()`, apart from a scene that is invalid.
class QueryError : public raster::SceneError {
 public:
  QueryError(std::string parameter, const std::string& message)
      : raster::SceneError(raster::ErrorKind::invalid, message), parameter_(std::move(parameter)) {}
  const std::string& parameter() const { return parameter_; }

 private:
  std::string parameter_;
};

/// The cache-buster: `?v=` (any value) is reserved for the caller to change an image URL without changing
/// the picture (a new `v` is a new URL to every cache). It and the parameters that sharing tools append
/// (`utm_*`, `fbclid`, `gclid`, `msclkid`) are ignored, never an error.
bool ignored_param(std::string_view name);

/// The query parameters of a bare model's default scene ("scale" and "explain" aside): the CLI's model flags.
std::span<const std::string_view> model_param_names();

/// `?scale=` (device pixel ratio, for `srcset`): multiplies the image's width and height (rounded), every 2D
/// coordinate and every width in pixels; 3D content is framed by its camera and so just gets more pixels.
/// 0.25 to 8; 1 changes nothing. The result is held to the limits as a scene of that size would be.
inline constexpr double kMinScale = 0.25, kMaxScale = 8;
void apply_scale(raster::Scene& scene, double scale, const raster::Limits& limits);

/// The name an uploaded part is kept under in raster::Uploads. "scene", "model" and "mtl" keep their
/// names; any other part with a file name is kept under that file's name without folders, so a texture
/// sent as `curl -F texture=@head_diffuse.png` is found by the name the MTL uses ("head_diffuse.png").
/// Without a file name, a part keeps its own name.
std::string upload_key(std::string_view part_name, std::string_view file_name);

/// One uploaded part as it arrived: its part name and the key upload_key() gave it.
struct PartName {
  std::string part;  ///< the multipart part's name (`tex` in `-F tex=@maps/c.png`)
  std::string key;   ///< where its bytes are in raster::Uploads (`c.png`)
};

/// Makes each part findable by its part name too, as in rasterd 0.1, where a scene's `"source"` and
/// `"mtl_source"` name parts: `-F tex=@maps/c.png` is "c.png" for the MTL and "tex" for `{"source": "tex"}`.
/// A part name that two parts share, or that is already a key, names nothing more (which bytes were meant is
/// not knowable). Such a part's bytes are held twice, within the body limit.
void add_part_names(raster::Uploads& uploads, const std::vector<PartName>& parts);

/// True when a Content-Type names JSON (application/json, text/json, any "+json" type): the body is then a
/// scene whatever its first byte.
bool is_json_media_type(std::string_view content_type);

/// The model format a Content-Type names: the library's table of formats knows their media types.
using raster::format_of_media_type;

/// True when `body` is a scene by its bytes: the first byte after an optional UTF-8 byte order mark and
/// whitespace is '{' or '['; anything else is a model.
bool is_scene_text(std::string_view body);

/// What raster::sniff_model tells of a request's main bytes: the body, or the "model" part when the body is
/// empty (a multipart upload). A request is sniffed once, by the first step that must know (the CLI, to
/// gather a model's files; adopt_main_part, to place a part; else scene_from_request), and the answer is
/// handed on from there to the model's reading.
struct Sniffed {
  std::optional<raster::ModelFormat> format;  ///< nullopt: the bytes are in no format by their own look
};

/// The request made ready for the readers and sniffed: a UTF-8 byte order mark at the start of `body`
/// (Windows editors write one) blanked, as whitespace to the readers, so every byte offset in an error
/// still counts from the start of what was sent; then its main bytes (Sniffed) sniffed.
Sniffed sniff_request(std::string& body, const raster::Uploads& uploads);

/// The value of the "explain" parameter: absent or 0/false/no/off is false; 1/true/yes/on, or a bare
/// ?explain, is true. Anything else throws raster::SceneError naming the parameter.
bool explain_requested(const Params& params);

/// A multipart upload with neither a "scene" nor a "model" part (`curl -F file=@bunny.stl`): a lone part,
/// or else the one part whose file name ends in a model's extension (.obj, .stl, .ply, .gltf, .glb, .3mf) or
/// .json, becomes the body (a scene by its bytes) or the model, whose file name then goes to
/// `model_file_name` when given. The part is sniffed to tell (a glTF document is JSON too), and that is the
/// request's sniff: it goes to `sniffed` when given, for scene_from_request. Returns an error message naming
/// the parts when no single part qualifies; "" otherwise (also when there was nothing to choose).
std::string adopt_main_part(std::string& body, raster::Uploads& uploads, const std::vector<PartName>& parts,
                            std::string* model_file_name = nullptr,
                            std::optional<Sniffed>* sniffed = nullptr);

/// A scene when `declared_json` (the request's Content-Type says JSON) or is_scene_text(body), unless the
/// bytes are a glTF document; otherwise a model drawn with the default scene (512x512, camera framing the
/// model) adjusted by `params`. The model's format is told by its bytes, else by `named_format` (from the
/// file name of the part that carried it, or the Content-Type), else by ?format=. A scene
/// takes no parameter but "explain" and "scale": any other is refused, as an unknown one is for a model. A
/// UTF-8 byte order mark is read as whitespace. A body that looks like an OBJ whose line breaks were
/// stripped (curl -d) is refused with a hint. `sniffed`: the request's sniff when a caller has made it
/// (sniff_request, adopt_main_part); without it, sniff_request is asked here. Throws raster::SceneError.
/// Takes the body and uploads by value: callers move them in, so a large model is never copied.
raster::Scene scene_from_request(std::string body, raster::Uploads uploads, const Params& params,
                                 const raster::Limits& limits, bool declared_json = false,
                                 std::optional<raster::ModelFormat> named_format = std::nullopt,
                                 std::optional<Sniffed> sniffed = std::nullopt);

}  // namespace rasterd
