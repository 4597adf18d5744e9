// glTF 2.0 models through tinygltf: the document (and a GLB's chunks) parsed by tinygltf, with its file
// callbacks resolving only uploaded parts and its image callback keeping the encoded bytes; then every
// mesh of the default scene read into one Mesh under its node's transform, each accessor checked to lie
// within its buffer view and buffer before a byte of it is read.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/budget_ask.h"
#include "base/json_cursor.h"
#include "raster/model.h"

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE        // images are decoded by decode_texture, under the texel budget
#define TINYGLTF_NO_STB_IMAGE_WRITE  // nothing is written
#define TINYGLTF_NO_EXTERNAL_IMAGE   // an image's URI is resolved below, among the uploads
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#include <tiny_gltf.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace raster {
namespace {

[[noreturn]] void gltf_error(const std::string& message, ErrorKind kind = ErrorKind::model) {
  throw SceneError(kind, "glTF: " + message);
}

// A URI's file name, percent-decoded, without folders ("textures/Duck%20Diffuse.png" -> "Duck Diffuse.png").
std::string file_name_of_uri(std::string_view uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    auto hex = [](char c) {
      return c >= '0' && c <= '9' ? c - '0' : (c | 32) >= 'a' && (c | 32) <= 'f' ? (c | 32) - 'a' + 10 : -1;
    };
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  const std::size_t slash = out.find_last_of("/\\");
  return slash == std::string::npos ? out : out.substr(slash + 1);
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return (x >= 'A' && x <= 'Z' ? x + 32 : x) == (y >= 'A' && y <= 'Z' ? y + 32 : y);
         });
}

// An uploaded file by a file name, exactly or else differing only in ASCII case, or in '+' for ' ' (tinygltf
// decodes a buffer's URI as a query string, '+' as a space, before it asks for the file).
const std::string* find_file(const Uploads& files, std::string_view name) {
  if (const auto it = files.find(name); it != files.end()) return &it->second;
  for (const auto& [key, bytes] : files)
    if (iequals(key, name)) return &bytes;
  for (const auto& [key, bytes] : files)
    if (key.size() == name.size() && std::equal(key.begin(), key.end(), name.begin(), [](char x, char y) {
          x = x == '+' ? ' ' : x, y = y == '+' ? ' ' : y;
          return (x >= 'A' && x <= 'Z' ? x + 32 : x) == (y >= 'A' && y <= 'Z' ? y + 32 : y);
        }))
      return &bytes;
  return nullptr;
}

// An uploaded file by a URI as the document writes it (percent-encoded, perhaps with folders).
const std::string* find_upload(const Uploads& files, const std::string& uri) {
  return find_file(files, file_name_of_uri(uri));
}

// A path as tinygltf passes it to the file callbacks: already decoded; only its folders are dropped.
std::string_view base_name(std::string_view path) {
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string_view::npos ? path : path.substr(slash + 1);
}

// What tinygltf's callbacks may copy: the bytes of the request (the model and its uploads) once over. A
// document can name one large upload or buffer view from many buffers or images; each copy is counted.
struct CopyBudget {
  const tinygltf::Model* model;  ///< the model being read, for an image's buffer view
  const Uploads* files;
  std::uint64_t bytes_left;  ///< bytes, what further copies may take
  bool take(std::uint64_t n, std::string* err) {
    if (n > bytes_left) {
      if (err) *err += "the document copies its buffers or images more often than its bytes allow\n";
      return false;
    }
    bytes_left -= n;
    return true;
  }
};

std::string upload_names(const Uploads& files) {
  std::string names;
  for (const auto& [key, bytes] : files) names += (names.empty() ? "\"" : ", \"") + key + "\"";
  return names.empty() ? "nothing else" : names;
}

// tinygltf's file system: the uploads, read-only.
bool upload_exists(const std::string& path, void* budget) {
  return find_file(*static_cast<CopyBudget*>(budget)->files, base_name(path)) != nullptr;
}
std::string same_path(const std::string& path, void*) {
  return path;
}
bool read_upload(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* budget) {
  auto& b = *static_cast<CopyBudget*>(budget);
  const std::string* bytes = find_file(*b.files, base_name(path));
  if (!bytes) {
    if (err) *err += "no uploaded part named \"" + std::string(base_name(path)) + "\"\n";
    return false;
  }
  if (!b.take(bytes->size(), err)) return false;
  out->assign(bytes->begin(), bytes->end());
  return true;
}
bool write_nothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

// tinygltf's image callback: the encoded bytes are kept (width 0 marks them so) and decoded only if a
// material uses the image. Called for data: URIs and for buffer views, whose range tinygltf does not check.
bool keep_image(tinygltf::Image* image, const int, std::string* err, std::string*, int, int,
                const unsigned char* bytes, int size, void* budget) {
  auto& b = *static_cast<CopyBudget*>(budget);
  const tinygltf::Model* model = b.model;
  if (image->bufferView >= 0) {
    const tinygltf::BufferView& view = model->bufferViews[static_cast<std::size_t>(image->bufferView)];
    const std::size_t buffer_size = model->buffers[static_cast<std::size_t>(view.buffer)].data.size();
    if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset) {
      if (err) *err += "an image's buffer view lies outside its buffer\n";
      return false;
    }
  }
  if (size < 0 || !b.take(static_cast<std::uint64_t>(size), err)) return false;
  image->image.assign(bytes, bytes + size);
  image->width = image->height = 0;
  return true;
}

// Room for `more` elements, growing geometrically: a model of many primitives must not reallocate its arrays
// once per primitive (reserving exactly each time copies them quadratically often).
template <typename T>
void make_room(std::vector<T>& v, std::size_t more) {
  if (v.capacity() - v.size() < more) v.reserve(std::max(v.size() + more, 2 * v.capacity()));
}

// --- Before tinygltf: what the document would make it build -------------------------------------------

// tinygltf makes a struct per element of each top-level array and a Value (or a struct of similar size)
// for every other object and array, extras included; three bytes of text ("{},") can ask for a kilobyte.
// Every value also costs a node of the JSON library's tree, and one inside "extras" or "extensions" becomes
// a Value too: `"extras": [0,0,0,...]` asks for ~170 bytes a value from two bytes of text. Its structures are
// bounded by this many bytes, counted from the text before it runs.
constexpr std::uint64_t kMaxStructureBytes = 256ull << 20;
// Mesh primitives drawn (a mesh's primitives once for each node that names it): each costs a few
// microseconds even when empty, so this bounds a model's reading to seconds, far above real scenes'
// thousands.
constexpr std::size_t kMaxDrawnPrimitives = 1 << 20;

std::uint64_t struct_bytes(std::string_view array) {
  static constexpr std::pair<std::string_view, std::size_t> kSizes[] = {
      {"accessors", sizeof(tinygltf::Accessor)}, {"animations", sizeof(tinygltf::Animation)},
      {"buffers", sizeof(tinygltf::Buffer)},     {"bufferViews", sizeof(tinygltf::BufferView)},
      {"cameras", sizeof(tinygltf::Camera)},     {"images", sizeof(tinygltf::Image)},
      {"materials", sizeof(tinygltf::Material)}, {"meshes", sizeof(tinygltf::Mesh)},
      {"nodes", sizeof(tinygltf::Node)},         {"samplers", sizeof(tinygltf::Sampler)},
      {"scenes", sizeof(tinygltf::Scene)},       {"skins", sizeof(tinygltf::Skin)},
      {"textures", sizeof(tinygltf::Texture)}};
  for (const auto& [name, size] : kSizes)
    if (name == array) return size;
  return 0;
}

constexpr std::uint64_t kContainerBytes = std::max(
    {sizeof(tinygltf::Value) + 64, sizeof(tinygltf::Primitive) + 64, sizeof(tinygltf::TextureInfo) + 64});
constexpr std::uint64_t kScalarBytes = 16;  // a number, string or literal in the JSON library's tree
constexpr std::uint64_t kValueBytes = sizeof(tinygltf::Value) + kScalarBytes;  // one under extras/extensions

bool holds_values(std::string_view key) {
  return key == "extras" || key == "extensions";
}

struct Shape {
  std::uint64_t structure_bytes = 0;  ///< what tinygltf would build, estimated from above
  std::uint64_t buffer_bytes = 0;     ///< the buffers' byteLength, summed
  int buffers_without_uri = 0;        ///< a GLB's chunk may back one
  std::string missing;                ///< the file name of the first buffer URI no upload holds
};

// Passes over one value, adding up what tinygltf would build for it (`values`: the value lies under
// "extras" or "extensions"); without recursion (the cursor bounds the depth).
std::uint64_t structure_bytes(JsonCursor& in, bool values) {
  using Kind = JsonCursor::Kind;
  struct Open {
    bool object;  ///< else an array
    bool values;  ///< its members become Values
  };
  std::vector<Open> open;  // the open containers, innermost last
  std::uint64_t bytes = 0;
  auto enter = [&](bool value) -> bool {  // reads a value's start: true when it opened a non-empty container
    const Kind k = in.peek();
    if (k != Kind::object && k != Kind::array) {
      bytes += value ? kValueBytes : kScalarBytes;
      in.skip();
      return false;
    }
    bytes += kContainerBytes;
    const bool object = k == Kind::object;
    if (!(object ? in.object_begin() : in.array_begin())) return false;
    open.push_back({object, value});
    return true;
  };
  // Whether the next member (its key read here) or element becomes a Value.
  auto next_is_value = [&] {
    const Open& o = open.back();
    return o.object ? holds_values(in.key()) || o.values : o.values;
  };
  if (!enter(values)) return bytes;
  while (!open.empty()) {
    if (enter(next_is_value())) continue;
    while (!open.empty()) {  // the value ended: on to the next member or element, or close
      if (open.back().object ? in.object_next() : in.array_next()) break;
      open.pop_back();
    }
  }
  return bytes;
}

Shape shape_of(std::string_view json, int max_depth, const Uploads& files) {
  using Kind = JsonCursor::Kind;
  JsonCursor in(json, max_depth);
  Shape shape;
  if (in.peek() != Kind::object) in.fail("expected a glTF document, an object");
  for (bool more = in.object_begin(); more; more = in.object_next()) {
    const std::string_view key = in.key();
    const std::uint64_t size = struct_bytes(key);
    if (size == 0 || in.peek() != Kind::array) {
      shape.structure_bytes += structure_bytes(in, holds_values(key));
      continue;
    }
    const bool buffers = key == "buffers";
    for (bool item = in.array_begin(); item; item = in.array_next()) {
      if (!buffers || in.peek() != Kind::object) {
        shape.structure_bytes += size + structure_bytes(in, false);
        continue;
      }
      shape.structure_bytes += size;
      bool uri = false;
      for (bool member = in.object_begin(); member; member = in.object_next()) {
        const std::string_view field = in.key();
        if (field == "byteLength" && in.peek() == Kind::number) {
          const double length = in.number();
          shape.buffer_bytes += length > 0 && length < 1e18 ? static_cast<std::uint64_t>(length) : 0;
        } else if (field == "uri" && in.peek() == Kind::string) {
          uri = true;
          const std::string name(in.string());
          if (shape.missing.empty() && !name.starts_with("data:") && !find_upload(files, name))
            shape.missing = file_name_of_uri(name);
        } else {
          shape.structure_bytes += structure_bytes(in, holds_values(field));
        }
      }
      shape.buffers_without_uri += !uri;
    }
  }
  in.finish();
  return shape;
}

// The GLB container: a 12-byte header, a JSON chunk and an optional BIN chunk, each within the file.
// (tinygltf 2.7.0 leaves the BIN chunk's 8-byte head out of its bounds check and could copy 8 bytes past
// the end of the input.) Returns the JSON chunk.
std::string_view glb_json(std::string_view bytes) {
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(bytes[at + k]);
    return std::uint64_t{v};
  };
  if (bytes.size() < 20)
    gltf_error("the GLB is " + std::to_string(bytes.size()) + " bytes, shorter than its headers");
  const std::uint64_t length = u32(8), json = u32(12);
  if (length > bytes.size())
    gltf_error("the GLB's header says " + std::to_string(length) + " bytes; the file has " +
               std::to_string(bytes.size()));
  if (bytes.substr(16, 4) != "JSON" || 20 + json > length)
    gltf_error("the GLB's first chunk is not a JSON chunk within the file");
  if (json % 4 != 0)  // tinygltf would look for the binary chunk right after it, where no chunk starts
    gltf_error("the GLB's JSON chunk is " + std::to_string(json) +
               " bytes, not padded to a multiple of 4 as GLB requires");
  const std::uint64_t bin = 20 + json;
  if (bin + 8 <= length && bin + 8 + u32(bin) > length)
    gltf_error("the GLB's binary chunk of " + std::to_string(u32(bin)) + " bytes runs past the file's " +
               std::to_string(length));
  return bytes.substr(20, static_cast<std::size_t>(json));
}

double srgb_of_linear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
}

std::uint8_t unit_byte(double v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
}

using Mat = std::array<double, 16>;  // column-major, as glTF stores it
constexpr Mat kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat multiply(const Mat& a, const Mat& b) {
  Mat r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
  return r;
}

Mat local_matrix(const tinygltf::Node& node) {
  Mat m = kIdentity;
  if (node.matrix.size() == 16) {
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  // T * R * S
  double s[3] = {1, 1, 1}, q[4] = {0, 0, 0, 1}, t[3] = {0, 0, 0};
  if (node.scale.size() == 3) std::copy(node.scale.begin(), node.scale.end(), s);
  if (node.rotation.size() == 4) std::copy(node.rotation.begin(), node.rotation.end(), q);
  if (node.translation.size() == 3) std::copy(node.translation.begin(), node.translation.end(), t);
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                       2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                       2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) m[c * 4 + row] = r[c * 3 + row] * s[c];
  m[12] = t[0], m[13] = t[1], m[14] = t[2];
  return m;
}

// One accessor's elements as doubles, after checking that every byte it names lies in its buffer.
class AccessorView {
 public:
  AccessorView(const tinygltf::Model& model, int index, const std::string& what) : what_(what) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
      gltf_error(what + " names accessor " + std::to_string(index) + ", which does not exist");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    what_ = what + " (accessor " + std::to_string(index) + ")";
    if (a.sparse.isSparse) gltf_error(what_ + " is sparse; rasterd reads only dense accessors");
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
      gltf_error(what_ + " has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
      gltf_error(what_ + "'s buffer view names no buffer");
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    component_ = a.componentType;
    const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    components_ = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (size <= 0 || components_ <= 0 || components_ > 4) gltf_error(what_ + " has an unknown type");
    normalized_ = a.normalized;
    count_ = a.count;
    const std::uint64_t element = static_cast<std::uint64_t>(size) * components_;
    stride_ = view.byteStride ? view.byteStride : element;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
      gltf_error(what_ + "'s buffer view (bytes " + std::to_string(view.byteOffset) + " + " +
                 std::to_string(view.byteLength) + ") lies outside its buffer of " +
                 std::to_string(buffer.size()) + " bytes");
    // count x stride within the view, in 64 bits: count, offset and stride come from the document and
    // can be anything, so each is bounded by the view before they are multiplied.
    if (a.byteOffset > view.byteLength || stride_ > view.byteLength + element)
      gltf_error(what_ + "'s byte offset or stride lies outside its buffer view of " +
                 std::to_string(view.byteLength) + " bytes");
    const std::uint64_t end = count_ == 0 ? 0 : a.byteOffset + stride_ * (count_ - 1) + element;
    if (count_ > view.byteLength || end > view.byteLength || (count_ > 0 && stride_ < element))
      gltf_error(what_ + " declares " + std::to_string(count_) + " elements of " + std::to_string(element) +
                 " bytes, which do not fit in its buffer view of " + std::to_string(view.byteLength) +
                 " bytes");
    data_ = buffer.data() + view.byteOffset + a.byteOffset;
  }

  std::size_t count() const { return count_; }
  int components() const { return components_; }
  const std::string& what() const { return what_; }

  double get(std::size_t i, int c) const {
    const unsigned char* p = data_ + i * stride_;
    switch (component_) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return load<float>(p, c);
      case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return load<double>(p, c);
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return norm(load<std::int8_t>(p, c), 127.0, true);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return norm(load<std::uint8_t>(p, c), 255.0, false);
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return norm(load<std::int16_t>(p, c), 32767.0, true);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return norm(load<std::uint16_t>(p, c), 65535.0, false);
      case TINYGLTF_COMPONENT_TYPE_INT:
        return load<std::int32_t>(p, c);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return norm(load<std::uint32_t>(p, c), 4294967295.0, false);
    }
    return 0;
  }
  // f(i, x, y, z) for each element of a VEC3 accessor, the component type dispatched once, not per value.
  template <typename F>
  void each_vec3(F&& f) const {
    if (component_ == TINYGLTF_COMPONENT_TYPE_FLOAT && !normalized_) {
      for (std::size_t i = 0; i < count_; ++i) {
        float v[3];
        std::memcpy(v, data_ + i * stride_, sizeof v);
        f(i, double{v[0]}, double{v[1]}, double{v[2]});
      }
      return;
    }
    for (std::size_t i = 0; i < count_; ++i) f(i, get(i, 0), get(i, 1), get(i, 2));
  }

  // Every index, offset by `base`, into `out`; the first one >= `limit` throws, naming its element.
  void indices(std::uint32_t base, std::uint64_t limit, std::vector<std::uint32_t>& out) const {
    out.resize(count_);
    read_indices(base, limit, [&](auto at) {
      for (std::size_t i = 0; i < count_; ++i) out[i] = at(i);
    });
  }

  // The same, three at a time, straight into `out`'s count_ / 3 triangles (a leftover index is unused).
  void triangles(std::uint32_t base, std::uint64_t limit, std::array<std::uint32_t, 3>* out) const {
    read_indices(base, limit, [&](auto at) {
      for (std::size_t t = 0; t < count_ / 3; ++t) out[t] = {at(3 * t), at(3 * t + 1), at(3 * t + 2)};
    });
  }

 private:
  // Hands `copy` a function from an element's position to its index plus `base`, with the component type
  // and the stride fixed (packed indices, as writers store them, get a constant stride the compiler can
  // use), while the largest index read is kept: it is checked once at the end, and only then is the bad
  // one looked for, for its element. The copy itself has no branch per index.
  template <typename Copy>
  void read_indices(std::uint32_t base, std::uint64_t limit, Copy&& copy) const {
    auto all = [&]<typename T>(T) {
      auto index_at = [&](std::size_t i, std::size_t stride) {
        T v;
        std::memcpy(&v, data_ + i * stride, sizeof v);
        return v;
      };
      T largest = 0;
      auto with_stride = [&](std::size_t stride) {
        copy([&, stride](std::size_t i) {
          const T v = index_at(i, stride);
          largest = std::max(largest, v);
          return static_cast<std::uint32_t>(base + v);  // wraps only past the vertices, which throws below
        });
      };
      stride_ == sizeof(T) ? with_stride(sizeof(T)) : with_stride(stride_);
      if (count_ == 0 || largest < limit) return;
      for (std::size_t i = 0; i < count_; ++i)
        if (const T v = index_at(i, stride_); v >= limit)
          gltf_error(what_ + " element " + std::to_string(i) + " is " + std::to_string(v) +
                     ", but the primitive has " + std::to_string(limit) + " vertices");
    };
    switch (component_) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return all(std::uint8_t{});
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return all(std::uint16_t{});
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return all(std::uint32_t{});
    }
    gltf_error(what_ + " holds indices of a type that is not an unsigned integer");
  }

  template <typename T>
  static double load(const unsigned char* p, int c) {
    T v;
    std::memcpy(&v, p + c * sizeof(T), sizeof(T));  // glTF buffers are little-endian, as this machine
    return static_cast<double>(v);
  }
  double norm(double v, double max, bool is_signed) const {
    if (!normalized_) return v;
    return is_signed ? std::max(v / max, -1.0) : v / max;
  }

  std::string what_;
  const unsigned char* data_ = nullptr;
  std::uint64_t stride_ = 0;
  std::size_t count_ = 0;
  int component_ = 0, components_ = 0;
  bool normalized_ = false;
};

class Reader {
 public:
  Reader(const tinygltf::Model& model, const Limits& limits, const Uploads& files)
      : model_(model), limits_(limits), files_(files) {}

  Mesh read() {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (static_cast<std::size_t>(s) >= model_.scenes.size())
        gltf_error("the default scene " + std::to_string(s) + " does not exist");
      roots = model_.scenes[static_cast<std::size_t>(s)].nodes;
    } else if (model_.nodes.empty()) {  // no scenes and no nodes: every mesh as it is
      for (std::size_t i = 0; i < model_.meshes.size(); ++i) add_mesh(static_cast<int>(i), kIdentity);
    } else {  // no scenes: every node that is no other node's child
      std::vector<bool> child(model_.nodes.size());
      for (const tinygltf::Node& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && static_cast<std::size_t>(c) < child.size()) child[static_cast<std::size_t>(c)] = true;
      for (std::size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(static_cast<int>(i));
    }
    visited_.assign(model_.nodes.size(), false);
    // Depth first without recursion: a document's nesting cannot exhaust the stack.
    std::vector<std::pair<int, Mat>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, kIdentity});
    while (!stack.empty()) {
      auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size())
        gltf_error("a scene or node names node " + std::to_string(index) + ", which does not exist");
      if (visited_[static_cast<std::size_t>(index)])
        gltf_error("node " + std::to_string(index) + " is reached twice; a scene's nodes form trees");
      visited_[static_cast<std::size_t>(index)] = true;
      const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
      const Mat world = multiply(parent, local_matrix(node));
      if (node.mesh >= 0) add_mesh(node.mesh, world);
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.push_back({*c, world});
    }
    if (mesh_.triangles.empty() && mesh_.segments.empty())
      gltf_error(
          "the default scene has no triangles or lines to draw (rasterd draws faces and lines, not "
          "points)");
    if (!textured_) {
      mesh_.textures.clear(), mesh_.uvs.clear(), mesh_.face_textures.clear();
    } else {
      mesh_.uvs.resize(mesh_.positions.size(), {0, 0});
      mesh_.uv_triangles = mesh_.triangles;
    }
    // One colour for the whole mesh when every vertex has the same (COLOR_0 of one value).
    if (!one_colour_ && std::all_of(mesh_.colors.begin(), mesh_.colors.end(),
                                    [&](Rgba8 c) { return c == mesh_.colors.front(); }))
      mesh_.colors.erase(mesh_.colors.begin() + 1, mesh_.colors.end());
    if (any_lit_ == false && any_unlit_) mesh_.shading = Shading::unlit;
    finish_normals();
    return std::move(mesh_);
  }

 private:
  void add_mesh(int index, const Mat& m) {
    if (static_cast<std::size_t>(index) >= model_.meshes.size())
      gltf_error("a node names mesh " + std::to_string(index) + ", which does not exist");
    // Normals go through the inverse transpose of the upper 3x3 (a, b, c / d, e, f / g, h, k, by rows): the
    // cofactor matrix, which is det x that, times the sign of det. A mirroring transform turns the winding.
    const double a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], k = m[10];
    const double det = a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
    const bool mirrored = det < 0;
    const double sign = mirrored ? -1 : 1;
    const double n[9] = {sign * (e * k - f * h), sign * (f * g - d * k), sign * (d * h - e * g),
                         sign * (c * h - b * k), sign * (a * k - c * g), sign * (b * g - a * h),
                         sign * (b * f - c * e), sign * (c * d - a * f), sign * (a * e - b * d)};
    const auto& primitives = model_.meshes[static_cast<std::size_t>(index)].primitives;
    // Nodes times their meshes' primitives: 150,000 nodes naming one mesh of 150,000 primitives are a few
    // megabytes of text and 2e10 primitives to read.
    drawn_primitives_ += primitives.size();
    if (drawn_primitives_ > kMaxDrawnPrimitives)
      throw SceneError(ErrorKind::limit,
                       "glTF: the default scene draws more than " + std::to_string(kMaxDrawnPrimitives) +
                           " mesh primitives (each node draws every primitive of its mesh)");
    for (std::size_t pi = 0; pi < primitives.size(); ++pi) {
      const tinygltf::Primitive& p = primitives[pi];
      if (p.mode == TINYGLTF_MODE_POINTS) continue;  // rasterd draws faces and lines
      const std::string where = "mesh " + std::to_string(index) + " primitive " + std::to_string(pi);
      const auto pos_it = p.attributes.find("POSITION");
      if (pos_it == p.attributes.end()) gltf_error(where + " has no POSITION");
      const AccessorView positions(model_, pos_it->second, where + " POSITION");
      if (positions.components() != 3) gltf_error(positions.what() + " is not VEC3");
      const std::size_t base = mesh_.positions.size();
      if (base + positions.count() > 3 * static_cast<std::size_t>(limits_.max_obj_faces) + 3)
        throw SceneError(ErrorKind::limit, "the model has more than " +
                                               std::to_string(3 * limits_.max_obj_faces) + " vertices");
      detail::stop_if_expired(limits_);
      detail::reserve(limits_, cost::kGltfPerVertex * static_cast<std::int64_t>(positions.count()), [&] {
        return positions.what() + "'s " + std::to_string(positions.count()) + " vertices";
      });
      make_room(mesh_.positions, positions.count());
      mesh_.positions.resize(base + positions.count());
      Vec3* out = mesh_.positions.data() + base;
      // Every coordinate finite and within +-2^128 (what the renderer takes): checked once, without a branch
      // (or a chain of additions) per vertex, and only then is the bad one looked for.
      bool in_range = true;
      auto put = [&](std::size_t i, const Vec3& w) {
        in_range &= (std::fabs(w.x) <= kMaxCoordinate) & (std::fabs(w.y) <= kMaxCoordinate) &
                    (std::fabs(w.z) <= kMaxCoordinate);
        out[i] = w;
      };
      if (m == kIdentity)  // most nodes: no transform to apply
        positions.each_vec3([&](std::size_t i, double x, double y, double z) { put(i, {x, y, z}); });
      else
        positions.each_vec3([&](std::size_t i, double x, double y, double z) {
          put(i, {m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13],
                  m[2] * x + m[6] * y + m[10] * z + m[14]});
        });
      if (!in_range)
        for (std::size_t i = 0; i < positions.count(); ++i)
          if (!(std::fabs(out[i].x) <= kMaxCoordinate && std::fabs(out[i].y) <= kMaxCoordinate &&
                std::fabs(out[i].z) <= kMaxCoordinate))
            gltf_error(positions.what() + " element " + std::to_string(i) +
                       " is not a finite point within +-2^128 (after its node's transform)");
      const std::size_t count = positions.count();
      const bool has_normals = add_normals(p, where, count, n);
      const Material material = material_of(p.material, where);
      add_colours(p, where, count, material.colour, material.blend);
      add_uvs(p, where, count, material);

      // The primitive's corner order: its indices, or 0..count-1.
      const std::size_t first_triangle = mesh_.triangles.size();
      if (p.indices >= 0 && p.mode == TINYGLTF_MODE_TRIANGLES) {  // most meshes: indices are the triangles
        const AccessorView indices(model_, p.indices, where + " indices");
        add_triangles(indices.count() / 3, mirrored, [&](std::array<std::uint32_t, 3>* out) {
          indices.triangles(static_cast<std::uint32_t>(base), count, out);
        });
      } else {
        // The primitive's corner order: its indices, or 0..count-1.
        std::vector<std::uint32_t>& corners = corners_;
        if (p.indices >= 0) {
          AccessorView(model_, p.indices, where + " indices")
              .indices(static_cast<std::uint32_t>(base), count, corners);
        } else {
          corners.resize(count);
          for (std::size_t i = 0; i < count; ++i) corners[i] = static_cast<std::uint32_t>(base + i);
        }
        add_faces(p.mode, corners, mirrored, where);
      }
      if (!has_normals) without_normals_.push_back({first_triangle, mesh_.triangles.size()});
    }
  }

  // The primitive's NORMALs, turned with its node, after those of earlier primitives (zeros where they had
  // none); false when it has none.
  bool add_normals(const tinygltf::Primitive& p, const std::string& where, std::size_t count,
                   const double* n) {
    const auto it = p.attributes.find("NORMAL");
    if (it == p.attributes.end()) return false;
    const AccessorView normals(model_, it->second, where + " NORMAL");
    if (normals.components() != 3 || normals.count() != count) return false;
    const std::size_t base = mesh_.positions.size() - count;
    make_room(mesh_.normals, base + count - mesh_.normals.size());
    mesh_.normals.resize(base);
    normals.each_vec3([&](std::size_t, double x, double y, double z) {
      mesh_.normals.push_back(
          {n[0] * x + n[1] * y + n[2] * z, n[3] * x + n[4] * y + n[5] * z, n[6] * x + n[7] * y + n[8] * z});
    });
    return true;
  }

  // glTF draws a primitive without normals flat. A mesh with none is shaded flat; one where only some
  // primitives have normals gets a face normal for each triangle of the others.
  void finish_normals() {
    if (mesh_.normals.empty()) {
      if (mesh_.shading == Shading::smooth) mesh_.shading = Shading::flat;
      return;
    }
    mesh_.normals.resize(mesh_.positions.size());
    mesh_.normal_triangles = mesh_.triangles;
    const auto& pos = mesh_.positions;
    for (const auto& [first, end] : without_normals_)
      for (std::size_t t = first; t < end; ++t) {
        const auto& tri = mesh_.triangles[t];
        const Vec3 a = pos[tri[0]], b = pos[tri[1]], c = pos[tri[2]];
        const Vec3 u{b.x - a.x, b.y - a.y, b.z - a.z}, v{c.x - a.x, c.y - a.y, c.z - a.z};
        const auto k = static_cast<std::uint32_t>(mesh_.normals.size());
        mesh_.normals.push_back({u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x});
        mesh_.normal_triangles[t] = {k, k, k};
      }
  }

  void add_colours(const tinygltf::Primitive& p, const std::string& where, std::size_t count,
                   const std::array<double, 4>& factor, bool blend) {
    const auto it = p.attributes.find("COLOR_0");
    std::optional<AccessorView> colours;
    if (it != p.attributes.end()) {
      colours.emplace(model_, it->second, where + " COLOR_0");
      if ((colours->components() != 3 && colours->components() != 4) || colours->count() != count)
        gltf_error(colours->what() + " is not one VEC3 or VEC4 per vertex");
    }
    // glTF colours are linear; the 8-bit colours lit here are sRGB-encoded, as texels are.
    auto encoded = [](const double* c) -> Rgba8 {
      return {unit_byte(srgb_of_linear(c[0])), unit_byte(srgb_of_linear(c[1])),
              unit_byte(srgb_of_linear(c[2])), unit_byte(c[3])};
    };
    const std::size_t base = mesh_.positions.size() - count;
    if (!colours) {  // one colour for the primitive, encoded once, and stored once while the mesh has one
      const Rgba8 c = encoded(factor.data());
      if (one_colour_ && (base == 0 || mesh_.colors.front() == c)) {
        mesh_.colors.assign(1, c);
        return;
      }
      colour_each_vertex(base);
      mesh_.colors.insert(mesh_.colors.end(), count, c);
      return;
    }
    colour_each_vertex(base);
    make_room(mesh_.colors, count);
    for (std::size_t i = 0; i < count; ++i) {
      double c[4] = {factor[0], factor[1], factor[2], factor[3]};
      for (int k = 0; k < colours->components(); ++k) c[k] *= colours->get(i, k);
      if (!blend) c[3] = 1;  // an opaque material is opaque whatever its vertices' alpha
      mesh_.colors.push_back(encoded(c));
    }
  }

  // From one colour for the mesh to one for each of the `vertices` read so far.
  void colour_each_vertex(std::size_t vertices) {
    if (!one_colour_) return;
    one_colour_ = false;
    if (vertices == 0) return;
    const Rgba8 c = mesh_.colors.front();
    mesh_.colors.assign(vertices, c);
  }

  struct Material {
    std::array<double, 4> colour{0.8, 0.8, 0.8, 1};  ///< linear RGBA: baseColorFactor, or the default grey
    std::int32_t texture = -1;                       ///< index into mesh_.textures, or -1
    int texcoord = 0;                                ///< which TEXCOORD_n the texture reads
    bool blend = false;                              ///< alphaMode BLEND: alpha is kept; else opaque
  };

  /// What a material does with its texture's alpha: OPAQUE ignores it, MASK keeps a texel where its alpha
  /// times the factor's reaches alphaCutoff and drops it otherwise, BLEND keeps it.
  struct TexelAlpha {
    enum Mode : std::uint8_t { opaque, mask, blend } mode = opaque;
    double cutoff = 0;  ///< mask: the texel alpha (0..1) at and above which a texel is kept
    friend auto operator<=>(const TexelAlpha&, const TexelAlpha&) = default;
  };

  Material material_of(int index, const std::string& where) {
    Material out;
    if (index < 0) {
      out.colour = {0.6038, 0.6038, 0.6038, 1};  // linear of sRGB 204: the grey OBJ models get
      any_lit_ = true;
      return out;
    }
    if (static_cast<std::size_t>(index) >= model_.materials.size())
      gltf_error(where + " names material " + std::to_string(index) + ", which does not exist");
    const tinygltf::Material& mat = model_.materials[static_cast<std::size_t>(index)];
    const auto& pbr = mat.pbrMetallicRoughness;
    for (std::size_t k = 0; k < 4 && k < pbr.baseColorFactor.size(); ++k)
      out.colour[k] = pbr.baseColorFactor[k];
    out.blend = mat.alphaMode == "BLEND";
    TexelAlpha alpha;
    if (out.blend)
      alpha.mode = TexelAlpha::blend;
    else if (mat.alphaMode == "MASK" && out.colour[3] > 0)
      alpha = {TexelAlpha::mask, mat.alphaCutoff / out.colour[3]};
    if (!out.blend) out.colour[3] = 1;
    (mat.extensions.count("KHR_materials_unlit") ? any_unlit_ : any_lit_) = true;
    if (pbr.baseColorTexture.index >= 0) {
      out.texture = texture_of(pbr.baseColorTexture.index, alpha, where);
      out.texcoord = pbr.baseColorTexture.texCoord;
    }
    return out;
  }

  // The texture's index in mesh_.textures, decoded once for each way a material takes its alpha.
  std::int32_t texture_of(int index, TexelAlpha alpha, const std::string& where) {
    if (static_cast<std::size_t>(index) >= model_.textures.size())
      gltf_error(where + "'s material names texture " + std::to_string(index) + ", which does not exist");
    const tinygltf::Texture& t = model_.textures[static_cast<std::size_t>(index)];
    if (t.source < 0) return -1;  // an extension's image (KTX2, WebP) rasterd cannot decode: untextured
    if (static_cast<std::size_t>(t.source) >= model_.images.size())
      gltf_error("texture " + std::to_string(index) + " names image " + std::to_string(t.source) +
                 ", which does not exist");
    const auto [cached, is_new] = textures_.try_emplace({t.source, alpha}, -1);
    if (!is_new) return cached->second;
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(t.source)];
    std::string_view bytes(reinterpret_cast<const char*>(image.image.data()), image.image.size());
    std::string name = image.name.empty() ? "image " + std::to_string(t.source) : image.name;
    if (image.bufferView < 0 && !image.uri.empty() && image.uri.rfind("data:", 0) != 0) {
      const std::string* upload = find_upload(files_, image.uri);
      name = file_name_of_uri(image.uri);
      if (!upload)
        gltf_error("the model asks for image \"" + name +
                   "\", which was not sent; sent: " + upload_names(files_) +
                   ". Send it as a multipart part with that file name (curl -F 'file=@" + name + "')");
      bytes = *upload;
    }
    Texture texture = decode_texture(bytes, name, texel_budget_);
    texel_budget_ -= std::int64_t{texture.width} * texture.height;
    if (t.sampler >= 0 && static_cast<std::size_t>(t.sampler) < model_.samplers.size())
      texture.clamp =
          model_.samplers[static_cast<std::size_t>(t.sampler)].wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    if (alpha.mode != TexelAlpha::blend)
      for (std::size_t k = 3; k < texture.rgba.size(); k += 4)
        texture.rgba[k] = alpha.mode == TexelAlpha::opaque || texture.rgba[k] >= alpha.cutoff * 255 ? 255 : 0;
    cached->second = static_cast<std::int32_t>(mesh_.textures.size());
    mesh_.textures.push_back(std::move(texture));
    return cached->second;
  }

  void add_uvs(const tinygltf::Primitive& p, const std::string& where, std::size_t count,
               const Material& material) {
    // Once a primitive is textured, one uv per position and a texture per triangle: (0, 0) and -1 where a
    // primitive has none. Before that, neither is kept.
    const std::size_t base = mesh_.positions.size() - count;
    primitive_texture_ = material.texture;
    const auto it = p.attributes.find("TEXCOORD_" + std::to_string(material.texcoord));
    if (material.texture >= 0 && it == p.attributes.end()) primitive_texture_ = -1;
    if (primitive_texture_ >= 0 && !textured_) {
      textured_ = true;
      mesh_.face_textures.assign(mesh_.triangles.size(), -1);
    }
    if (textured_) mesh_.uvs.resize(mesh_.positions.size(), {0, 0});
    if (primitive_texture_ < 0) return;
    const AccessorView uv(model_, it->second, where + " TEXCOORD_" + std::to_string(material.texcoord));
    if (uv.components() != 2 || uv.count() != count) gltf_error(uv.what() + " is not one VEC2 per vertex");
    for (std::size_t i = 0; i < count; ++i) {
      const double u = uv.get(i, 0), v = uv.get(i, 1);
      if (!(std::fabs(u) <= 1e30 && std::fabs(v) <= 1e30))  // NaN, infinite, or out of a float's range
        gltf_error(uv.what() + " element " + std::to_string(i) + " is not a finite coordinate");
      mesh_.uvs[base + i] = {static_cast<float>(u), static_cast<float>(1 - v)};  // glTF's v runs down
    }
  }

  // `more` triangles to come: refused over the face limit, else room made for them.
  void make_room_for_triangles(std::size_t more) {
    if (mesh_.triangles.size() + more > static_cast<std::size_t>(limits_.max_obj_faces))
      throw SceneError(ErrorKind::limit,
                       "the model has more than " + std::to_string(limits_.max_obj_faces) + " faces");
    detail::reserve(limits_, cost::kGltfPerTriangle * static_cast<std::int64_t>(more),
                    [&] { return std::to_string(more) + " more triangles"; });
    make_room(mesh_.triangles, more);
    if (textured_) make_room(mesh_.face_textures, more);
  }

  // `count` triangles that `fill` writes at once (the common case, in straight loops rather than one call a
  // triangle), wound back where the node mirrors.
  template <typename Fill>
  void add_triangles(std::size_t count, bool mirrored, Fill&& fill) {
    const std::size_t first = mesh_.triangles.size();
    make_room_for_triangles(count);
    mesh_.triangles.resize(first + count);
    std::array<std::uint32_t, 3>* t = mesh_.triangles.data() + first;
    fill(t);
    if (mirrored)
      for (std::size_t i = 0; i < count; ++i) std::swap(t[i][1], t[i][2]);
    if (textured_) mesh_.face_textures.insert(mesh_.face_textures.end(), count, primitive_texture_);
  }

  void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, bool mirrored) {
    mesh_.triangles.push_back(mirrored ? std::array{a, c, b} : std::array{a, b, c});
    if (textured_) mesh_.face_textures.push_back(primitive_texture_);
  }

  void add_faces(int mode, const std::vector<std::uint32_t>& v, bool mirrored, const std::string& where) {
    const std::size_t n = v.size();
    switch (mode) {
      case TINYGLTF_MODE_TRIANGLES:
        add_triangles(n / 3, mirrored, [&](std::array<std::uint32_t, 3>* t) {
          for (std::size_t i = 0; i < n / 3; ++i) t[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
        });
        break;
      case TINYGLTF_MODE_TRIANGLE_STRIP:  // every other triangle turned back to the strip's winding
        make_room_for_triangles(n < 2 ? 0 : n - 2);
        for (std::size_t i = 0; i + 2 < n; ++i)
          add_triangle(v[i], v[i + 1 + (i & 1)], v[i + 2 - (i & 1)], mirrored);
        break;
      case TINYGLTF_MODE_TRIANGLE_FAN:
        make_room_for_triangles(n < 2 ? 0 : n - 2);
        for (std::size_t i = 1; i + 1 < n; ++i) add_triangle(v[0], v[i], v[i + 1], mirrored);
        break;
      case TINYGLTF_MODE_LINE:
        for (std::size_t i = 0; i + 1 < n; i += 2) mesh_.segments.push_back({v[i], v[i + 1]});
        break;
      case TINYGLTF_MODE_LINE_STRIP:
      case TINYGLTF_MODE_LINE_LOOP:
        for (std::size_t i = 0; i + 1 < n; ++i) mesh_.segments.push_back({v[i], v[i + 1]});
        if (mode == TINYGLTF_MODE_LINE_LOOP && n > 2) mesh_.segments.push_back({v[n - 1], v[0]});
        break;
      default:
        gltf_error(where + " has mode " + std::to_string(mode) + ", which glTF does not define");
    }
    if (mesh_.segments.size() > 3 * static_cast<std::size_t>(limits_.max_obj_faces))
      throw SceneError(ErrorKind::limit,
                       "the model has more than " + std::to_string(3 * limits_.max_obj_faces) + " lines");
  }

  const tinygltf::Model& model_;
  const Limits& limits_;
  const Uploads& files_;
  Mesh mesh_;
  std::vector<bool> visited_;
  std::map<std::pair<int, TexelAlpha>, std::int32_t>
      textures_;  ///< (image, alpha) -> index into mesh_.textures
  std::int64_t texel_budget_ = limits_.max_texture_pixels;
  std::int32_t primitive_texture_ = -1;
  bool any_lit_ = false, any_unlit_ = false;
  /// Triangles [first, end) of the primitives that had no NORMAL, for finish_normals.
  std::vector<std::pair<std::size_t, std::size_t>> without_normals_;
  std::size_t drawn_primitives_ = 0;    ///< primitives of every node's mesh so far, for kMaxDrawnPrimitives
  bool textured_ = false;               ///< a primitive so far had a texture and its coordinates
  bool one_colour_ = true;              ///< every vertex so far has mesh_.colors[0]: it is stored once
  std::vector<std::uint32_t> corners_;  ///< the current primitive's vertex order, kept for its capacity
};

}  // namespace

std::vector<std::string> gltf_files(std::string_view bytes) {
  std::vector<std::string> names;
  if (bytes.starts_with("glTF")) {  // a GLB: the JSON chunk follows the 12-byte header and its 8-byte head
    if (bytes.size() < 20) return names;
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    bytes = bytes.substr(20, std::min<std::size_t>(length, bytes.size() - 20));
  }
  const nlohmann::json doc = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
  if (!doc.is_object()) return names;
  for (const char* list : {"buffers", "images"}) {
    const auto it = doc.find(list);
    if (it == doc.end() || !it->is_array()) continue;
    for (const nlohmann::json& item : *it) {
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      const std::string& uri = item["uri"].get_ref<const std::string&>();
      if (uri.rfind("data:", 0) == 0) continue;
      std::string name = file_name_of_uri(uri);
      if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  return names;
}

Mesh parse_gltf(std::string_view bytes, const Limits& limits, const Uploads& files) {
  if (bytes.size() > 0xFFFFFFFFu) gltf_error("the model is over 4 GB", ErrorKind::limit);
  const bool binary = bytes.starts_with("glTF");
  if (binary && bytes.size() >= 8 && bytes[4] != 2)
    gltf_error("the file is a GLB of version " + std::to_string(static_cast<unsigned char>(bytes[4])) +
               "; rasterd reads glTF 2.0 (Blender and the glTF tools convert older files)");
  // Checked before tinygltf sees the document: it is JSON within the depth limit (tinygltf turns "extras"
  // into Values recursively: 50,000 nested '[' overflowed the stack), what it would build is bounded, and
  // the buffers it would copy fit in the bytes sent.
  std::uint64_t sent = bytes.size();
  for (const auto& [name, file] : files) sent += file.size();
  Shape shape;
  try {
    shape = shape_of(binary ? glb_json(bytes) : bytes, limits.max_json_depth, files);
  } catch (const SceneError& e) {
    gltf_error(std::string("the document is not JSON: ") + e.what() +
               (e.where().byte ? " (byte " + std::to_string(e.where().byte) + " of the JSON)" : ""));
  }
  if (shape.structure_bytes > kMaxStructureBytes)
    gltf_error("the document describes about " + std::to_string(shape.structure_bytes >> 20) +
                   " MB of nodes, meshes, materials and other objects; rasterd reads at most " +
                   std::to_string(kMaxStructureBytes >> 20) + " MB",
               ErrorKind::limit);
  if (!shape.missing.empty())
    gltf_error("the model asks for buffer \"" + shape.missing +
               "\", which was not sent; sent: " + upload_names(files) +
               ". Send it as a multipart part with that file name (curl -F 'file=@" + shape.missing + "')");
  if (shape.buffer_bytes > sent)
    gltf_error("the buffers declare " + std::to_string(shape.buffer_bytes) + " bytes, more than the " +
               std::to_string(sent) + " bytes sent");
  if (binary && shape.buffers_without_uri > 1)
    gltf_error("more than one buffer has no URI; only the first may be a GLB's binary chunk");

  // tinygltf copies the buffers and images it is given (base64 ones decoded), and keeps the document's
  // objects: bounded by what was sent, asked for before it runs.
  detail::reserve(limits, cost::kGltfPerByte * static_cast<std::int64_t>(sent),
                  [] { return std::string("reading the glTF document"); });
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  CopyBudget budget{&model, &files, sent};
  loader.SetImageLoader(&keep_image, &budget);
  loader.SetFsCallbacks({&upload_exists, &same_path, &read_upload, &write_nothing, &budget});
  std::string err, warn;
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                              reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned int>(bytes.size()))
                : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                             static_cast<unsigned int>(bytes.size()), "");
  } catch (const std::exception&
               e) {  // tinygltf 2.7.0 indexes some vectors with at(): e.g. a GLB buffer of 0 bytes
    err = e.what();
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    for (char& c : err)
      if (c == '\n') c = ';';
    if (bytes.find("KHR_draco_mesh_compression") != std::string_view::npos)
      gltf_error(
          "the model's meshes are Draco-compressed (KHR_draco_mesh_compression), which rasterd does not "
          "read; export it without compression");
    gltf_error("the model could not be read: " +
               (err.empty() ? std::string("tinygltf gave no reason") : err));
  }
  if (!model.asset.version.starts_with("2"))
    gltf_error("the document is glTF " + model.asset.version.substr(0, 20) +
               "; rasterd reads glTF 2.0 (Blender and the glTF tools convert older files)");
  return Reader(model, limits, files).read();
}

}  // namespace raster
