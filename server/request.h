// What a render request means: a scene JSON, or a bare OBJ model with query parameters, plus uploads.
// Shared by the HTTP routes and the CLI so both accept exactly the same inputs.
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "raster/scene.h"

namespace rasterd {

/// Query parameters (HTTP) or --key=value options (CLI) that shape the default scene of a bare model:
/// width, height, background, projection, fov, eye, target, up (vectors as "x,y,z").
using Params = std::map<std::string, std::string, std::less<>>;

/// The name an uploaded part is kept under in raster::Uploads. "scene", "model" and "mtl" keep their
/// names; any other part with a file name is kept under that file's name without folders, so a texture
/// sent as `curl -F texture=@head_diffuse.png` is found by the name the MTL uses ("head_diffuse.png").
/// Without a file name, a part keeps its own name.
std::string upload_key(std::string_view part_name, std::string_view file_name);

/// True when `body` is a scene (its first non-blank byte is '{'); else it is an OBJ model.
bool is_scene_text(std::string_view body);

/// `body` starting with '{' (after whitespace) is a scene; anything else is an OBJ model drawn with the
/// default scene (512x512, camera framing the model) adjusted by `params`. A body that looks like an OBJ
/// whose line breaks were stripped (curl -d) is refused with a hint. Throws raster::SceneError.
/// Takes the body and uploads by value: callers move them in, so a large model is never copied.
raster::Scene scene_from_request(std::string body, raster::Uploads uploads, const Params& params,
                                 const raster::Limits& limits);

}  // namespace rasterd
