// The ZIP container of a 3MF package (an OPC package): its central directory read from the bytes sent, and
// an entry's bytes inflated (ISA-L's raw DEFLATE) into exactly the size the directory states. Nothing is
// read from disk. Every offset and size is checked against the bytes before it is used, and an entry's
// uncompressed size is asked of the budget before it is inflated, so a ZIP bomb is refused from its
// directory, costing nothing.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "raster/scene.h"

namespace raster::detail {

/// One entry of the central directory.
struct ZipEntry {
  std::string name;              ///< as stored: '/'-separated, no leading '/'
  std::uint16_t method = 0;      ///< 0 stored, 8 deflated (others are refused when read)
  std::uint16_t flags = 0;       ///< general purpose bits; bit 0: encrypted
  std::uint64_t compressed = 0;  ///< bytes of the stored data
  std::uint64_t size = 0;        ///< bytes once inflated
  std::uint64_t local = 0;       ///< offset of the entry's local header in the archive
};

/// The most entries a package may have: far above a slicer's (a few dozen parts), far below what would make
/// the directory's reading costly.
inline constexpr std::size_t kZipMaxEntries = 65535;

/// The most bytes one entry may inflate to: 1 GiB, the XML of some ten million triangles (twice the face
/// limit's worth).
inline constexpr std::uint64_t kZipMaxEntryBytes = std::uint64_t{1} << 30;

class ZipArchive {
 public:
  /// Reads the directory of `bytes` (which must outlive the archive). SceneError(model) naming what is wrong
  /// when they are no ZIP archive, or one this reader does not read (split over disks).
  explicit ZipArchive(std::string_view bytes);
  const std::vector<ZipEntry>& entries() const { return entries_; }
  /// The entry named `name` (a leading '/' ignored, ASCII case ignored, as OPC part names compare), or null.
  const ZipEntry* find(std::string_view name) const;
  /// The entry's `size` bytes, asked of `limits`' budget before anything is inflated (MemoryRefused when
  /// refused).
  /// SceneError(model) naming the entry when its data is not all there, is encrypted, uses a method other
  /// than stored or DEFLATE, or inflates to other than its stated size.
  std::string read(const ZipEntry& entry, const Limits& limits) const;

 private:
  std::string_view bytes_;
  std::vector<ZipEntry> entries_;
};

}  // namespace raster::detail
