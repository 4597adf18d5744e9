// libFuzzer target: OBJ (+ MTL) text -> mesh -> render through the default camera -> PNG, on a small image,
// and the same text through the OBJ oracle (tests/oracle/obj_tinyobj.cpp, the reader through tinyobjloader
// that rasterd's own replaced): both must read it or both refuse it, and what they read must be the same
// mesh but for the oracle's documented differences (tests/obj_reader_test.cpp): its lines and points where
// a material or group statement follows them, its normals of a model without faces, and a position's last
// float bit where tinyobjloader's own number parser rounds a long decimal otherwise.
// The input is the OBJ, optionally followed by a NUL byte and an MTL. The MTL is given as text on even
// lengths and as the uploaded file "a.mtl" (which `mtllib a.mtl` names) on odd ones, so the MTL reader,
// its map_Kd options and the library lookup are all reached; the uploads also hold a 2x2 PNG under "t.png"
// for map_Kd to find. The input's length also picks the pieces the reader cuts the text into (down to a
// line each) and its threads. Any crash, sanitizer report, disagreement, or exception other than
// SceneError is a finding.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "model/obj_text.h"
#include "oracle/obj_tinyobj.h"
#include "raster/raster.h"

namespace {

std::string small_png() {
  raster::Image image;
  image.width = image.height = 2, image.format = raster::PixelFormat::rgba8;
  image.pixels = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 255, 255, 255, 0};
  const auto bytes = raster::encode_png(image);
  return std::string(bytes.begin(), bytes.end());
}

[[noreturn]] void disagree(const char* what) {
  std::fprintf(stderr, "obj_fuzzer: the reader and its oracle disagree: %s\n", what);
  std::abort();
}

bool near(const raster::Vec3f& a, const raster::Vec3f& b) {
  auto one = [](float x, float y) { return x == y || std::nextafter(x, y) == y; };
  return one(a.x, b.x) && one(a.y, b.y) && one(a.z, b.z);
}

void compare(const raster::Mesh& ours, raster::Mesh oracle, std::string_view obj) {
  if (ours.positions.size() != oracle.positions.size()) disagree("vertex count");
  for (std::size_t i = 0; i < ours.positions.size(); ++i)
    if (!near(ours.positions[i], oracle.positions[i])) disagree("a position");
  if (oracle.triangles.empty()) oracle.normals.clear(), oracle.normal_triangles.clear();
  if (ours.normals.size() != oracle.normals.size()) disagree("normal count");
  for (std::size_t i = 0; i < ours.normals.size(); ++i)
    if (!near(ours.normals[i], oracle.normals[i])) disagree("a normal");
  if (ours.triangles != oracle.triangles || ours.normal_triangles != oracle.normal_triangles)
    disagree("triangles");
  if (ours.colors != oracle.colors || ours.face_colors != oracle.face_colors) disagree("colours");
  if (ours.uvs != oracle.uvs || ours.uv_triangles != oracle.uv_triangles ||
      ours.textures != oracle.textures || ours.face_textures != oracle.face_textures)
    disagree("textures");
  if (ours.materials != oracle.materials || ours.face_materials != oracle.face_materials)
    disagree("materials");
  // tinyobjloader gives a line or point statement again at each later material change, and loses those of
  // a group without faces: compared only where neither can happen.
  bool grouped = false, doubled_blank = false;
  for (std::size_t at = 0; at <= obj.size() && !grouped && !doubled_blank;) {
    std::size_t end = obj.find('\n', at);
    if (end == std::string_view::npos) end = obj.size();
    const std::string_view line = obj.substr(at, end - at);
    const std::size_t first = line.find_first_not_of(" \t\r");
    const std::string_view word = first == std::string_view::npos ? "" : line.substr(first, 6);
    grouped = word.starts_with("usemtl") || word.starts_with("g") || word.starts_with("o");
    // tinyobjloader reads the references of an `l` or `p` line whose keyword is followed by two blanks
    // ("l  1 4", " p  4") with one more: those lines are not compared.
    doubled_blank |= (word.starts_with("l") || word.starts_with("p")) && word.size() >= 3 &&
                     (word[1] == ' ' || word[1] == '\t') && (word[2] == ' ' || word[2] == '\t');
    at = end + 1;
  }
  if (!grouped && !doubled_blank && (ours.segments != oracle.segments || ours.points != oracle.points))
    disagree("lines or points");
}

// tinyobjloader (2.0.0~rc10's LoadObj) takes any line that begins with "usemtl" for a `usemtl` statement
// ("usemtl)m" names the material ")m"); rasterd's reader, like OBJ, takes only the keyword followed by a
// blank. A documented difference: such a model's looks are not compared.
bool glued_usemtl(std::string_view obj) {
  for (std::size_t at = obj.find("usemtl"); at != std::string_view::npos; at = obj.find("usemtl", at + 6)) {
    const std::size_t start = obj.rfind('\n', at) == std::string_view::npos ? 0 : obj.rfind('\n', at) + 1;
    const bool first_word = obj.find_first_not_of(" \t\r", start) == at;
    const char next = at + 6 < obj.size() ? obj[at + 6] : '\n';
    if (first_word && next != ' ' && next != '\t' && next != '\r' && next != '\n') return true;
  }
  return false;
}

// A reference with an empty part after its last slash ("11/ 2/2"): tinyobjloader cannot parse it or reads the
// next reference's number into it; rasterd reads the position alone. Such a model is not compared.
bool empty_after_slash(std::string_view obj) {
  for (std::size_t at = obj.find('/'); at != std::string_view::npos; at = obj.find('/', at + 1))
    if (at + 1 == obj.size() || std::string_view(" \t\r\n").find(obj[at + 1]) != std::string_view::npos)
      return true;
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string kPng = small_png();
  raster::Limits limits;
  limits.max_model_faces = 20000;
  limits.max_texture_pixels = 64;
  limits.threads = 1 + static_cast<int>(size % 3);
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = input.find('\0');
  const std::string_view obj = input.substr(0, nul);
  const std::string_view mtl = nul == std::string_view::npos ? std::string_view() : input.substr(nul + 1);
  raster::Uploads files{{"t.png", kPng}};
  if (size % 2 == 1) files["a.mtl"] = std::string(mtl);
  const std::string_view given_mtl = size % 2 == 0 ? mtl : std::string_view();
  raster::Mesh oracle;
  std::string oracle_error;
  try {
    oracle = raster::oracle::parse_obj_tinyobj(obj, given_mtl, limits, files);
  } catch (const raster::SceneError& e) {
    oracle_error = e.what();
  }
  const std::size_t piece = size % 4 == 0 ? std::size_t{1} << 20 : 1 + size % 61;
  raster::Mesh ours;
  std::string our_error;
  try {
    ours = raster::obj::read_obj_text(obj, given_mtl, limits, files, piece);
  } catch (const raster::SceneError& e) {
    our_error = e.what();
    // its message (echoed to clients) must be UTF-8
    if (raster::first_invalid_utf8(our_error) != std::string_view::npos) std::abort();
  }
  // tinyobjloader also refuses its own extensions' lines it cannot parse ("vw" skin weights), which
  // rasterd's reader passes over as it passes over every statement it does not draw, and a reference with an
  // empty part after its slash ("3/"), which rasterd reads as the position alone: then rasterd's reader may
  // read the model, or refuse it for what comes after (a texture not sent).
  const bool oracle_own = oracle_error.find("could not be parsed") != std::string::npos;
  // A CR alone ends a line for tinyobjloader (classic Mac OS line ends); rasterd refuses a line with more
  // after a CR, naming it, rather than read the rest as more of the statement (the fuzzer's finding "v 0 03
  // \r-2 -1").
  if (our_error.find("a carriage return (CR)") != std::string::npos) return 0;
  // It loses the lines and points of a group without faces (see compare()): a model of those alone is
  // empty to it, and drawn by rasterd.
  const bool oracle_lost =
      our_error.empty() && oracle_error.find("no faces, lines or points") != std::string::npos;
  if (our_error != oracle_error && !oracle_own && !oracle_lost)
    disagree(("the readers' errors: \"" + our_error + "\" and \"" + oracle_error + "\"").c_str());
  if (!our_error.empty()) return 0;
  if (oracle_error.empty() && !glued_usemtl(obj) && !empty_after_slash(obj)) compare(ours, oracle, obj);
  try {
    raster::Scene scene;
    scene.width = 64;
    scene.height = 48;
    scene.meshes.push_back(std::move(ours));
    if (scene.meshes[0].colors.empty()) scene.meshes[0].colors = {raster::Rgba8{200, 180, 160, 255}};
    // Alternate shadings, wireframe and edges by input length so every path sees inputs.
    scene.meshes[0].shading = static_cast<raster::Shading>(size % 3);
    scene.meshes[0].wireframe = size % 7 == 0;
    scene.meshes[0].edges.enabled = size % 5 == 0;
    raster::Primitive p;
    p.kind = raster::PrimitiveKind::mesh;
    scene.primitives.push_back(p);
    raster::PlanOptions options;
    options.max_threads = 1;
    const raster::RenderPlan plan = raster::plan(scene, limits, options);
    raster::encode_png(raster::render(scene, plan), plan.png);
  } catch (const raster::SceneError& e) {
    if (raster::first_invalid_utf8(e.what()) != std::string_view::npos) std::abort();
  }
  return 0;
}
