// UTF-8 checks for text that comes from clients (scenes, models, names, parameters) and for anything a
// caller echoes back to them in an error or a log line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace raster {

/// Offset (0-based) of the first byte of `text` that does not belong to a well-formed UTF-8 sequence as
/// RFC 3629 defines it (no overlong forms, no surrogates U+D800..DFFF, nothing above U+10FFFF, no lone
/// continuation bytes, no sequence cut short), or std::string_view::npos when all of `text` is well formed.
std::size_t first_invalid_utf8(std::string_view text);

/// `text` made safe to show: each byte of an ill-formed sequence and each control character (U+0000..001F,
/// U+007F) becomes "\xNN", so a message or log line quoting client text is valid UTF-8 on one line.
std::string escape_for_display(std::string_view text);

/// Throws SceneError(encoding) when `text` is not well-formed UTF-8, located at the first bad byte (1-based
/// byte offset, and 1-based line when `with_line`), the message naming `what` (e.g. "the scene") and why the
/// byte is wrong. Returns normally for valid text.
void require_utf8(std::string_view text, const std::string& what, bool with_line = false);

}  // namespace raster
