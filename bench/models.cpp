// "Models by size" (issue 50): how rasterd's cost grows with a model, beside its peers. A closed,
// scan-like surface (a bumpy sphere: a UV sphere whose radius ripples by ±4%) of 125,000, 500,000 and
// 2,000,000 triangles, written by this program in each format people send it as (binary STL, OBJ, binary
// PLY, GLB), and for each file:
//   - parse: raster::parse_model of the bytes at 2 threads (the service's render threads), in this
//     program's hidden mode (`models --measure runs dir`); tinyobjloader 2.0's ParseFromString of the OBJ
//     beside it, the library rasterd's OBJ reader replaced;
//   - the service (`rasterd serve`, 2 render threads): the aliased picture on black (?antialias=1, what
//     llvmpipe draws) and the default picture (no query), Server-Timing's stages and the whole request;
//   - llvmpipe per pixel (bench/osmesa_peer --models, LP_NUM_THREADS=2) drawing the same mesh as rasterd's
//     aliased picture (its camera matrix and lights, per-pixel lighting in GLSL), from the PLY;
//   - peak resident memory of `rasterd render file -o /dev/null` (the CLI's default picture) and of f3d 1.3
//     writing its own default picture of the file at 512x512 (`f3d --output`, under an Xvfb this program
//     starts), each process's getrusage after wait4, with f3d's whole run time.
// Every time is the fastest of kProcesses processes (a service, an llvmpipe, a parse child, a CLI, an f3d
// per round, the rounds interleaved: the VM runs a whole process at one of two speeds), each process's time
// the median of its runs; memory is the median of the processes' peaks.
// Usage: models runs osmesa_peer rasterd image.png. Prints Markdown; writes the plot to image.png.
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "plot.h"
#include "raster/raster.h"
#include "scenes.h"
#include "timing.h"
#include "wall.h"

namespace {

namespace fs = std::filesystem;
constexpr int kProcesses = 3;

struct Size {
  int n;              ///< rings and segments: 2 n^2 triangles
  const char* label;  ///< as the tables name it
};
constexpr Size kSizes[] = {{250, "125k"}, {500, "500k"}, {1000, "2M"}};

struct Format {
  const char* extension;
  const char* name;
  const char* media_type;
};
constexpr Format kFormats[] = {{"stl", "binary STL", "model/stl"},
                               {"obj", "OBJ", "model/obj"},
                               {"ply", "binary PLY", "model/ply"},
                               {"glb", "GLB", "model/gltf-binary"}};

// The bumpy sphere: (n + 1) rings of n vertices from pole to pole (each pole ring n copies of one point, as
// a scan's grid would be), two triangles a quad, wound counter-clockwise seen from outside.
struct Surface {
  std::vector<raster::Vec3f> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

Surface bumpy_sphere(int n) {
  Surface s;
  s.positions.reserve(static_cast<std::size_t>(n + 1) * n);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i <= n; ++i) {
    const double t = pi * i / n;
    for (int j = 0; j < n; ++j) {
      const double p = 2 * pi * j / n;
      const double r = 1 + 0.03 * std::sin(7 * t) * std::cos(9 * p) + 0.01 * std::sin(31 * t + 3 * p);
      s.positions.push_back({static_cast<float>(r * std::sin(t) * std::cos(p)),
                             static_cast<float>(r * std::cos(t)),
                             static_cast<float>(r * std::sin(t) * std::sin(p))});
    }
  }
  s.triangles.reserve(2 * static_cast<std::size_t>(n) * n);
  const auto u = static_cast<std::uint32_t>(n);
  for (std::uint32_t i = 0; i < u; ++i)
    for (std::uint32_t j = 0; j < u; ++j) {
      const std::uint32_t a = i * u + j, b = i * u + (j + 1) % u, c = a + u, d = b + u;
      s.triangles.push_back({a, c, b});
      s.triangles.push_back({b, c, d});
    }
  return s;
}

template <typename T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);  // little-endian, as x86 holds it
}

std::string stl_of(const Surface& s) {
  std::string out(80, '\0');
  put(out, static_cast<std::uint32_t>(s.triangles.size()));
  out.reserve(out.size() + s.triangles.size() * 50);
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) put(out, 0.0f);  // the facet normal, which rasterd recomputes
    for (std::uint32_t v : t) put(out, s.positions[v]);
    put(out, std::uint16_t{0});
  }
  return out;
}

std::string obj_of(const Surface& s) {
  std::string out;
  out.reserve(s.positions.size() * 32 + s.triangles.size() * 24);
  char line[96];
  for (const raster::Vec3f& v : s.positions)
    out.append(line, static_cast<std::size_t>(
                         std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", v.x, v.y, v.z)));
  for (const auto& t : s.triangles)
    out.append(line, static_cast<std::size_t>(
                         std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1)));
  return out;
}

std::string ply_of(const Surface& s) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(s.positions.size()) +
      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
      std::to_string(s.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  out.reserve(out.size() + s.positions.size() * 12 + s.triangles.size() * 13);
  for (const raster::Vec3f& v : s.positions) put(out, v);
  for (const auto& t : s.triangles) {
    put(out, std::uint8_t{3});
    for (std::uint32_t v : t) put(out, static_cast<std::int32_t>(v));
  }
  return out;
}

std::string glb_of(const Surface& s) {
  raster::Vec3f lo = s.positions[0], hi = lo;
  for (const raster::Vec3f& v : s.positions) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  const std::size_t positions = s.positions.size() * 12, indices = s.triangles.size() * 12;
  char json[1024];
  std::snprintf(json, sizeof json,
                R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
                R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
                R"("accessors":[{"bufferView":0,"componentType":5126,"count":%zu,"type":"VEC3",)"
                R"("min":[%.9g,%.9g,%.9g],"max":[%.9g,%.9g,%.9g]},)"
                R"({"bufferView":1,"componentType":5125,"count":%zu,"type":"SCALAR"}],)"
                R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":%zu},)"
                R"({"buffer":0,"byteOffset":%zu,"byteLength":%zu}],"buffers":[{"byteLength":%zu}]})",
                s.positions.size(), lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, s.triangles.size() * 3, positions,
                positions, indices, positions + indices);
  std::string doc = json;
  doc.resize((doc.size() + 3) / 4 * 4, ' ');
  std::string out = "glTF";
  put(out, std::uint32_t{2});
  put(out, static_cast<std::uint32_t>(12 + 8 + doc.size() + 8 + positions + indices));
  put(out, static_cast<std::uint32_t>(doc.size()));
  out += "JSON" + doc;
  put(out, static_cast<std::uint32_t>(positions + indices));
  out.append("BIN\0", 4);
  for (const raster::Vec3f& v : s.positions) put(out, v);
  for (const auto& t : s.triangles)
    for (std::uint32_t v : t) put(out, v);
  return out;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string file_name(const Size& size, const Format& format) {
  return std::string("sphere-") + size.label + "." + format.extension;
}

// The hidden mode: one process's medians, "parse file ms" for every file, "tinyobj file ms" for the OBJs.
void measure(int runs, const std::string& dir) {
  for (const Size& size : kSizes)
    for (const Format& format : kFormats) {
      const std::string name = file_name(size, format), bytes = read_bytes(dir + "/" + name);
      const raster::ModelFormat f = raster::model_format_of(bytes, raster::format_of_file_name(name));
      raster::Limits limits;
      limits.threads = 2;
      std::printf("parse %s %.4f\n", name.c_str(),
                  bench::median_ms(runs, [&] { raster::Mesh m = raster::parse_model(bytes, f, limits); }));
      if (f == raster::ModelFormat::obj)
        std::printf("tinyobj %s %.4f\n", name.c_str(), bench::median_ms(std::max(3, runs / 3), [&] {
                      tinyobj::ObjReader reader;
                      tinyobj::ObjReaderConfig config;
                      config.triangulate = true;
                      config.vertex_color = false;
                      reader.ParseFromString(bytes, "", config);
                    }));
      std::fflush(stdout);
    }
}

struct Peak {
  double kib = 0, ms = 0;
  bool ok = false;
};

// Runs `args` with `display` as DISPLAY (when not empty), its output to /dev/null: its peak resident KiB
// and wall time.
Peak run_peak(const std::vector<std::string>& args, const std::string& display) {
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    if (!display.empty()) setenv("DISPLAY", display.c_str(), 1);
    if (std::FILE* null = std::fopen("/dev/null", "w")) dup2(fileno(null), 1), dup2(fileno(null), 2);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  Peak out;
  if (pid > 0 && wait4(pid, &status, 0, &usage) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0)
    out = {static_cast<double>(usage.ru_maxrss), bench::ms_since(t0), true};
  return out;
}

bool on_path(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

// An X display for f3d: Xvfb on the first free display number from 90, or 0 (and why on stderr).
pid_t start_xvfb(std::string& display) {
  if (!on_path("f3d") || !on_path("Xvfb")) {
    std::fprintf(stderr, "models: f3d or Xvfb not installed (scripts/install-deps bench): no f3d column\n");
    return 0;
  }
  for (int d = 90; d < 190; ++d) {
    if (fs::exists("/tmp/.X" + std::to_string(d) + "-lock")) continue;
    display = ":" + std::to_string(d);
    const pid_t pid = fork();
    if (pid == 0) {
      if (std::FILE* null = std::fopen("/dev/null", "w")) dup2(fileno(null), 1), dup2(fileno(null), 2);
      execlp("Xvfb", "Xvfb", display.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp",
             static_cast<char*>(nullptr));
      _exit(127);
    }
    for (int tries = 0; tries < 100; ++tries) {
      if (fs::exists("/tmp/.X11-unix/X" + std::to_string(d))) return pid;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    kill(pid, SIGTERM);
    waitpid(pid, nullptr, 0);
  }
  std::fprintf(stderr, "models: Xvfb did not start: no f3d column\n");
  return 0;
}

void keep_min(double& into, double ms) {
  if (ms > 0 && (into == 0 || ms < into)) into = ms;
}

struct Measured {
  double mb = 0;                                                    // file size, 10^6 bytes
  double parse = 0, tinyobj = 0;                                    // in-process, ms
  double served_parse = 0, aliased_raster = 0, aliased_encode = 0;  // the aliased picture's Server-Timing
  double aliased_wall = 0, default_wall = 0, default_raster = 0;  // whole requests (client), raster (server)
  std::vector<double> rss_kib, f3d_kib;                           // a peak per process
  double cli_ms = 0, f3d_ms = 0;                                  // whole CLI / f3d runs
  double aliased_request() const { return served_parse + aliased_raster + aliased_encode; }
};

double median_mb(const std::vector<double>& kib) {
  return kib.empty() ? 0 : bench::median(kib) / 1024.0;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// docs/images/models-by-size.png: whole default-picture run time and peak memory against triangles
// (log-log), a line per format for rasterd's CLI and, lighter, for f3d; llvmpipe's aliased raster and
// rasterd's (the service's, from the PLY) in grey and black.
void plot(const std::map<std::string, Measured>& m, const std::map<std::string, double>& llvmpipe,
          const std::string& path) {
  bench::PlotScene p;
  p.scene.width = 1040;
  p.scene.height = 420;
  p.scene.background = {255, 255, 255, 255};
  p.scene.antialias = raster::Antialias::area;
  const raster::Rgba8 ink{40, 40, 40, 255}, grid{225, 225, 225, 255};
  const raster::Rgba8 colour[] = {
      {220, 60, 60, 255}, {40, 120, 220, 255}, {30, 160, 90, 255}, {200, 130, 20, 255}};
  auto lighter = [](raster::Rgba8 c) {
    return raster::Rgba8{static_cast<std::uint8_t>(c.r + (255 - c.r) * 3 / 5),
                         static_cast<std::uint8_t>(c.g + (255 - c.g) * 3 / 5),
                         static_cast<std::uint8_t>(c.b + (255 - c.b) * 3 / 5), 255};
  };
  const double tri_lo = std::log10(1e5), tri_hi = std::log10(3e6);
  struct Panel {
    double left, right, top, bottom, lo, hi;  // pixels; log10 of the value range
    const char* title;
    const char* unit;
  };
  const Panel panels[2] = {{60, 400, 40, 360, 1, 4, "ms: the CLI's whole run of the default picture", "ms"},
                           {500, 840, 40, 360, 1, 3, "peak resident memory (MB)", "MB"}};
  auto px = [&](const Panel& q, double tris) {
    return q.left + (std::log10(tris) - tri_lo) / (tri_hi - tri_lo) * (q.right - q.left);
  };
  auto py = [&](const Panel& q, double v) {
    return q.bottom - (std::log10(std::max(v, 1.0)) - q.lo) / (q.hi - q.lo) * (q.bottom - q.top);
  };
  for (const Panel& q : panels) {
    for (double d = q.lo; d <= q.hi; ++d) {
      p.line({q.left, py(q, std::pow(10, d))}, {q.right, py(q, std::pow(10, d))}, grid);
      const std::string label = fmt("%g", std::pow(10, d));
      p.text(q.left - 6 - bench::PlotScene::text_width(label), py(q, std::pow(10, d)) - 5, label, ink);
    }
    for (double t : {1e5, 1e6}) {
      p.line({px(q, t), q.top}, {px(q, t), q.bottom}, grid);
      p.text(px(q, t) - 20, q.bottom + 8, t == 1e5 ? "100k" : "1M", ink);
    }
    p.text(q.right - 60, q.bottom + 22, "triangles", ink, 1.2);
    p.line({q.left, q.bottom}, {q.right, q.bottom}, ink, 1.5f);
    p.line({q.left, q.top}, {q.left, q.bottom}, ink, 1.5f);
    p.text(q.left, 14, q.title, ink, 1.3);
  }
  auto series = [&](const Panel& q, const std::vector<double>& values, raster::Rgba8 c) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double tris = 2.0 * kSizes[i].n * kSizes[i].n;
      if (values[i] <= 0) continue;
      const raster::Point2 at{px(q, tris), py(q, values[i])};
      p.mark(at, 3, c);
      if (i > 0 && values[i - 1] > 0) {
        const double before = 2.0 * kSizes[i - 1].n * kSizes[i - 1].n;
        p.line({px(q, before), py(q, values[i - 1])}, at, c, 2);
      }
    }
  };
  int legend = 0;
  auto key = [&](const std::string& name, raster::Rgba8 c) {
    const double y = 60 + 16 * legend++;
    p.line({855, y}, {875, y}, c, 3);
    p.text(880, y - 5, name, ink, 1.1);
  };
  for (std::size_t f = 0; f < std::size(kFormats); ++f) {
    std::vector<double> cli, f3d, rss, f3d_rss;
    for (const Size& size : kSizes) {
      const Measured& r = m.at(file_name(size, kFormats[f]));
      cli.push_back(r.cli_ms), f3d.push_back(r.f3d_ms);
      rss.push_back(median_mb(r.rss_kib)), f3d_rss.push_back(median_mb(r.f3d_kib));
    }
    series(panels[0], cli, colour[f]), series(panels[1], rss, colour[f]);
    series(panels[0], f3d, lighter(colour[f])), series(panels[1], f3d_rss, lighter(colour[f]));
    key(std::string("rasterd ") + kFormats[f].extension, colour[f]);
    key(std::string("f3d ") + kFormats[f].extension, lighter(colour[f]));
  }
  std::vector<double> ours, theirs;
  for (const Size& size : kSizes) {
    ours.push_back(m.at(file_name(size, kFormats[2])).aliased_raster);
    const auto it = llvmpipe.find(file_name(size, kFormats[2]));
    theirs.push_back(it == llvmpipe.end() ? 0 : it->second);
  }
  series(panels[0], ours, {0, 0, 0, 255}), series(panels[0], theirs, {150, 150, 150, 255});
  key("rasterd aliased raster, PLY", {0, 0, 0, 255});
  key("llvmpipe raster, PLY", {150, 150, 150, 255});
  const raster::RenderPlan plan = raster::plan(p.scene);
  const std::vector<std::uint8_t> png = raster::encode_png(raster::render(p.scene, plan), plan.png);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--measure") {
    measure(std::atoi(argv[2]), argv[3]);
    return 0;
  }
  if (argc < 5) {
    std::fprintf(stderr, "usage: models runs osmesa_peer rasterd plot.png\n");
    return 2;
  }
  const int runs = std::max(1, std::atoi(argv[1]));
  const std::string peer = argv[2], rasterd = argv[3], image = argv[4];
  const std::string dir = "/tmp/rasterd-models-" + std::to_string(getpid());
  fs::create_directories(dir);
  std::map<std::string, Measured> m;
  for (const Size& size : kSizes) {
    const Surface s = bumpy_sphere(size.n);
    for (const Format& format : kFormats) {
      const std::string ext = format.extension;
      const std::string bytes = ext == "stl"   ? stl_of(s)
                                : ext == "obj" ? obj_of(s)
                                : ext == "ply" ? ply_of(s)
                                               : glb_of(s);
      std::ofstream(dir + "/" + file_name(size, format), std::ios::binary) << bytes;
      m[file_name(size, format)].mb = static_cast<double>(bytes.size()) / 1e6;
    }
  }
  std::string display;
  const pid_t xvfb = start_xvfb(display);
  std::map<std::string, double> llvmpipe;  // PLY file -> ms
  const int service_runs = std::max(3, runs / 2);
  for (int round = 0; round < kProcesses; ++round) {
    std::fprintf(stderr, "models: round %d of %d\n", round + 1, kProcesses);
    std::string command = "LP_NUM_THREADS=2 " + peer + " " + std::to_string(runs) + " --models";
    for (const Size& size : kSizes) command += " " + dir + "/" + file_name(size, kFormats[2]);
    if (FILE* f = popen(command.c_str(), "r")) {
      char path[4096];
      double ms = 0;
      while (std::fscanf(f, "%4095s %lf", path, &ms) == 2) keep_min(llvmpipe[fs::path(path).filename()], ms);
      pclose(f);
    }
    char self[4096];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    self[std::max<ssize_t>(n, 0)] = 0;
    std::string child = "'";
    child.append(self).append("' --measure ").append(std::to_string(runs)).append(" ").append(dir);
    if (FILE* f = popen(child.c_str(), "r")) {
      char what[16], name[256];
      double ms = 0;
      while (std::fscanf(f, "%15s %255s %lf", what, name, &ms) == 3)
        keep_min(std::string(what) == "parse" ? m[name].parse : m[name].tinyobj, ms);
      pclose(f);
    }
    for (const Size& size : kSizes)
      for (const Format& format : kFormats) {
        const std::string name = file_name(size, format), path = dir + "/" + name;
        Measured& r = m[name];
        const std::string bytes = read_bytes(path);
        const bench::ServerTimes aliased = bench::server_times(
            rasterd, bytes, "antialias=1&background=000000", service_runs, format.media_type, 2);
        keep_min(r.served_parse, aliased.parse_ms), keep_min(r.aliased_raster, aliased.raster_ms);
        keep_min(r.aliased_encode, aliased.encode_ms), keep_min(r.aliased_wall, aliased.wall_ms);
        const bench::ServerTimes picture =
            bench::server_times(rasterd, bytes, "", service_runs, format.media_type, 2);
        keep_min(r.default_wall, picture.wall_ms), keep_min(r.default_raster, picture.raster_ms);
        const Peak cli = run_peak({rasterd, "render", path, "-o", "/dev/null"}, "");
        if (cli.ok) r.rss_kib.push_back(cli.kib), keep_min(r.cli_ms, cli.ms);
        if (xvfb) {
          const Peak f3d =
              run_peak({"f3d", "--output=" + dir + "/f3d.png", "--resolution=512,512", path}, display);
          if (f3d.ok) r.f3d_kib.push_back(f3d.kib), keep_min(r.f3d_ms, f3d.ms);
        }
      }
  }
  if (xvfb) kill(xvfb, SIGTERM), waitpid(xvfb, nullptr, 0);
  fs::remove_all(dir);

  std::printf(
      "| mesh | file | MB | parse ms | MB/s | aliased raster ms | llvmpipe ms | ÷ | aliased request ms | "
      "default picture, whole request ms | CLI peak MB | f3d peak MB | ÷ | CLI run s | f3d run s |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Size& size : kSizes)
    for (const Format& format : kFormats) {
      const Measured& r = m.at(file_name(size, format));
      const double peer_ms =
          llvmpipe.count(file_name(size, kFormats[2])) ? llvmpipe[file_name(size, kFormats[2])] : 0;
      const double ours = median_mb(r.rss_kib), theirs = median_mb(r.f3d_kib);
      std::printf(
          "| %s | %s | %.1f | %.1f | %.0f | %.1f | %.1f | %.2f× | %.1f | %.1f | %.0f | %s | %s | %.2f | %s "
          "|\n",
          size.label, format.name, r.mb, r.parse, r.mb * 1e3 / r.parse, r.aliased_raster, peer_ms,
          r.aliased_raster > 0 ? peer_ms / r.aliased_raster : 0, r.aliased_request(), r.default_wall, ours,
          theirs > 0 ? fmt("%.0f", theirs).c_str() : "-",
          theirs > 0 ? fmt("%.2f", ours / theirs).c_str() : "-", r.cli_ms / 1e3,
          r.f3d_ms > 0 ? fmt("%.2f", r.f3d_ms / 1e3).c_str() : "-");
    }

  // The issue's targets at 2M triangles.
  const Size& big = kSizes[2];
  auto at = [&](const Format& f) -> const Measured& { return m.at(file_name(big, f)); };
  const double peer_big =
      llvmpipe.count(file_name(big, kFormats[2])) ? llvmpipe[file_name(big, kFormats[2])] : 0;
  std::printf("\n| target (2M triangles) | file | measured | met |\n|---|---|---:|---|\n");
  const Measured& obj = at(kFormats[1]);
  std::printf("| OBJ parse ≥ 6× tinyobjloader alone | OBJ | %.2f× (%.0f ms; tinyobjloader %.0f ms) | %s |\n",
              obj.tinyobj / obj.parse, obj.parse, obj.tinyobj,
              obj.tinyobj / obj.parse >= 6 ? "yes" : "**no**");
  for (const Format& f : kFormats) {
    if (std::string(f.extension) == "obj") continue;
    const double rate = at(f).mb * 1e3 / at(f).parse;
    std::printf("| binary parse ≥ 1 GB/s | %s | %.0f MB/s | %s |\n", f.name, rate,
                rate >= 1000 ? "yes" : "**no**");
  }
  for (const Format& f : kFormats) {
    const double ratio = peer_big / at(f).aliased_raster;
    std::printf("| aliased raster ≥ 3× llvmpipe per pixel | %s | %.2f× | %s |\n", f.name, ratio,
                ratio >= 3 ? "yes" : "**no**");
  }
  for (const Format& f : kFormats) {
    if (std::string(f.extension) == "obj") continue;
    const double ms = at(f).aliased_request();
    std::printf("| aliased request (parse + raster + encode) ≤ 200 ms | %s | %.0f ms | %s |\n", f.name, ms,
                ms <= 200 ? "yes" : "**no**");
  }
  for (const Format& f : kFormats) {
    const double ours = median_mb(at(f).rss_kib), theirs = median_mb(at(f).f3d_kib);
    if (theirs > 0)
      std::printf("| CLI default picture's peak ≤ ½ f3d's | %s | %.0f / %.0f MB = %.2f | %s |\n", f.name,
                  ours, theirs, ours / theirs, ours <= theirs / 2 ? "yes" : "**no**");
  }
  plot(m, llvmpipe, image);
  return 0;
}
