// The llvmpipe peer for ShaderToy programs: renders one program (a `mainImage(out vec4, in vec2)` file)
// through Mesa's OSMesa (gallium llvmpipe) and prints one line of JSON: how long GL took to compile and link
// it, to draw the first frame (which includes llvmpipe's LLVM JIT of the fragment shader, done at the first
// draw) and to draw a frame afterwards (the fastest of --frames draws). Its pictures are what rasterd's own
// shader compiler and interpreter are compared against.
//
//   shader_peer program.glsl [--size WxH] [--frames N] [--time T] [--frame F] [--mouse x,y,z,w]
//               [--date y,m,d,s] [--channel0..3 image.png] [--png out.png] [--raw out.rgba]
//               [--source out.frag]
//
// GL compiles exactly raster::shader::shadertoy_fragment_shader(program) (renderer/src/shader/shadertoy.h),
// the text rasterd and the glslang oracle compile; --source writes that text. Every frame is drawn with the
// same uniforms, so every frame is the same picture: iResolution = (W, H, 1), iTime = T, iTimeDelta = 1/60,
// iFrameRate = 60, iFrame = F, iMouse, iDate (default 2026-12-03 00:00:00, ShaderToy's month counts from 0),
// iSampleRate = 44100, iChannelTime = 0, iChannelResolution[i] = (w, h, 1) of a bound channel, else 0.
//
// Thread count comes from LP_NUM_THREADS, which llvmpipe reads once per process, so `bench` runs this binary
// once per thread count. MESA_SHADER_CACHE_DISABLE is set before any GL call so that every run compiles and
// JITs afresh (the times are of a program never seen before, as rasterd's are).
//
// Exit status: 0, 1 for bad arguments, files or no GL context, 2 when the shader does not compile or link
// (GL's info log on stderr).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "shader/shadertoy.h"
#include "timing.h"

namespace {

struct Options {
  std::string program;  // path of the ShaderToy program
  int width = 512, height = 512;
  int frames = 5;  // frames timed after the first
  float time = 0;
  int frame = 0;
  std::array<float, 4> mouse{0, 0, 0, 0};
  std::array<float, 4> date{2026, 11, 3, 0};  // year, month - 1, day, seconds since midnight
  std::array<std::string, 4> channels;        // image files of iChannel0..3 ("" = none bound)
  std::string png, raw, source;               // outputs ("" = not written)
};

[[noreturn]] void fail(const std::string& message, int status = 1) {
  std::fprintf(stderr, "shader_peer: %s\n", message.c_str());
  std::exit(status);
}

[[noreturn]] void usage() {
  fail(
      "usage: shader_peer program.glsl [--size WxH] [--frames N] [--time T] [--frame F] [--mouse x,y,z,w] "
      "[--date y,m,d,s] [--channel0..3 image.png] [--png out.png] [--raw out.rgba] [--source out.frag]");
}

// Exactly `count` comma-separated floats, or exit.
template <std::size_t count>
std::array<float, count> parse_floats(const std::string& text, const char* what) {
  std::array<float, count> values{};
  std::istringstream in(text);
  for (std::size_t i = 0; i < count; ++i) {
    char comma = ',';
    if ((i > 0 && !(in >> comma)) || comma != ',' || !(in >> values[i])) fail(std::string("bad ") + what);
  }
  if (in >> std::ws; !in.eof()) fail(std::string("bad ") + what);
  return values;
}

int parse_int(const std::string& text, const char* what, int low, int high) {
  std::size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value < low || value > high) fail(std::string("bad ") + what);
  return value;
}

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0) {
      if (!o.program.empty()) usage();
      o.program = arg;
      continue;
    }
    if (i + 1 == argc) usage();
    const std::string value = argv[++i];
    if (arg == "--size") {
      const std::size_t x = value.find('x');
      if (x == std::string::npos) fail("bad --size (WxH)");
      o.width = parse_int(value.substr(0, x), "--size", 1, 16384);
      o.height = parse_int(value.substr(x + 1), "--size", 1, 16384);
    } else if (arg == "--frames") {
      o.frames = parse_int(value, "--frames", 1, 100000);
    } else if (arg == "--time") {
      o.time = parse_floats<1>(value, "--time")[0];
    } else if (arg == "--frame") {
      o.frame = parse_int(value, "--frame", 0, std::numeric_limits<int>::max());
    } else if (arg == "--mouse") {
      o.mouse = parse_floats<4>(value, "--mouse (x,y,z,w)");
    } else if (arg == "--date") {
      o.date = parse_floats<4>(value, "--date (y,m,d,s)");
    } else if (arg.size() == 10 && arg.rfind("--channel", 0) == 0 && arg[9] >= '0' && arg[9] <= '3') {
      o.channels[arg[9] - '0'] = value;
    } else if (arg == "--png") {
      o.png = value;
    } else if (arg == "--raw") {
      o.raw = value;
    } else if (arg == "--source") {
      o.source = value;
    } else {
      usage();
    }
  }
  if (o.program.empty()) usage();
  return o;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot read " + path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_file(const std::string& path, const void* bytes, std::size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || std::fwrite(bytes, 1, size, f) != size || std::fclose(f) != 0) fail("cannot write " + path);
}

// A GL 3.3 (or later) core context drawing into `pixels` (RGBA8, rows bottom first: OSMesa's default Y_UP).
// llvmpipe takes `#version 300 es` shaders there through ARB_ES3_compatibility. (Mesa 22.3's default OSMesa
// context, 4.5 compatibility, would take them too; core keeps fixed-function state out of the draw.)
OSMesaContext make_context(std::vector<unsigned char>& pixels, int width, int height) {
  const int attributes[][2] = {{OSMESA_FORMAT, OSMESA_RGBA},
                               {OSMESA_DEPTH_BITS, 0},
                               {OSMESA_STENCIL_BITS, 0},
                               {OSMESA_ACCUM_BITS, 0},
                               {OSMESA_PROFILE, OSMESA_CORE_PROFILE},
                               {OSMESA_CONTEXT_MAJOR_VERSION, 3},
                               {OSMESA_CONTEXT_MINOR_VERSION, 3},
                               {0, 0}};  // name, value pairs; 0 ends the list
  OSMesaContext context = OSMesaCreateContextAttribs(&attributes[0][0], nullptr);
  if (!context) fail("no OSMesa 3.3 core context");
  pixels.assign(static_cast<std::size_t>(width) * height * 4, 0);
  if (!OSMesaMakeCurrent(context, pixels.data(), GL_UNSIGNED_BYTE, width, height))
    fail("OSMesaMakeCurrent failed at " + std::to_string(width) + "x" + std::to_string(height));
  return context;
}

// The info log of a shader or program (`get_iv`/`get_log`: the shader or the program query functions).
template <typename GetIv, typename GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint length = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  get_log(object, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

// A compiled shader, or exit 2 with GL's info log.
GLuint compile(GLenum type, const std::string& source, const char* what) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  const GLint length = static_cast<GLint>(source.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok)
    fail(std::string(what) + " does not compile:\n" + info_log(shader, glGetShaderiv, glGetShaderInfoLog), 2);
  return shader;
}

// A linked program of the two shaders, or exit 2 with GL's info log.
GLuint link(GLuint vertex, GLuint fragment) {
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) fail("program does not link:\n" + info_log(program, glGetProgramiv, glGetProgramInfoLog), 2);
  return program;
}

// One triangle covering the viewport, from gl_VertexID alone (no vertex buffer): (-1,-1), (3,-1), (-1,3).
constexpr const char* kVertexShader =
    "#version 300 es\n"
    "void main() {\n"
    "  gl_Position = vec4(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1), 0.0, 1.0);\n"
    "}\n";

// The image at `path` as texture unit `unit` (GL_RGBA8: the bytes as stored, no sRGB decoding; mipmaps;
// trilinear, repeating). Rows go up bottom row first, so texture() at v = 0 reads the image's bottom row and
// a program drawing uv = fragCoord / iResolution shows the image upright: ShaderToy's default (its "vflip"
// sampler option is on unless a user turns it off). Returns the image's size.
std::array<int, 2> bind_channel(int unit, const std::string& path) {
  int width = 0, height = 0, channels = 0;
  stbi_set_flip_vertically_on_load(1);
  unsigned char* rgba = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (!rgba) fail("cannot read image " + path + ": " + stbi_failure_reason());
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  stbi_image_free(rgba);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  return {width, height};
}

// ShaderToy's uniforms, by name (a uniform the program does not use has no location and is skipped).
void set_uniforms(GLuint program, const Options& o, const std::array<std::array<int, 2>, 4>& channel_sizes) {
  auto at = [program](const char* name) { return glGetUniformLocation(program, name); };
  glUniform3f(at("iResolution"), static_cast<float>(o.width), static_cast<float>(o.height), 1.0f);
  glUniform1f(at("iTime"), o.time);
  glUniform1f(at("iTimeDelta"), 1.0f / 60.0f);
  glUniform1f(at("iFrameRate"), 60.0f);
  glUniform1i(at("iFrame"), o.frame);
  glUniform4fv(at("iMouse"), 1, o.mouse.data());
  glUniform4fv(at("iDate"), 1, o.date.data());
  glUniform1f(at("iSampleRate"), 44100.0f);
  const float channel_time[4] = {0, 0, 0, 0};
  glUniform1fv(at("iChannelTime"), 4, channel_time);
  float resolution[12] = {};
  for (int i = 0; i < 4; ++i) {
    if (channel_sizes[i][0] == 0) continue;
    resolution[i * 3] = static_cast<float>(channel_sizes[i][0]);
    resolution[i * 3 + 1] = static_cast<float>(channel_sizes[i][1]);
    resolution[i * 3 + 2] = 1.0f;
  }
  glUniform3fv(at("iChannelResolution"), 4, resolution);
  const char* samplers[4] = {"iChannel0", "iChannel1", "iChannel2", "iChannel3"};
  for (int i = 0; i < 4; ++i) glUniform1i(at(samplers[i]), i);
}

// One frame: the triangle drawn and finished; milliseconds from the draw call to glFinish's return.
double draw_frame() {
  const auto start = std::chrono::steady_clock::now();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glFinish();
  return bench::ms_since(start);
}

// The framebuffer's RGBA8 bytes, top row first (GL's rows are bottom first).
std::vector<unsigned char> read_top_down(int width, int height) {
  std::vector<unsigned char> bottom_up(static_cast<std::size_t>(width) * height * 4),
      top_down(bottom_up.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(bottom_up.data() + (height - 1 - y) * row, row, top_down.data() + y * row);
  return top_down;
}

// A JSON string literal of `text` (paths and GL's renderer name: quotes, backslashes, control bytes).
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\', out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
  // Before any GL call: Mesa opens its on-disk shader cache when the context's screen is made.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  const Options o = parse_options(argc, argv);
  const std::string fragment_text = raster::shader::shadertoy_fragment_shader(read_file(o.program));
  if (!o.source.empty()) write_file(o.source, fragment_text.data(), fragment_text.size());

  std::vector<unsigned char> pixels;
  OSMesaContext context = make_context(pixels, o.width, o.height);
  glViewport(0, 0, o.width, o.height);
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);  // a core context draws nothing without a bound vertex array object
  glBindVertexArray(vao);
  std::array<std::array<int, 2>, 4> channel_sizes{};
  for (int i = 0; i < 4; ++i)
    if (!o.channels[i].empty()) channel_sizes[i] = bind_channel(i, o.channels[i]);
  // The vertex shader is the frame, not the program: compiled before the clock starts.
  const GLuint vertex = compile(GL_VERTEX_SHADER, kVertexShader, "vertex shader");

  const auto start = std::chrono::steady_clock::now();
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_text, o.program.c_str());
  const GLuint program = link(vertex, fragment);
  const double compile_link_ms = bench::ms_since(start);

  glUseProgram(program);
  set_uniforms(program, o, channel_sizes);
  const double first_frame_ms = draw_frame();
  double frame_ms = std::numeric_limits<double>::infinity();
  for (int i = 0; i < o.frames; ++i) frame_ms = std::min(frame_ms, draw_frame());
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) fail("GL error " + std::to_string(error));

  if (!o.png.empty() || !o.raw.empty()) {
    const std::vector<unsigned char> rgba = read_top_down(o.width, o.height);
    if (!o.raw.empty()) write_file(o.raw, rgba.data(), rgba.size());
    if (!o.png.empty() && !stbi_write_png(o.png.c_str(), o.width, o.height, 4, rgba.data(), o.width * 4))
      fail("cannot write " + o.png);
  }

  const char* threads = std::getenv("LP_NUM_THREADS");
  std::printf(
      "{\"program\": %s, \"width\": %d, \"height\": %d, \"threads\": %s, \"renderer\": %s, "
      "\"compile_link_ms\": %.3f, \"first_frame_ms\": %.3f, \"frame_ms\": %.3f, \"frames\": %d}\n",
      json_string(o.program).c_str(), o.width, o.height, threads ? json_string(threads).c_str() : "null",
      json_string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))).c_str(), compile_link_ms,
      first_frame_ms, frame_ms, o.frames);
  OSMesaDestroyContext(context);
  return 0;
}
