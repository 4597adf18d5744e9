// The scene of an image URL, GET /render?scene=...: base64url text back to the scene's bytes.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rasterd {

/// Why a ?scene= value cannot be decoded: `status` is 400 (not base64url, not deflate) or 413 (inflates
/// past the limit).
class SceneUrlError : public std::runtime_error {
 public:
  SceneUrlError(int status, const std::string& message) : std::runtime_error(message), status_(status) {}
  int status() const { return status_; }

 private:
  int status_;
};

/// base64url (RFC 4648 section 5; '=' padding optional) of either the plain scene text, when the first
/// decoded byte is '{', or of its deflate stream, inflated here: raw (RFC 1951), zlib-wrapped (RFC 1950,
/// told by its two-byte header) or gzip. A deflate stream can begin with '{' (0x7B) only when the text it
/// holds begins with a byte 0xE0..0xEF, which no scene does, so the rule is unambiguous; a raw stream whose
/// first bytes happen to read as a zlib header is read raw when the zlib reading fails. Inflating stops as
/// soon as the output would exceed `max_bytes` (the body limit), so a small URL cannot expand into unbounded
/// memory. Throws SceneUrlError.
std::string decode_scene_param(std::string_view param, std::size_t max_bytes);

}  // namespace rasterd
