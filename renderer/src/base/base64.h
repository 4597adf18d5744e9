// Base64: text -> bytes, for the image files a scene carries inline (textures as base64 or a data URI).
#pragma once

#include <string>
#include <string_view>

namespace raster {

/// Standard base64 (RFC 4648 section 4, '=' padding optional), or a data URI holding it, decoded into
/// `out`. False on any other character.
bool decode_base64(std::string_view text, std::string& out);

}  // namespace raster
