// ShaderToy's frame around a program: the text before and after a "shader" primitive's source, so that a
// program written for ShaderToy (a `mainImage(out vec4, in vec2)` and its uniforms) is a whole GLSL ES 3.00
// fragment shader. rasterd's compiler, the llvmpipe peer (bench/) and the glslang oracle (tests/) all
// compile exactly prelude + source + epilogue, so they judge the same text.
#pragma once

#include <string>
#include <string_view>

namespace raster::shader {

/// Before the program: the version, highp defaults (ShaderToy's WebGL 2 header has the same) and the
/// uniforms ShaderToy declares. `#line 1 1` makes the program's first line line 1 of source string 1, so
/// every message about the program names the program's own lines (string 0 is this text, 2 the epilogue).
inline constexpr std::string_view kShaderToyPrelude =
    "#version 300 es\n"
    "precision highp float;\n"
    "precision highp int;\n"
    "precision highp sampler2D;\n"
    "uniform vec3 iResolution;\n"
    "uniform float iTime;\n"
    "uniform float iTimeDelta;\n"
    "uniform float iFrameRate;\n"
    "uniform int iFrame;\n"
    "uniform float iChannelTime[4];\n"
    "uniform vec3 iChannelResolution[4];\n"
    "uniform vec4 iMouse;\n"
    "uniform vec4 iDate;\n"
    "uniform float iSampleRate;\n"
    "uniform sampler2D iChannel0;\n"
    "uniform sampler2D iChannel1;\n"
    "uniform sampler2D iChannel2;\n"
    "uniform sampler2D iChannel3;\n"
    "#line 1 1\n";

/// After the program: the fragment shader's entry point. The colour starts at zero (an `out` parameter is
/// undefined in GLSL; zero here makes every implementation agree) and is written as the program left it.
inline constexpr std::string_view kShaderToyEpilogue =
    "\n#line 1 2\n"
    "out vec4 rasterd_FragColor;\n"
    "void main() {\n"
    "  vec4 rasterd_color = vec4(0.0);\n"
    "  mainImage(rasterd_color, gl_FragCoord.xy);\n"
    "  rasterd_FragColor = rasterd_color;\n"
    "}\n";

/// Source string numbers of the three parts (the second number of their `#line`).
inline constexpr int kPreludeString = 0, kProgramString = 1, kEpilogueString = 2;

/// The whole fragment shader of a ShaderToy program.
inline std::string shadertoy_fragment_shader(std::string_view program) {
  std::string text;
  text.reserve(kShaderToyPrelude.size() + program.size() + kShaderToyEpilogue.size());
  text.append(kShaderToyPrelude).append(program).append(kShaderToyEpilogue);
  return text;
}

}  // namespace raster::shader
