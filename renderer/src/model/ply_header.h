// PLY's header (private to the PLY reader): the elements and properties a file declares, read from its text,
// and the layout of the vertex and face elements, checked against the data's size before anything is sized
// from a count (ply_header.cpp). ply.cpp reads the data by them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "raster/scene.h"

namespace raster::ply {

[[noreturn]] inline void ply_error(const std::string& message, std::size_t line = 0, std::size_t byte = 0) {
  throw SceneError(ErrorKind::model, "PLY: " + message, ErrorLocation{"", byte, line});
}

/// A property's value type, as the header names it ("uchar", "float32", ...).
enum class Type : std::uint8_t { i8, u8, i16, u16, i32, u32, f32, f64 };
inline constexpr int kSize[] = {1, 1, 2, 2, 4, 4, 4, 8};  ///< bytes of each Type, in its order

// What the reader does with a property of the vertex or face element.
enum class Role : std::uint8_t { none, x, y, z, nx, ny, nz, red, green, blue, alpha, indices };

/// One "property" line.
struct Property {
  std::string name;            ///< as written ("x", "vertex_indices")
  Type type = Type::f32;       ///< a scalar's type, or a list's items'
  bool list = false;           ///< "property list <count type> <type> <name>"
  Type count_type = Type::u8;  ///< lists: the type of the length before the items
  Role role = Role::none;      ///< what the reader takes it for
};

/// One "element" line and the properties after it, in the order each entry holds them.
struct Element {
  std::string name;                  ///< as written ("vertex", "face")
  std::uint64_t count = 0;           ///< entries the header declares (checked against the data's size)
  std::vector<Property> properties;  ///< in file order
  std::size_t line = 0;              ///< the header line that declares it, 1-based
};

/// The "format" line's data encoding; binary orders are the file's, not the machine's.
enum class Encoding : std::uint8_t { ascii, little, big };

/// What the header declares.
struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
  std::size_t data = 0;   ///< byte offset of the first data byte
  std::size_t lines = 0;  ///< lines in the header, for ASCII data's line numbers
};

/// The header of `bytes` (which start with "ply" and a line break), or a PLY error naming its line.
Header read_header(std::string_view bytes);

/// The fewest bytes one instance of `e` takes: binary, its scalars and each list's length; ASCII, one
/// character and a separator per value.
std::uint64_t min_bytes(const Element& e, Encoding enc);

// The vertex and face elements of a header, checked against the data after it before anything is sized
// from their counts, and what the vertices hold.
struct Layout {
  const Element* vertex = nullptr;  ///< the "vertex" element, which has x, y and z
  const Element* face = nullptr;    ///< the "face" element, which has a list of vertex indices
  bool normals = false;             ///< the vertices have nx, ny and nz
  bool colours = false;             ///< the vertices have red, green and blue
};

/// The vertex and face elements of `h`, checked against the `data_bytes` after the header before anything is
/// sized from their counts, and what the vertices hold; PLY errors, or SceneError(limit) over `limits`.
Layout check_elements(const Header& h, std::size_t data_bytes, const Limits& limits);

}  // namespace raster::ply
