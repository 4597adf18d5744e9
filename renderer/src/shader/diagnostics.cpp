#include "shader/diagnostics.h"

#include <cstdio>

namespace raster::shader {

void Diagnostics::error(SourcePos pos, std::string message) {
  if (errors_.size() >= kMaxErrors) {
    ++overflow_;
    return;
  }
  errors_.push_back({pos, std::move(message)});
}

std::string quote(std::string_view text, std::size_t max) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (out.size() >= max) {
      out += "...";
      break;
    }
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out;
}

}  // namespace raster::shader
