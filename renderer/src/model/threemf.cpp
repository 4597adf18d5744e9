// 3MF: the ZIP package (model/zip.h), its root model part found through _rels/.rels, and each model part's
// XML read by expat as it streams: resources (objects with a mesh or components, base materials and the
// materials extension's colour groups), then the build. Every build item is placed, its components within
// it, into one mesh in millimetres.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <expat.h>

#include "base/budget_ask.h"
#include "base/vecmath.h"
#include "model/zip.h"
#include "raster/model.h"

namespace raster {
namespace {

constexpr std::string_view kModelRelationship =
    "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";
constexpr std::string_view kRelationshipsNs = "http://schemas.openxmlformats.org/package/2006/relationships";
constexpr std::string_view kCoreNs = "http://schemas.microsoft.com/3dmanufacturing/core/2015/02";
constexpr std::string_view kMaterialNs = "http://schemas.microsoft.com/3dmanufacturing/material/2015/02";
constexpr std::string_view kProductionNs = "http://schemas.microsoft.com/3dmanufacturing/production/2015/06";
// The extensions a model may require that rasterd draws as they mean: the materials extension's colour
// groups are read; the production extension's parts in other files are followed (its UUIDs need nothing).
constexpr std::string_view kKnownExtensions[] = {kCoreNs, kMaterialNs, kProductionNs};

constexpr int kMaxXmlDepth = 64;        // elements nested: a model is ~5 deep, XML bombs are thousands
constexpr int kMaxComponentDepth = 32;  // components within components
constexpr std::uint32_t kNone = 0xffffffffu;

struct Triangle {
  std::uint32_t v[3];
  std::uint32_t pid = kNone, p1 = kNone;  // a property group and an index into it; kNone: the object's
};
struct Component {
  std::uint32_t object = 0;
  std::string path;  // the production extension's part holding the object; empty: this part
  Mat4 transform;
};
struct Object {
  std::uint32_t pid = kNone, pindex = 0;  // the object's default property
  std::vector<Vec3f> vertices;            // model units
  std::vector<Triangle> triangles;
  std::vector<Component> components;
  bool has_mesh = false;
};
/// One model part, read.
struct Part {
  std::string name;
  double to_mm = 1;  // the part's unit in millimetres
  std::map<std::uint32_t, Object> objects;
  std::map<std::uint32_t, std::vector<Rgba8>> colours;  // base materials' display colours, colour groups
  std::vector<Component> build;                         // the build's items (object, path, transform)
};

// "#RRGGBB" or "#RRGGBBAA" (sRGB, as 3MF writes colours).
std::optional<Rgba8> colour_of(std::string_view s) {
  if (!(s.size() == 7 || s.size() == 9) || s[0] != '#') return std::nullopt;
  std::uint8_t c[4] = {0, 0, 0, 255};
  for (std::size_t i = 0; i + 1 < s.size(); i += 2) {
    const auto r = std::from_chars(s.data() + 1 + i, s.data() + 3 + i, c[i / 2], 16);
    if (r.ec != std::errc() || r.ptr != s.data() + 3 + i) return std::nullopt;
  }
  return Rgba8{c[0], c[1], c[2], c[3]};
}

// The SAX reader of one model part.
class PartReader {
 public:
  PartReader(std::string name, const Limits& limits) : limits_(limits) { part_.name = std::move(name); }

  Part read(const std::string& xml) {
    std::unique_ptr<XML_ParserStruct, decltype(&XML_ParserFree)> parser(XML_ParserCreateNS(nullptr, '|'),
                                                                        &XML_ParserFree);
    if (!parser) throw std::bad_alloc();
    parser_ = parser.get();
    XML_SetUserData(parser_, this);
    XML_SetElementHandler(parser_, &PartReader::on_start, &PartReader::on_end);
    XML_SetStartNamespaceDeclHandler(parser_, &PartReader::on_namespace);
    XML_SetStartDoctypeDeclHandler(parser_, &PartReader::on_doctype);
    // One call for the whole part: the text is in memory already (its size asked of the budget).
    if (XML_Parse(parser_, xml.data(), static_cast<int>(std::min<std::size_t>(xml.size(), INT32_MAX)), 1) ==
            XML_STATUS_ERROR &&
        !error_) {
      fail(std::string("is not well-formed XML: ") + XML_ErrorString(XML_GetErrorCode(parser_)));
    }
    if (error_) std::rethrow_exception(error_);
    if (!saw_model_) fail("has no <model> element");
    return std::move(part_);
  }

 private:
  static void on_start(void* self, const char* name, const char** attrs) {
    auto* r = static_cast<PartReader*>(self);
    try {
      r->start(name, attrs);
    } catch (...) {
      r->error_ = std::current_exception();
      XML_StopParser(r->parser_, XML_FALSE);
    }
  }
  static void on_end(void* self, const char*) {
    auto* r = static_cast<PartReader*>(self);
    --r->depth_;
    if (r->depth_ < r->object_depth_) r->object_ = nullptr, r->object_depth_ = 0;
    if (r->depth_ < r->group_depth_) r->group_ = nullptr, r->group_depth_ = 0;
  }
  static void on_namespace(void* self, const char* prefix, const char* uri) {
    static_cast<PartReader*>(self)->prefixes_[prefix ? prefix : ""] = uri ? uri : "";
  }
  static void on_doctype(void* self, const char*, const char*, const char*, int) {
    auto* r = static_cast<PartReader*>(self);
    try {
      r->fail("has a DOCTYPE, which 3MF does not allow (and entities could expand without bound)");
    } catch (...) {
      r->error_ = std::current_exception();
      XML_StopParser(r->parser_, XML_FALSE);
    }
  }

  [[noreturn]] void fail(const std::string& message) const {
    const std::size_t line = parser_ ? XML_GetCurrentLineNumber(parser_) : 0;
    throw SceneError(ErrorKind::model,
                     "3MF part " + part_.name + " line " + std::to_string(line) + ": " + message,
                     {"", 0, line});
  }

  const char* attribute(const char** attrs, std::string_view name) const {
    for (; *attrs; attrs += 2)
      if (name == *attrs) return attrs[1];
    return nullptr;
  }
  double number(const char* text, std::string_view what) const {
    double v = 0;
    const char* end = text + std::strlen(text);
    const char* at = text;
    while (at < end && (*at == ' ' || *at == '\t')) ++at;
    if (at < end && *at == '+') ++at;
    const auto r = std::from_chars(at, end, v);
    if (r.ec != std::errc() || r.ptr != end || !std::isfinite(v))
      fail(std::string(what) + " is \"" + std::string(text).substr(0, 40) + "\", not a finite number");
    return v;
  }
  std::uint32_t index(const char* text, std::string_view what) const {
    std::uint32_t v = 0;
    const char* end = text + std::strlen(text);
    const auto r = std::from_chars(text, end, v);
    if (r.ec != std::errc() || r.ptr != end)
      fail(std::string(what) + " is \"" + std::string(text).substr(0, 40) + "\", not an index");
    return v;
  }
  std::uint32_t required_index(const char** attrs, const char* name, std::string_view element) const {
    const char* v = attribute(attrs, name);
    if (!v) fail("<" + std::string(element) + "> has no " + name);
    return index(v, std::string(element) + " " + name);
  }
  // A 3MF transform: 12 numbers, the rows of a 4x3 matrix acting on row vectors (x' = x m00 + y m10 + z m20
  // + m30), as a column-vector Mat4.
  Mat4 transform(const char* text) const {
    Mat4 m;
    std::string_view s(text);
    double v[12];
    for (int i = 0; i < 12; ++i) {
      const std::size_t a = s.find_first_not_of(" \t\r\n");
      if (a == std::string_view::npos) fail("a transform has " + std::to_string(i) + " numbers, not 12");
      s.remove_prefix(a);
      const std::size_t b = std::min(s.find_first_of(" \t\r\n"), s.size());
      v[i] = number(std::string(s.substr(0, b)).c_str(), "a transform's number");
      s.remove_prefix(b);
    }
    if (s.find_first_not_of(" \t\r\n") != std::string_view::npos)
      fail("a transform has more than 12 numbers");
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 4; ++col) m(row, col) = v[col * 3 + row];
    return m;
  }

  void check_required(const char* list) {
    std::string_view s(list);
    while (!s.empty()) {
      const std::size_t a = s.find_first_not_of(" \t\r\n");
      if (a == std::string_view::npos) break;
      s.remove_prefix(a);
      const std::size_t b = std::min(s.find_first_of(" \t\r\n"), s.size());
      const std::string prefix(s.substr(0, b));
      s.remove_prefix(b);
      const auto ns = prefixes_.find(prefix);
      if (ns == prefixes_.end())
        fail("requires the extension \"" + prefix + "\", a prefix it does not declare");
      if (std::find(std::begin(kKnownExtensions), std::end(kKnownExtensions), ns->second) ==
          std::end(kKnownExtensions))
        throw SceneError(ErrorKind::model,
                         "the 3MF model requires the extension " + ns->second + " (\"" + prefix +
                             "\"), which rasterd does not read; it reads the core, materials and production "
                             "specifications");
    }
  }

  void start(const char* name, const char** attrs);
  void start_model(const char** attrs);

  // A new resource's id: objects, base materials and colour groups share one id space within a part.
  std::uint32_t resource_id(const char** attrs, std::string_view element) const {
    const std::uint32_t id = required_index(attrs, "id", element);
    if (part_.objects.count(id) || part_.colours.count(id))
      fail("two resources have the id " + std::to_string(id));
    return id;
  }
  // <basematerials> and <m:colorgroup>: the colours their entries add, by index.
  void start_group(const char** attrs, std::string_view element) {
    group_ = &part_.colours[resource_id(attrs, element)], group_depth_ = depth_;
  }
  // A group's entry (<base displaycolor>, <m:color color>): its colour, in order.
  void add_colour(const char** attrs, const char* key, std::string_view element, std::string_view group) {
    if (!group_) fail("a <" + std::string(element) + "> outside <" + std::string(group) + ">");
    const char* c = attribute(attrs, key);
    const auto colour = c ? colour_of(c) : std::nullopt;
    if (!colour) fail("a <" + std::string(element) + "> needs a " + key + " as #RRGGBB or #RRGGBBAA");
    group_->push_back(*colour);
  }

  const Limits& limits_;
  XML_Parser parser_ = nullptr;
  std::exception_ptr error_;
  Part part_;
  std::map<std::string, std::string> prefixes_;
  int depth_ = 0, object_depth_ = 0, group_depth_ = 0;
  bool saw_model_ = false, in_build_ = false;
  Object* object_ = nullptr;
  std::vector<Rgba8>* group_ = nullptr;
  std::uint32_t lines_ = 0;
};

void PartReader::start_model(const char** attrs) {
  saw_model_ = true;
  if (const char* unit = attribute(attrs, "unit")) {
    static constexpr std::pair<std::string_view, double> kUnits[] = {{"micron", 0.001},  {"millimeter", 1},
                                                                     {"centimeter", 10}, {"inch", 25.4},
                                                                     {"foot", 304.8},    {"meter", 1000}};
    const auto u =
        std::find_if(std::begin(kUnits), std::end(kUnits), [&](const auto& p) { return p.first == unit; });
    if (u == std::end(kUnits))
      fail(std::string("has the unit \"") + unit +
           "\"; 3MF's are micron, millimeter, centimeter, inch, foot and meter");
    part_.to_mm = u->second;
  }
  if (const char* required = attribute(attrs, "requiredextensions")) check_required(required);
}

void PartReader::start(const char* name, const char** attrs) {
  if (++depth_ > kMaxXmlDepth) fail("nests elements more than " + std::to_string(kMaxXmlDepth) + " deep");
  if (++lines_ % detail::kLinesPerCheck == 0) detail::stop_if_expired(limits_);
  const char* bar = std::strrchr(name, '|');
  if (!bar) return;  // an element of no namespace: not 3MF's
  const std::string_view ns(name, static_cast<std::size_t>(bar - name)), local(bar + 1);
  if (ns == kCoreNs) {
    if (local == "vertex") {
      if (!object_) fail("a <vertex> outside an object's mesh");
      const char *x = attribute(attrs, "x"), *y = attribute(attrs, "y"), *z = attribute(attrs, "z");
      if (!x || !y || !z) fail("a <vertex> needs x, y and z");
      detail::grow_asked(limits_, object_->vertices, object_->vertices.size() + 1,
                         [] { return std::string("the 3MF model's vertices"); });
      object_->vertices.push_back(Vec3f(Vec3{number(x, "x"), number(y, "y"), number(z, "z")}));
    } else if (local == "triangle") {
      if (!object_) fail("a <triangle> outside an object's mesh");
      Triangle t;
      t.v[0] = required_index(attrs, "v1", "triangle"), t.v[1] = required_index(attrs, "v2", "triangle");
      t.v[2] = required_index(attrs, "v3", "triangle");
      for (const std::uint32_t v : t.v)
        if (v >= object_->vertices.size())
          fail("a <triangle> names vertex " + std::to_string(v) + " of " +
               std::to_string(object_->vertices.size()));
      if (const char* pid = attribute(attrs, "pid")) t.pid = index(pid, "pid");
      if (const char* p1 = attribute(attrs, "p1")) t.p1 = index(p1, "p1");
      detail::grow_asked(limits_, object_->triangles, object_->triangles.size() + 1,
                         [] { return std::string("the 3MF model's triangles"); });
      object_->triangles.push_back(t);
    } else if (local == "object") {
      object_ = &part_.objects[resource_id(attrs, local)], object_depth_ = depth_;
      if (const char* pid = attribute(attrs, "pid")) object_->pid = index(pid, "pid");
      if (const char* pindex = attribute(attrs, "pindex")) object_->pindex = index(pindex, "pindex");
    } else if (local == "mesh") {
      if (!object_) fail("a <mesh> outside an <object>");
      object_->has_mesh = true;
    } else if (local == "component" || local == "item") {
      const bool item = local == "item";
      if (item ? !in_build_ : !object_)
        fail("a <" + std::string(local) + "> outside " + (item ? "the <build>" : "an <object>"));
      Component c;
      c.object = required_index(attrs, "objectid", local);
      if (const char* t = attribute(attrs, "transform")) c.transform = transform(t);
      static const std::string kPath = std::string(kProductionNs) + "|path";
      if (const char* path = attribute(attrs, kPath)) c.path = path;
      (item ? part_.build : object_->components).push_back(std::move(c));
    } else if (local == "build") {
      in_build_ = true;
    } else if (local == "basematerials") {
      start_group(attrs, local);
    } else if (local == "base") {
      add_colour(attrs, "displaycolor", local, "basematerials");
    } else if (local == "model") {
      start_model(attrs);
    }
  } else if (ns == kMaterialNs) {
    if (local == "colorgroup")
      start_group(attrs, local);
    else if (local == "color")
      add_colour(attrs, "color", local, "colorgroup");
  }
}

// The package's parts, read as the build asks for them, and the mesh they build.
class Package {
 public:
  Package(std::string_view bytes, const Limits& limits)
      : zip_(bytes),
        limits_(limits),
        allowed_(std::max(kModelBuiltFloor, kModelBuiltPerByte * bytes.size())) {}

  Mesh build() {
    const Part& root = part(root_name());
    to_mm_ = root.to_mm;
    for (const Component& item : root.build) place(root, item, Mat4{}, 0);
    if (mesh_.triangles.empty())
      throw SceneError(ErrorKind::model, "the 3MF model's build places no triangle");
    if (any_colour_) mesh_.face_colors = std::move(colours_);
    mesh_.crease_deg = kModelCreaseDeg;
    return std::move(mesh_);
  }

 private:
  // The root model part: the target of the package's 3D model relationship (OPC's _rels/.rels).
  std::string root_name() {
    const detail::ZipEntry* rels = zip_.find("_rels/.rels");
    if (!rels)
      throw SceneError(ErrorKind::model, "the 3MF package has no _rels/.rels to name its model part");
    const std::string xml = zip_.read(*rels, limits_);
    std::unique_ptr<XML_ParserStruct, decltype(&XML_ParserFree)> parser(XML_ParserCreateNS(nullptr, '|'),
                                                                        &XML_ParserFree);
    struct Found {
      std::string target;
    } found;
    XML_SetUserData(parser.get(), &found);
    XML_SetStartElementHandler(parser.get(), [](void* data, const char* name, const char** attrs) {
      auto* f = static_cast<Found*>(data);
      if (!f->target.empty() || std::string(kRelationshipsNs) + "|Relationship" != name) return;
      const char *type = nullptr, *target = nullptr;
      for (; *attrs; attrs += 2) {
        if (std::strcmp(attrs[0], "Type") == 0) type = attrs[1];
        if (std::strcmp(attrs[0], "Target") == 0) target = attrs[1];
      }
      if (type && target && kModelRelationship == type) f->target = target;
    });
    XML_SetStartDoctypeDeclHandler(parser.get(), [](void* data, const char*, const char*, const char*, int) {
      static_cast<Found*>(data)->target.clear();
    });
    if (XML_Parse(parser.get(), xml.data(), static_cast<int>(std::min<std::size_t>(xml.size(), INT32_MAX)),
                  1) == XML_STATUS_ERROR)
      throw SceneError(ErrorKind::model,
                       "3MF part _rels/.rels line " + std::to_string(XML_GetCurrentLineNumber(parser.get())) +
                           ": is not well-formed XML: " + XML_ErrorString(XML_GetErrorCode(parser.get())));
    if (found.target.empty())
      throw SceneError(ErrorKind::model,
                       "the 3MF package's _rels/.rels names no 3D model part (a Relationship of type " +
                           std::string(kModelRelationship) + ")");
    return found.target;
  }

  const Part& part(const std::string& name) {
    const std::string key = name.starts_with('/') ? name.substr(1) : name;
    if (const auto it = parts_.find(key); it != parts_.end()) return it->second;
    const detail::ZipEntry* entry = zip_.find(key);
    if (!entry) throw SceneError(ErrorKind::model, "the 3MF package has no part " + key);
    const std::string xml = zip_.read(*entry, limits_);
    return parts_.emplace(key, PartReader(key, limits_).read(xml)).first->second;
  }

  void place(const Part& in, const Component& c, const Mat4& parent, int depth) {
    if (depth > kMaxComponentDepth)
      throw SceneError(ErrorKind::model, "3MF part " + in.name + ": components nest more than " +
                                             std::to_string(kMaxComponentDepth) +
                                             " deep (or refer to themselves)");
    // Components can name an object twice at every level: 32 levels of that is 2^32 placements even of
    // empty objects, so placements are bounded as the vertices they build are.
    if (++placements_ > allowed_)
      throw SceneError(ErrorKind::limit, "the 3MF build places more than " + std::to_string(allowed_) +
                                             " objects and components (components naming others many times)");
    const Part& from = c.path.empty() ? in : part(c.path);
    const auto it = from.objects.find(c.object);
    if (it == from.objects.end())
      throw SceneError(ErrorKind::model,
                       "3MF part " + from.name + ": no object has the id " + std::to_string(c.object));
    const Object& object = it->second;
    const Mat4 to_world = detail::operator*(parent, c.transform);
    if (object.has_mesh) add_mesh(from, object, to_world);
    for (const Component& child : object.components) place(from, child, to_world, depth + 1);
  }

  void add_mesh(const Part& from, const Object& object, const Mat4& to_world) {
    const std::uint64_t vertices = mesh_.positions.size() + object.vertices.size();
    const std::uint64_t faces = mesh_.triangles.size() + object.triangles.size();
    if (vertices > allowed_ || faces > allowed_ ||
        faces > static_cast<std::uint64_t>(limits_.max_model_faces))
      throw SceneError(ErrorKind::limit,
                       "the 3MF build places " + std::to_string(faces) + " triangles and " +
                           std::to_string(vertices) + " vertices, over the limit (" +
                           std::to_string(std::min<std::uint64_t>(allowed_, limits_.max_model_faces)) + ")");
    detail::grow_asked(limits_, mesh_.positions, vertices,
                       [] { return std::string("the 3MF model's vertices"); });
    detail::grow_asked(limits_, mesh_.triangles, faces,
                       [] { return std::string("the 3MF model's triangles"); });
    detail::grow_asked(limits_, colours_, faces, [] { return std::string("the 3MF model's colours"); });
    const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
    // The root part's unit: a part's transforms and positions are in it (the production parts' own unit
    // attributes are the root's in the files slicers write).
    const double s = to_mm_;
    const bool identity = to_world == Mat4{} && s == 1;
    for (const Vec3f& p : object.vertices) {
      const Vec3 w = detail::transform_point(to_world, p);
      mesh_.positions.push_back(identity ? p : Vec3f(Vec3{w.x * s, w.y * s, w.z * s}));
    }
    // A mirroring transform turns the triangles inside out: their winding is flipped back.
    const double det = to_world(0, 0) * (to_world(1, 1) * to_world(2, 2) - to_world(1, 2) * to_world(2, 1)) -
                       to_world(0, 1) * (to_world(1, 0) * to_world(2, 2) - to_world(1, 2) * to_world(2, 0)) +
                       to_world(0, 2) * (to_world(1, 0) * to_world(2, 1) - to_world(1, 1) * to_world(2, 0));
    for (const Triangle& t : object.triangles) {
      mesh_.triangles.push_back(det < 0 ? std::array{base + t.v[0], base + t.v[2], base + t.v[1]}
                                        : std::array{base + t.v[0], base + t.v[1], base + t.v[2]});
      colours_.push_back(
          colour(from, t.pid == kNone ? object.pid : t.pid, t.pid == kNone ? object.pindex : t.p1));
    }
  }

  Rgba8 colour(const Part& from, std::uint32_t pid, std::uint32_t index) {
    if (pid == kNone) return kDefault;
    const auto group = from.colours.find(pid);
    if (group == from.colours.end() || index >= group->second.size())
      return kDefault;  // a texture or other property
    any_colour_ = true;
    return group->second[index];
  }

  static constexpr Rgba8 kDefault{204, 204, 204, 255};  // a model's grey (#cccccc)
  detail::ZipArchive zip_;
  const Limits& limits_;
  std::uint64_t allowed_;
  std::uint64_t placements_ = 0;
  double to_mm_ = 1;
  std::map<std::string, Part> parts_;
  Mesh mesh_;
  std::vector<Rgba8> colours_;
  bool any_colour_ = false;
};

}  // namespace

Mesh parse_3mf(std::string_view bytes, const Limits& limits) {
  return Package(bytes, limits).build();
}

}  // namespace raster
