// A bare ShaderToy program as a request (the CLI's `rasterd render program.glsl`): how it is told from a
// scene or a model, and the scene that draws it over a whole image, shaped by the options --width,
// --height, --time, --frame, --mouse and --antialias.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "raster/scene.h"
#include "request.h"

namespace rasterd {

/// A program's picture when no size is given: 512 x 288, ShaderToy's 16:9 at the width of a bare model's.
inline constexpr int kProgramWidth = 512, kProgramHeight = 288;

/// True for a ShaderToy program: a file named *.glsl, *.frag or *.fs (any case), or text that is not a scene
/// (is_scene_text) and holds "mainImage".
bool is_shader_program(std::string_view file_name, std::string_view text);

/// The options a bare program takes ("explain" aside): width, height, time, frame, mouse, antialias.
std::span<const std::string_view> program_param_names();

/// The scene of one shader primitive over a kProgramWidth x kProgramHeight image (or --width x --height),
/// its iTime, iFrame and iMouse from the options ("x,y" or "x,y,click x,click y"), black behind it. Each
/// value is checked with the scene reader's words for its field; an unknown or bad option throws
/// QueryError naming it. The program is compiled by the plan, as a scene's is.
raster::Scene program_scene(std::string source, const Params& params, const raster::Limits& limits);

}  // namespace rasterd
