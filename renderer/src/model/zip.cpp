#include "model/zip.h"

#include <algorithm>
#include <cstring>

#include <isa-l/igzip_lib.h>

#include "base/budget_ask.h"
#include "base/text.h"

namespace raster::detail {
namespace {

[[noreturn]] void zip_error(const std::string& message) {
  throw SceneError(ErrorKind::model, "the 3MF package (a ZIP archive) " + message);
}

std::uint64_t le(std::string_view b, std::size_t at, int n) {
  std::uint64_t v = 0;
  for (int i = n - 1; i >= 0; --i)
    v = v << 8 | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
  return v;
}

constexpr std::uint32_t kEnd = 0x06054b50, kEnd64 = 0x06064b50, kEnd64Locator = 0x07064b50;
constexpr std::uint32_t kCentral = 0x02014b50, kLocal = 0x04034b50;

// The zip64 extra field (tag 1) of a central entry: the sizes and offset that are 0xffffffff in the fixed
// part, in that order.
void read_zip64(std::string_view extra, ZipEntry& e) {
  for (std::size_t at = 0; at + 4 <= extra.size();) {
    const std::uint64_t tag = le(extra, at, 2), n = le(extra, at + 2, 2);
    if (at + 4 + n > extra.size()) zip_error("has an entry whose extra field runs past it: " + e.name);
    if (tag == 1) {
      std::size_t p = at + 4;
      for (std::uint64_t* field : {&e.size, &e.compressed, &e.local})
        if (*field == 0xffffffffu) {
          if (p + 8 > at + 4 + n) zip_error("has a ZIP64 entry without its sizes: " + e.name);
          *field = le(extra, p, 8), p += 8;
        }
      return;
    }
    at += 4 + n;
  }
}

}  // namespace

ZipArchive::ZipArchive(std::string_view bytes) : bytes_(bytes) {
  // The end record is in the last 22 + 65535 bytes (its comment is at most 65535 bytes).
  if (bytes.size() < 22) zip_error("is too short to hold a directory");
  std::size_t end = std::string_view::npos;
  for (std::size_t at = bytes.size() - 22;; --at) {
    if (le(bytes, at, 4) == kEnd && at + 22 + le(bytes, at + 20, 2) == bytes.size()) {
      end = at;
      break;
    }
    if (at == 0 || bytes.size() - at > 22 + 65535) break;
  }
  if (end == std::string_view::npos) zip_error("has no end of central directory record");
  if (le(bytes, end + 4, 2) != 0 || le(bytes, end + 6, 2) != 0) zip_error("is split over several disks");
  std::uint64_t count = le(bytes, end + 10, 2), size = le(bytes, end + 12, 4),
                offset = le(bytes, end + 16, 4);
  if ((count == 0xffff || size == 0xffffffffu || offset == 0xffffffffu) && end >= 20 &&
      le(bytes, end - 20, 4) == kEnd64Locator) {
    const std::uint64_t at = le(bytes, end - 20 + 8, 8);
    if (at > bytes.size() || bytes.size() - at < 56 || le(bytes, at, 4) != kEnd64)
      zip_error("has a ZIP64 end record locator that points nowhere");
    count = le(bytes, at + 32, 8), size = le(bytes, at + 40, 8), offset = le(bytes, at + 48, 8);
  }
  if (offset > bytes.size() || size > bytes.size() - offset)
    zip_error("has a central directory that runs past the end of the file");
  // A directory entry is at least 46 bytes, so the count is bounded by the bytes before it is trusted.
  if (count > kZipMaxEntries || count > size / 46)
    zip_error("says it has " + std::to_string(count) + " entries, more than " +
              (count > kZipMaxEntries ? "a package may have (" + std::to_string(kZipMaxEntries) + ")"
                                      : std::string("its directory holds")));
  entries_.reserve(count);
  std::size_t at = offset;
  for (std::uint64_t i = 0; i < count; ++i) {
    if (offset + size - at < 46 || le(bytes, at, 4) != kCentral)
      zip_error("has a damaged central directory (entry " + std::to_string(i + 1) + ")");
    const std::size_t name = le(bytes, at + 28, 2), extra = le(bytes, at + 30, 2),
                      comment = le(bytes, at + 32, 2);
    if (offset + size - at - 46 < name + extra + comment)
      zip_error("has a damaged central directory (entry " + std::to_string(i + 1) + ")");
    ZipEntry e;
    e.flags = static_cast<std::uint16_t>(le(bytes, at + 8, 2));
    e.method = static_cast<std::uint16_t>(le(bytes, at + 10, 2));
    e.compressed = le(bytes, at + 20, 4), e.size = le(bytes, at + 24, 4), e.local = le(bytes, at + 42, 4);
    e.name = std::string(bytes.substr(at + 46, name));
    read_zip64(bytes.substr(at + 46 + name, extra), e);
    entries_.push_back(std::move(e));
    at += 46 + name + extra + comment;
  }
}

const ZipEntry* ZipArchive::find(std::string_view name) const {
  if (name.starts_with('/')) name.remove_prefix(1);
  for (const ZipEntry& e : entries_) {
    std::string_view stored = e.name;
    if (stored.starts_with('/')) stored.remove_prefix(1);
    if (iequals(stored, name)) return &e;
  }
  return nullptr;
}

std::string ZipArchive::read(const ZipEntry& e, const Limits& limits) const {
  if (e.flags & 1) zip_error("entry " + e.name + " is encrypted");
  if (e.method != 0 && e.method != 8)
    zip_error("entry " + e.name + " is compressed by method " + std::to_string(e.method) +
              "; 3MF packages use DEFLATE (8) or none (0)");
  if (e.local > bytes_.size() || bytes_.size() - e.local < 30 || le(bytes_, e.local, 4) != kLocal)
    zip_error("entry " + e.name + " has no local header where the directory says");
  const std::uint64_t data = e.local + 30 + le(bytes_, e.local + 26, 2) + le(bytes_, e.local + 28, 2);
  if (data > bytes_.size() || e.compressed > bytes_.size() - data)
    zip_error("entry " + e.name + " runs past the end of the file");
  const std::string_view in = bytes_.substr(data, e.compressed);
  if (e.method == 0 && e.size != e.compressed)
    zip_error("entry " + e.name + " is stored with two different sizes");
  // DEFLATE cannot expand more than 1032:1, and no 3MF part of a model within the face limit is near
  // kZipMaxEntryBytes: a size beyond either is a lie or a bomb, refused from the directory. What is asked
  // of the budget is what the directory says, before any inflating.
  if (e.method == 8 && e.size > 1032 * e.compressed + 1024)
    zip_error("entry " + e.name + " says it inflates to " + std::to_string(e.size) + " bytes from " +
              std::to_string(e.compressed) + ", more than DEFLATE can (a ZIP bomb)");
  if (e.size > kZipMaxEntryBytes)
    throw SceneError(ErrorKind::limit, "the 3MF entry " + e.name + " is " + std::to_string(e.size) +
                                           " bytes once inflated, over the limit of " +
                                           std::to_string(kZipMaxEntryBytes));
  reserve(limits, static_cast<std::int64_t>(std::min<std::uint64_t>(e.size, INT64_MAX)),
          [&] { return "the 3MF entry " + e.name; });
  std::string out;
  out.resize(e.size);
  if (e.method == 0) {
    std::memcpy(out.data(), in.data(), in.size());
    return out;
  }
  inflate_state state;
  isal_inflate_init(&state);
  state.crc_flag = ISAL_DEFLATE;
  state.next_in = reinterpret_cast<std::uint8_t*>(const_cast<char*>(in.data()));
  state.next_out = reinterpret_cast<std::uint8_t*>(out.data());
  // avail_in and avail_out are 32-bit: entries over 4 GiB are fed in turns. A turn that neither reads nor
  // writes is the end of the input (or of the room) before the end of the data.
  std::uint64_t left_in = in.size(), left_out = out.size();
  for (;;) {
    const auto give_in = static_cast<std::uint32_t>(std::min<std::uint64_t>(left_in, 1u << 30));
    const auto give_out = static_cast<std::uint32_t>(std::min<std::uint64_t>(left_out, 1u << 30));
    state.avail_in = give_in, state.avail_out = give_out;
    if (isal_inflate(&state) != ISAL_DECOMP_OK) zip_error("entry " + e.name + " is not valid DEFLATE data");
    const std::uint64_t used = give_in - state.avail_in, made = give_out - state.avail_out;
    left_in -= used, left_out -= made;
    if (state.block_state == ISAL_BLOCK_FINISH) break;
    if (used == 0 && made == 0)
      zip_error("entry " + e.name +
                (left_out == 0 ? " inflates to more than its stated " + std::to_string(e.size) + " bytes"
                               : std::string(" ends before its DEFLATE data does")));
  }
  if (left_out != 0)
    zip_error("entry " + e.name + " inflates to " + std::to_string(out.size() - left_out) +
              " bytes, not its stated " + std::to_string(e.size));
  return out;
}

}  // namespace raster::detail
