// Luminance of lit pixels under a light rig, for docs/lighting.md: is a model without materials too dark
// or washed out? Each model is read as an upload without its MTL (so it is the default grey #cccccc),
// drawn with the default camera (and the iso view) at 256x256 over a transparent background, and every
// covered pixel's luma is taken: Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' on the 8-bit sRGB values, 0..255.
// Printed per model and rig: mean, 5th and 95th percentile, and the share of pixels at the surface colour's
// full value (the light saturated: 204 for #cccccc) or above.
//
//   lighting MODEL.obj...   (a cube is built in code and always measured first)
//
// Second part, materials (issue 42, point 4): every glTF 2.0 file under DIR that reads and has a specular
// material (raster::Material::is_specular) is drawn as a bare model (raster::model_scene) at 192x192 twice:
// its materials cleared, which is exactly the Lambert shading of before materials (old), and as read (new).
// Each pair is written side by side (old | new) to OUT/materials-<name>.png, and a Markdown section for
// docs/lighting.md is printed: per model its materials, the share of its pixels that changed and the
// largest change of luma (as above); the models with no specular material are listed in one line.
//
//   lighting --materials DIR OUT
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "raster/raster.h"
#include "scenes.h"

namespace {

struct Rig {
  const char* name;
  std::vector<raster::Light> lights;
};

struct Figures {
  double mean = 0, p5 = 0, p95 = 0, saturated = 0;
  std::size_t pixels = 0;
  const char* unmeasured = nullptr;  ///< why there is nothing to measure (then pixels = 0)
};

const char* kCube =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

Figures measure(const std::string& obj, const Rig& rig, raster::View view) {
  const std::string doc = R"({"width": 256, "height": 256, "background": "#00000000",)"
                          R"( "primitives": [{"type": "obj", "source": "model"}]})";
  raster::Scene scene = raster::parse_scene(doc, {}, {{"model", obj}});
  scene.lights = rig.lights;
  scene.camera.view = view, scene.camera.has_view = true;
  const raster::RenderPlan plan = raster::plan(scene);
  Figures f;
  if (plan.lit_count == 0) {
    f.unmeasured = "lines or points only, drawn unlit";
    return f;
  }
  const raster::Image image = raster::render(scene, plan);
  std::vector<double> luma;
  const int c = raster::channel_count(image.format);
  for (std::size_t i = 0; i + c <= image.pixels.size(); i += c) {
    if (image.pixels[i + c - 1] == 0) continue;  // not covered (alpha 0)
    const double r = image.pixels[i], g = c >= 3 ? image.pixels[i + 1] : r,
                 b = c >= 3 ? image.pixels[i + 2] : r;
    luma.push_back(0.2126 * r + 0.7152 * g + 0.0722 * b);
  }
  f.pixels = luma.size();
  if (luma.empty()) {
    f.unmeasured = "no pixel covered from this view (a flat model seen edge-on)";
    return f;
  }
  std::sort(luma.begin(), luma.end());
  double sum = 0;
  std::size_t full = 0;
  for (double y : luma) sum += y, full += y >= 203.5;
  f.mean = sum / luma.size();
  f.p5 = luma[luma.size() * 5 / 100];
  f.p95 = luma[std::min(luma.size() - 1, luma.size() * 95 / 100)];
  f.saturated = 100.0 * full / luma.size();
  return f;
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string base_name(const std::string& path) {
  return path.substr(path.find_last_of('/') + 1);
}

namespace fs = std::filesystem;

constexpr int kMaterialSize = 192;  // pixels a side of each half of a materials picture

// Y' of pixel (x, y), 0..255: a grey picture (grey8, grey_alpha8; the plan picks it when every colour is
// grey) has one channel of colour, rgb8 and rgba8 three.
double luma(const raster::Image& image, int x, int y) {
  const std::uint8_t* p = image.at(x, y);
  return image.channels() < 3 ? p[0] : 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// A model as the CLI reads it (bench::read_model_file), then its reader. Throws what the reader throws.
raster::Mesh read_model(const fs::path& path, raster::ModelFormat& format) {
  const bench::ModelFile file = bench::read_model_file(path.string());
  format = file.format;
  return raster::parse_model(file.bytes, format, {}, file.files);
}

raster::Image draw_model(raster::Mesh mesh, raster::ModelFormat format, const raster::Rgba8* background) {
  raster::Scene scene = raster::model_scene(std::move(mesh), format);
  scene.width = scene.height = kMaterialSize;
  if (background) scene.background = *background;
  raster::validate(scene);
  return raster::render(scene, raster::plan(scene));
}

// The materials the mesh's faces use, in words: "metallic 0, roughness 0.5 (metallic-roughness texture)".
std::string describe_materials(const raster::Mesh& mesh) {
  std::set<std::int32_t> used;
  if (mesh.face_materials.empty())
    used.insert(0);
  else
    used.insert(mesh.face_materials.begin(), mesh.face_materials.end());
  // Identical materials (a file often repeats one per part) are counted, not repeated.
  std::vector<std::pair<std::string, int>> kinds;
  int lambert_faces = 0;
  for (std::int32_t m : mesh.face_materials) lambert_faces += m < 0;
  for (std::int32_t i : used) {
    if (i < 0 || static_cast<std::size_t>(i) >= mesh.materials.size()) continue;
    const raster::Material& m = mesh.materials[static_cast<std::size_t>(i)];
    char line[160];
    if (m.model == raster::Material::Model::metallic_roughness)
      std::snprintf(line, sizeof line, "metallic %g, roughness %g%s", m.metallic, m.roughness,
                    m.metallic_roughness_texture >= 0 ? " x a metallic-roughness texture" : "");
    else
      std::snprintf(line, sizeof line, "Blinn-Phong Ks (%g, %g, %g), Ns %g", m.specular[0], m.specular[1],
                    m.specular[2], m.shininess);
    auto same = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == line; });
    if (same == kinds.end())
      kinds.emplace_back(line, 1);
    else
      ++same->second;
  }
  std::string out;
  for (const auto& [kind, count] : kinds)
    out += (out.empty() ? "" : "; ") + kind + (count > 1 ? " (" + std::to_string(count) + " materials)" : "");
  if (lambert_faces > 0) out += "; " + std::to_string(lambert_faces) + " faces Lambert";
  // The glTF reader gives face_textures base-colour textures only (a metallic-roughness texture is named
  // by its material), so any face with one is textured, whichever image the two share.
  const bool textured = std::any_of(mesh.face_textures.begin(), mesh.face_textures.end(),
                                    [](std::int32_t t) { return t >= 0; });
  return out + (textured ? "; base colour textured" : "; base colour untextured");
}

struct Change {
  std::size_t model_pixels = 0, changed = 0;
  double largest = 0;    ///< the largest |luma new - luma old| over the model's pixels, 0..255
  bool brighter = true;  ///< whether that largest change brightens
};

// Model pixels are those the model covers over a transparent background (the same for old and new: only
// the shading differs); a pixel changed when any channel of old and new differs.
Change compare(const raster::Image& coverage, const raster::Image& old_image,
               const raster::Image& new_image) {
  Change c;
  const int cc = coverage.channels();
  for (int y = 0; y < old_image.height; ++y)
    for (int x = 0; x < old_image.width; ++x) {
      if (coverage.at(x, y)[cc - 1] == 0) continue;
      ++c.model_pixels;
      const std::uint8_t *o = old_image.at(x, y), *n = new_image.at(x, y);
      if (!std::equal(o, o + old_image.channels(), n)) ++c.changed;
      const double d = luma(new_image, x, y) - luma(old_image, x, y);
      if (std::abs(d) > c.largest) c.largest = std::abs(d), c.brighter = d > 0;
    }
  return c;
}

// old | new | difference, side by side with 4-pixel gaps in the pictures' background colour. Most changes
// are a few levels of luma, too small to see beside each other, so the third panel shows where they are:
// the model's pixels black, brightened by 16x their change of luma (a change of 16 or more is white).
void write_pictures(const raster::Image& coverage, const raster::Image& old_image,
                    const raster::Image& new_image, const fs::path& path) {
  constexpr int kGap = 4, kGain = 16;
  const int side = old_image.width, c = old_image.channels();
  raster::Image diff = old_image;
  for (int y = 0; y < diff.height; ++y)
    for (int x = 0; x < side; ++x) {
      if (coverage.at(x, y)[coverage.channels() - 1] == 0) continue;
      const double d = std::abs(luma(new_image, x, y) - luma(old_image, x, y));
      std::uint8_t* p = diff.pixels.data() + (static_cast<std::size_t>(y) * side + x) * c;
      std::fill(p, p + c, static_cast<std::uint8_t>(std::min(255.0, std::round(kGain * d))));
      if (c == 2 || c == 4) p[c - 1] = 255;
    }
  const raster::Image* panels[] = {&old_image, &new_image, &diff};
  raster::Image sheet;
  sheet.format = old_image.format;
  sheet.width = 3 * side + 2 * kGap, sheet.height = old_image.height;
  sheet.pixels.resize(static_cast<std::size_t>(sheet.width) * sheet.height * c);
  for (int y = 0; y < sheet.height; ++y)
    for (int x = 0; x < sheet.width; ++x) {
      const int panel = x / (side + kGap), within = x % (side + kGap);
      const std::uint8_t* from = within < side ? panels[panel]->at(within, y) : old_image.at(0, 0);  // a gap
      std::copy(from, from + c, sheet.pixels.data() + (static_cast<std::size_t>(y) * sheet.width + x) * c);
    }
  const auto png = raster::encode_png(sheet);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
}

int materials(const fs::path& dir, const fs::path& out) {
  std::vector<fs::path> paths;
  std::error_code error;
  for (const auto& entry : fs::recursive_directory_iterator(dir, error)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  struct Drawn {
    std::vector<std::string> names;  ///< the files drawn exactly alike (the same model in other packagings)
    std::string materials, file;
    raster::Image old_image, new_image;
    Change change;
    bool metal = false;   ///< some material has metallic > 0 (before its texture)
    float roughness = 1;  ///< the least roughness factor of its materials, 0..1
  };
  std::vector<Drawn> drawn;
  std::vector<std::string> plain, refused;
  for (const fs::path& path : paths) {
    const std::string name = fs::relative(path, dir).string();
    try {
      raster::ModelFormat format;
      raster::Mesh mesh = read_model(path, format);
      bool specular = false;
      for (const raster::Material& m : mesh.materials) specular |= m.is_specular();
      raster::Mesh old_mesh = mesh;
      old_mesh.materials.clear(), old_mesh.face_materials.clear();
      const raster::Rgba8 clear{0, 0, 0, 0};
      const raster::Image coverage =
          draw_model(old_mesh, format, &clear);  // refused: not drawn before either
      if (!specular) {
        plain.push_back(name);
        continue;
      }
      Drawn d{{name},
              describe_materials(mesh),
              "",
              draw_model(old_mesh, format, nullptr),
              draw_model(mesh, format, nullptr),
              {}};
      d.change = compare(coverage, d.old_image, d.new_image);
      for (const raster::Material& m : mesh.materials)
        if (m.model == raster::Material::Model::metallic_roughness)
          d.metal |= m.metallic > 0, d.roughness = std::min(d.roughness, m.roughness);
      auto same = std::find_if(drawn.begin(), drawn.end(), [&](const Drawn& e) {
        return e.materials == d.materials && e.old_image.pixels == d.old_image.pixels &&
               e.new_image.pixels == d.new_image.pixels;
      });
      if (same != drawn.end()) {
        same->names.push_back(name);
        continue;
      }
      d.file = "materials-" + name.substr(0, name.find_last_of('.')) + ".png";
      std::replace(d.file.begin(), d.file.end(), '/', '-');
      write_pictures(coverage, d.old_image, d.new_image, out / d.file);
      drawn.push_back(std::move(d));
    } catch (const std::exception&) {
      refused.push_back(name);
    }
  }
  auto join = [](const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "`" : ", `") + n + "`";
    return s.empty() ? std::string("none") : s;
  };
  std::size_t metals = 0, files = 0;
  const Drawn* smoothest = nullptr;
  for (const Drawn& d : drawn) {
    files += d.names.size(), metals += d.metal;
    if (!smoothest || d.roughness < smoothest->roughness) smoothest = &d;
  }
  std::printf("## Materials: glTF's metallic-roughness, old beside new\n\n");
  std::printf(
      "A glTF 2.0 model's materials are now read (`raster::Material`: metallic and roughness factors, and "
      "the\nmetallic-roughness texture) and shaded with the specification's BRDF (appendix B). Old is the "
      "same mesh\nwith its materials cleared, which is exactly the Lambert shading of before; new is the "
      "mesh as read.\nEvery glTF 2.0 file of `assimp-testmodels` (`/usr/share/assimp/models/glTF2`, .gltf "
      "and .glb) is drawn\nas a bare model (`raster::model_scene`: default camera, lights and background) at "
      "%dx%d. Each picture is\nold | new | the change: the model's pixels in black, brightened 16x their "
      "change "
      "of luma Y' (as\nabove, 0..255; 16 or more is white). \"Changed\" counts the model's pixels (those "
      "it covers over a\ntransparent background) where any channel differs. Files drawn byte for byte "
      "alike share a picture.\n\n",
      kMaterialSize, kMaterialSize);
  std::printf(
      "%zu files have a specular material, %zu distinct pictures; %zu of them have a metal (metallic > 0). "
      "A\ndielectric's F0 is 0.04, so a rough one (roughness near 1, as most of these) changes by a few "
      "levels:\nwhat its diffuse loses to Fresnel comes back as a faint, wide highlight and as ambient x F0 "
      "(a white\nsurface's loss and gain cancel to within rounding). The smoothest, `%s` (roughness %g), "
      "shows\nhighlights.\n\n",
      files, drawn.size(), metals, smoothest ? smoothest->names[0].c_str() : "none",
      smoothest ? smoothest->roughness : 0.0f);
  for (const Drawn& d : drawn) {
    const Change& c = d.change;
    std::printf("### %s\n\n", join(d.names).c_str());
    if (d.names.size() > 1) std::printf("(drawn alike: the same model and materials)\n\n");
    std::printf(
        "%s. %zu model pixels, %.1f%% changed; the largest change of luma %.0f%s.\n\n"
        "![%s: old (Lambert) | new (materials) | change x16](images/%s)\n\n",
        d.materials.c_str(), c.model_pixels, c.model_pixels ? 100.0 * c.changed / c.model_pixels : 0.0,
        c.largest,
        c.largest == 0 ? ""
        : c.brighter   ? " (brighter)"
                       : " (darker)",
        d.names[0].c_str(), d.file.c_str());
  }
  std::printf(
      "Drawn as before (no specular material): %s.\n\nNot read (refused by the reader or the plan, "
      "with or without materials): %s.\n",
      join(plain).c_str(), join(refused).c_str());
  return 0;
}

int lit_pixels(int argc, char** argv) {
  const std::vector<Rig> rigs = {
      {"before (0.1: headlight 0.8 + ambient 0.2)", raster::single_light(0.2, nullptr)},
      {"after (default: key 0.45 + fill 0.25 + ambient 0.35)", raster::default_lights()}};
  std::vector<std::pair<std::string, std::string>> models = {{"cube (built in)", kCube}};
  for (int i = 1; i < argc; ++i) models.emplace_back(base_name(argv[i]), read(argv[i]));

  std::printf("| model | view | rig | lit pixels | mean | p5 | p95 | at full value |\n");
  std::printf("|---|---|---|--:|--:|--:|--:|--:|\n");
  std::vector<Figures> totals(rigs.size());
  std::vector<std::vector<double>> means(rigs.size()), p5s(rigs.size()), p95s(rigs.size());
  for (const auto& [name, obj] : models) {
    bool drawn = true;
    for (const auto& [view, view_name] :
         {std::pair{raster::View::front, "front"}, {raster::View::iso, "iso"}}) {
      for (std::size_t r = 0; drawn && r < rigs.size(); ++r) {
        Figures f;
        try {
          f = measure(obj, rigs[r], view);
        } catch (const std::exception& e) {  // the model itself is refused: once, for every view
          std::printf("| %s | | not drawn: %.80s | | | | | |\n", name.c_str(), e.what());
          drawn = false;
          break;
        }
        if (f.unmeasured) {  // the same for every rig
          std::printf("| %s | %s | not measured: %s | | | | | |\n", name.c_str(), view_name, f.unmeasured);
          break;
        }
        std::printf("| %s | %s | %s | %zu | %.0f | %.0f | %.0f | %.1f%% |\n", name.c_str(), view_name,
                    r == 0 ? "before" : "after", f.pixels, f.mean, f.p5, f.p95, f.saturated);
        means[r].push_back(f.mean), p5s[r].push_back(f.p5), p95s[r].push_back(f.p95);
        totals[r].saturated += f.saturated;
      }
    }
  }
  std::printf(
      "\n| rig | renders | mean of means | lowest p5 | median p5 | median p95 | highest p95 | mean share at "
      "full value |\n");
  std::printf("|---|--:|--:|--:|--:|--:|--:|--:|\n");
  for (std::size_t r = 0; r < rigs.size(); ++r) {
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v.empty() ? 0.0 : v[v.size() / 2];
    };
    double mean = 0;
    for (double m : means[r]) mean += m;
    const std::size_t n = means[r].size();
    std::printf("| %s | %zu | %.0f | %.0f | %.0f | %.0f | %.0f | %.1f%% |\n", rigs[r].name, n,
                n ? mean / n : 0, n ? *std::min_element(p5s[r].begin(), p5s[r].end()) : 0, median(p5s[r]),
                median(p95s[r]), n ? *std::max_element(p95s[r].begin(), p95s[r].end()) : 0,
                n ? totals[r].saturated / n : 0);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--materials") return materials(argv[2], argv[3]);
  return lit_pixels(argc, argv);
}
