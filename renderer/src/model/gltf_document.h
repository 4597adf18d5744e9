// glTF's document as the mesh builder (gltf_mesh.cpp) takes it from the document reader (gltf.cpp):
// tinygltf's types, configured as the library compiles them; the error every glTF message goes through;
// uploads found by the URI a document writes; and AccessorView, one accessor checked to lie within its
// buffer view and buffer before a byte of it is read, then read as doubles or indices. Its loops are the
// per-vertex code of a glTF model, so they are here, inline, for the builder's loops to take in.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "raster/model.h"

#define TINYGLTF_NO_STB_IMAGE        // images are decoded by decode_texture, under the texel budget
#define TINYGLTF_NO_STB_IMAGE_WRITE  // nothing is written
#define TINYGLTF_NO_EXTERNAL_IMAGE   // an image's URI is resolved among the uploads (gltf_mesh.cpp)
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

namespace raster::gltf {

[[noreturn]] inline void gltf_error(const std::string& message, ErrorKind kind = ErrorKind::model) {
  throw SceneError(kind, "glTF: " + message);
}

// A URI's file name, percent-decoded, without folders ("textures/Duck%20Diffuse.png" -> "Duck Diffuse.png").
std::string file_name_of_uri(std::string_view uri);
// An uploaded file by a URI as the document writes it (percent-encoded, perhaps with folders); null if none.
const std::string* find_upload(const Uploads& files, const std::string& uri);
// The uploads' names, quoted, for an error that says what was sent.
std::string upload_names(const Uploads& files);

// What drawing the nodes from `roots` (or, `every_mesh`, each mesh once) would build, counted from the
// accessors' declared counts before anything is built, against what the `sent` bytes allow (model.h:
// kModelBuiltPerByte); more than `max_primitives` drawn primitives is refused too. Throws SceneError(limit).
// Only a count: the walk that builds checks each node, accessor and limit itself; it sizes the mesh's
// arrays by it once (vertices for positions and their attributes, faces for triangles and theirs).
struct BuiltCounts {
  std::uint64_t vertices = 0;  ///< POSITION elements of every drawn primitive
  std::uint64_t faces = 0;     ///< triangles, and line segments, as add_faces makes them
};
BuiltCounts check_what_it_builds(const tinygltf::Model& model, const std::vector<int>& roots, bool every_mesh,
                                 std::uint64_t sent, std::size_t max_primitives);

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

// Every mesh of the document's default scene (else of every root node, else every mesh) in one Mesh,
// under its nodes' transforms: the document is tinygltf's, already loaded and within the limits' bytes.
// `sent` is the bytes of the model and its uploads, which bound what it may build (kModelBuiltPerByte).
Mesh build_mesh(const tinygltf::Model& model, const Limits& limits, const Uploads& files, std::uint64_t sent);

}  // namespace raster::gltf
