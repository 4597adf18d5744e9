// The peer: the same seeded scenes drawn through Mesa's OSMesa (gallium llvmpipe: JIT-compiled SIMD,
// tiles, threads), timed from the first GL call to glFinish. Thread count comes from LP_NUM_THREADS,
// which llvmpipe reads once per process, so `make bench` runs this binary once per thread count.
// Prints: scene raster_ms (median), one line per scene. The 3D scenes are drawn with rasterd's own camera
// (the plan's world-to-clip matrix, its reversed depth turned into GL's), indexed vertex arrays, a depth
// test and the plan's lights (rasterd's default rig for these scenes), twice: "sphere" and "bunny" light
// every pixel in a GLSL fragment shader, the work rasterd does; "sphere-gouraud" and "bunny-gouraud"
// light every vertex through GL's fixed function. With OSMESA_PEER_PNG=dir each 3D picture is also written
// to dir/<scene>.png, to compare by eye with `rasterd render` of the same scene.
// `osmesa_peer runs --models file...` draws only the model files given, each as rasterd draws a bare model
// aliased on black (raster::model_scene: its camera and lights), lit per pixel: one "file-name milliseconds"
// line each (bench/models.cpp's llvmpipe column).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster/plan.h"
#include "raster/png.h"
#include "raster/scene_checks.h"
#include "scenes.h"
#include "timing.h"

namespace {

GLuint compile(GLenum type, const std::string& source) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    std::fprintf(stderr, "osmesa_peer: shader: %s\n", log);
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

// rasterd's per-pixel lighting (renderer/src/shade/light.h) as a GLSL program, its uniforms set from the
// plan's lights: the interpolated normal normalised and turned toward the viewer on back faces, the sum of
// each light's rgb x max(0, n . toward the light) (ambient: x 1), times the mesh colour. The light counts
// are compiled in, as a driver would specialise; the world position is interpolated only for point lights.
// Returns 0 (after saying why on stderr) when GLSL does not compile or link.
GLuint lit_program(std::span<const raster::LightPlan> lights, const float (&color)[4]) {
  float ambient[3] = {0, 0, 0};
  std::vector<float> dir_to, dir_rgb, point_at, point_rgb;
  for (const raster::LightPlan& l : lights) {
    const float rgb[3] = {static_cast<float>(l.rgb[0]), static_cast<float>(l.rgb[1]),
                          static_cast<float>(l.rgb[2])};
    if (l.kind == raster::LightKind::ambient) {
      for (int c = 0; c < 3; ++c) ambient[c] += rgb[c];
    } else if (l.kind == raster::LightKind::directional) {
      dir_to.insert(dir_to.end(), {static_cast<float>(l.to_light.x), static_cast<float>(l.to_light.y),
                                   static_cast<float>(l.to_light.z)});
      dir_rgb.insert(dir_rgb.end(), rgb, rgb + 3);
    } else {
      point_at.insert(point_at.end(), {static_cast<float>(l.position.x), static_cast<float>(l.position.y),
                                       static_cast<float>(l.position.z)});
      point_rgb.insert(point_rgb.end(), rgb, rgb + 3);
    }
  }
  const int dirs = static_cast<int>(dir_to.size() / 3), points = static_cast<int>(point_at.size() / 3);
  const std::string defines = "#version 120\n#define DIRS " + std::to_string(dirs) + "\n#define POINTS " +
                              std::to_string(points) + "\n";
  const GLuint vertex = compile(GL_VERTEX_SHADER, defines + R"(
varying vec3 normal;
#if POINTS > 0
varying vec3 world;
#endif
void main() {
  normal = gl_Normal;
#if POINTS > 0
  world = gl_Vertex.xyz;
#endif
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)");
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, defines + R"(
uniform vec4 color;
uniform vec3 ambient;
#if DIRS > 0
uniform vec3 dir_to[DIRS];
uniform vec3 dir_rgb[DIRS];
#endif
#if POINTS > 0
uniform vec3 point_at[POINTS];
uniform vec3 point_rgb[POINTS];
varying vec3 world;
#endif
varying vec3 normal;
void main() {
  // A degenerate interpolated normal gets the ambient light only, as in rasterd.
  float len = length(normal);
  vec3 n = len > 0.0 ? normal / len : vec3(0.0);
  if (!gl_FrontFacing) n = -n;
  vec3 light = ambient;
#if DIRS > 0
  for (int i = 0; i < DIRS; ++i) light += dir_rgb[i] * max(0.0, dot(n, dir_to[i]));
#endif
#if POINTS > 0
  for (int i = 0; i < POINTS; ++i) {
    vec3 d = point_at[i] - world;
    float dl = length(d);
    light += point_rgb[i] * (dl > 0.0 ? max(0.0, dot(n, d) / dl) : 1.0);
  }
#endif
  gl_FragColor = vec4(color.rgb * light, color.a);
}
)");
  if (!vertex || !fragment) return 0;
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    std::fprintf(stderr, "osmesa_peer: program: %s\n", log);
    glDeleteProgram(program);
    return 0;
  }
  glUseProgram(program);
  glUniform4fv(glGetUniformLocation(program, "color"), 1, color);
  glUniform3fv(glGetUniformLocation(program, "ambient"), 1, ambient);
  if (dirs) {
    glUniform3fv(glGetUniformLocation(program, "dir_to"), dirs, dir_to.data());
    glUniform3fv(glGetUniformLocation(program, "dir_rgb"), dirs, dir_rgb.data());
  }
  if (points) {
    glUniform3fv(glGetUniformLocation(program, "point_at"), points, point_at.data());
    glUniform3fv(glGetUniformLocation(program, "point_rgb"), points, point_rgb.data());
  }
  glUseProgram(0);
  return program;
}

// The plan's lights as GL's fixed-function ones, placed under an identity modelview so that their
// directions and positions stay world ones: the ambient ones summed into the model's ambient, each other
// one a GL light of that diffuse colour (no attenuation, as in rasterd). False, after saying why on
// stderr, for more lights than GL's eight.
bool fixed_function_lights(std::span<const raster::LightPlan> lights) {
  GLint max_lights = 8;
  glGetIntegerv(GL_MAX_LIGHTS, &max_lights);
  float ambient[4] = {0, 0, 0, 1};
  const float none[4] = {0, 0, 0, 1};
  int used = 0;
  for (const raster::LightPlan& l : lights) {
    if (l.kind == raster::LightKind::ambient) {
      for (int c = 0; c < 3; ++c) ambient[c] += static_cast<float>(l.rgb[c]);
      continue;
    }
    if (used == max_lights) {
      std::fprintf(stderr, "osmesa_peer: more lights than GL's %d\n", max_lights);
      return false;
    }
    const GLenum light = GL_LIGHT0 + static_cast<GLenum>(used++);
    const bool point = l.kind == raster::LightKind::point;
    const raster::Vec3& v = point ? l.position : l.to_light;
    const float where[4] = {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z),
                            point ? 1.0f : 0.0f};
    const float diffuse[4] = {static_cast<float>(l.rgb[0]), static_cast<float>(l.rgb[1]),
                              static_cast<float>(l.rgb[2]), 1};
    glLightfv(light, GL_AMBIENT, none);
    glLightfv(light, GL_DIFFUSE, diffuse);
    glLightfv(light, GL_SPECULAR, none);
    glLightfv(light, GL_POSITION, where);
    glEnable(light);
  }
  for (int i = used; i < max_lights; ++i) glDisable(GL_LIGHT0 + static_cast<GLenum>(i));
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  return true;
}

// With OSMESA_PEER_PNG set, the frame just drawn as OSMESA_PEER_PNG/<name>.png (GL's rows bottom first).
void write_debug_png(const std::string& name, int width, int height) {
  const char* dir = std::getenv("OSMESA_PEER_PNG");
  if (!dir || !*dir) return;
  raster::Image image;
  image.width = width, image.height = height, image.format = raster::PixelFormat::rgb8;
  image.pixels.resize(static_cast<std::size_t>(width) * height * 3);
  std::vector<std::uint8_t> rows(image.pixels.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y)
    std::copy_n(rows.data() + (height - 1 - y) * row, row, image.pixels.data() + y * row);
  const std::vector<std::uint8_t> png = raster::encode_png(image);
  const std::string path = std::string(dir) + "/" + name + ".png";
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(png.data(), 1, png.size(), f);
    std::fclose(f);
  }
}

// Draws `s`'s first mesh as rasterd's plan of `s` does (its camera matrix, its lights per pixel in GLSL),
// printing "name ms" (the median of `runs` draws, clear to glFinish); with `gouraud`, then the same lights
// per vertex through GL's fixed function, "name-gouraud ms". The framebuffer must hold s.width x s.height.
void draw_mesh(const raster::Scene& s, const std::string& name, int runs, bool gouraud) {
  const raster::RenderPlan plan = raster::plan(s);
  const raster::Mesh& m = s.meshes[0];
  // Area-weighted vertex normals (rasterd weighs by angle; the lighting work is the same).
  std::vector<float> xyz, normal(m.positions.size() * 3, 0.0f);
  for (const raster::Vec3f& p : m.positions) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  std::vector<GLuint> index;
  for (const auto& t : m.triangles) {
    const raster::Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
    const double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (int k = 0; k < 3; ++k) {
      index.push_back(t[k]);
      for (int d = 0; d < 3; ++d) normal[t[k] * 3 + d] += static_cast<float>(n[d]);
    }
  }
  // GL matrices are column-major; rasterd's clip z runs 0 (far) .. w (near), GL's -w (near) .. w (far).
  const raster::Mat4& mvp = plan.view.world_to_clip;
  double gl[16];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) gl[c * 4 + r] = r == 2 ? mvp(3, c) - 2 * mvp(2, c) : mvp(r, c);
  glViewport(0, 0, s.width, s.height);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(gl);
  // World space is eye space for GL: lights placed under this identity keep the plan's world vectors.
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glShadeModel(GL_SMOOTH);
  glDisableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, xyz.data());
  glNormalPointer(GL_FLOAT, 0, normal.data());
  const raster::Rgba8 col = m.colors.empty() ? raster::Rgba8{200, 200, 200, 255} : m.colors[0];
  const float color[4] = {col.r / 255.0f, col.g / 255.0f, col.b / 255.0f, col.a / 255.0f};
  auto draw = [&] {
    glClearColor(0, 0, 0, 1);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(index.size()), GL_UNSIGNED_INT, index.data());
    glFinish();
  };

  // Per pixel, what rasterd does: the plan's lights (rasterd's default rig) in a fragment shader.
  if (const GLuint program = lit_program(plan.view.lights, color)) {
    glUseProgram(program);
    std::printf("%s %.3f\n", name.c_str(), bench::median_ms(runs, draw));
    write_debug_png(name, s.width, s.height);
    glUseProgram(0);
    glDeleteProgram(program);
  }

  // Per vertex: the same lights through GL's fixed function (Gouraud), the cheaper work GL offers.
  if (gouraud && fixed_function_lights(plan.view.lights)) {
    const float ambient_and_diffuse[4] = {color[0], color[1], color[2], color[3]};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, ambient_and_diffuse);
    glEnable(GL_NORMALIZE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_LIGHTING);
    std::printf("%s-gouraud %.3f\n", name.c_str(), bench::median_ms(runs, draw));
    write_debug_png(name + "-gouraud", s.width, s.height);
    glDisable(GL_LIGHTING);
  }
  std::fflush(stdout);
  glDisableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
}

// A model file as rasterd draws a bare model (read as the service reads it: grey without colours of its
// own; raster::model_scene's camera and lights), aliased on black: the picture bench/models.cpp times
// rasterd's service drawing.
raster::Scene model_file_scene(const std::string& path) {
  bench::ModelFile file = bench::read_model_file(path);
  raster::Scene s = raster::model_scene(
      raster::checks::model_mesh(file.bytes, file.format, {}, file.files, {}, "", 0), file.format);
  s.antialias = raster::Antialias::none;
  s.background = {0, 0, 0, 255};
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 11;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx) {
    std::fprintf(stderr, "osmesa_peer: no OSMesa context\n");
    return 1;
  }
  std::vector<unsigned char> buffer(1024 * 1024 * 4);
  if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 1024, 1024)) return 1;
  if (argc > 2 && std::string(argv[2]) == "--models") {
    for (int i = 3; i < argc; ++i) {
      try {
        const raster::Scene s = model_file_scene(argv[i]);
        if (s.width > 1024 || s.height > 1024) throw std::runtime_error("larger than 1024x1024");
        const std::string path = argv[i];
        draw_mesh(s, path.substr(path.find_last_of('/') + 1), runs, false);  // by its file name
      } catch (const std::exception& e) {
        std::fprintf(stderr, "osmesa_peer: %s: %s\n", argv[i], e.what());
      }
    }
    OSMesaDestroyContext(ctx);
    return 0;
  }
  for (const char* kind : {"small", "large", "flat", "grid"}) {
    const raster::Scene s = bench::make_scene(kind, 1);
    // Vertex arrays of the same triangles: pixel coordinates, per-vertex colours (flat ones repeated).
    std::vector<float> xy;
    std::vector<unsigned char> rgba;
    for (const raster::Primitive& p : s.primitives)
      for (std::uint32_t k = 0; k < 3; ++k) {
        const raster::Point2& q = s.points[p.first_point + k];
        xy.push_back(static_cast<float>(q.x)), xy.push_back(static_cast<float>(q.y));
        const raster::Rgba8 c = s.colors[p.first_color + (p.per_vertex_color ? k : 0)];
        rgba.insert(rgba.end(), {c.r, c.g, c.b, c.a});
      }
    glViewport(0, 0, s.width, s.height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, s.width, s.height, 0, -1, 1);  // pixel coordinates, y down, like rasterd
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glShadeModel(GL_SMOOTH);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, xy.data());
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, rgba.data());
    std::vector<double> ms;
    for (int r = 0; r < runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      glClearColor(0, 0, 0, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(xy.size() / 2));
      glFinish();
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    std::printf("%s %.3f\n", kind, ms[ms.size() / 2]);
  }
  for (const char* kind : {"sphere", "bunny"}) {
    raster::Scene s;
    try {
      s = bench::mesh_scene(kind);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "osmesa_peer: %s\n", e.what());
      continue;
    }
    draw_mesh(s, kind, runs, true);
  }
  OSMesaDestroyContext(ctx);
}
