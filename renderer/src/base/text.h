// ASCII case for the names and keywords the readers compare (format names and extensions, file names, STL
// and MTL keywords): only 'A'..'Z' fold, whatever the locale, so a byte of a UTF-8 name is never changed.
#pragma once

#include <algorithm>
#include <string_view>

namespace raster::detail {

/// `c` in lower case when it is an ASCII capital; any other byte as it is.
inline char ascii_lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c + ('a' - 'A')) : c;
}

/// True when `a` and `b` are the same but for ASCII case.
inline bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](char x, char y) { return ascii_lower(x) == ascii_lower(y); });
}

}  // namespace raster::detail
