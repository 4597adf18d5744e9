// A plot drawn by rasterd itself: triangles, lines and stb_easy_font's text as one scene's primitives,
// in pixels (origin top left, y down). docs/accuracy.png and docs/images/models-by-size.png are made so.
#pragma once

// stb_easy_font's functions are static: each file that includes this has its own.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

#include <string>
#include <vector>

#include "raster/scene.h"
#include "scenes.h"

namespace bench {

struct PlotScene {
  raster::Scene scene;
  void tri(raster::Point2 a, raster::Point2 b, raster::Point2 c, raster::Rgba8 col) {
    add_triangle(scene, {a, b, c}, &col, 1);
  }
  void line(raster::Point2 a, raster::Point2 b, raster::Rgba8 col, float width = 1) {
    add_line(scene, a, b, col, width);
  }
  /// `s` from its top-left corner at (x, y), stb_easy_font's glyphs (about 7 px tall) times `scale`.
  void text(double x, double y, const std::string& s, raster::Rgba8 col, double scale = 1.5) {
    // stb_easy_font writes 64 bytes a quad and stops at the buffer's end; a glyph is at most 11 quads ("0" is
    // 6: its ~270 bytes a glyph are an average, which cut the last digits of numbers off).
    std::vector<char> buffer(s.size() * 1024 + 64);
    const int quads = stb_easy_font_print(0, 0, const_cast<char*>(s.c_str()), nullptr, buffer.data(),
                                          static_cast<int>(buffer.size()));
    const float* v = reinterpret_cast<const float*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
      raster::Point2 p[4];
      for (int k = 0; k < 4; ++k) p[k] = {x + v[(q * 4 + k) * 4] * scale, y + v[(q * 4 + k) * 4 + 1] * scale};
      tri(p[0], p[1], p[2], col);
      tri(p[0], p[2], p[3], col);
    }
  }
  /// The width in pixels `s` takes at `scale`: to end a label at a given x.
  static double text_width(const std::string& s, double scale = 1.5) {
    return stb_easy_font_width(const_cast<char*>(s.c_str())) * scale;
  }
  /// A filled square of side `2 r` around `c`: a plot's marker.
  void mark(raster::Point2 c, double r, raster::Rgba8 col) {
    tri({c.x - r, c.y - r}, {c.x + r, c.y - r}, {c.x + r, c.y + r}, col);
    tri({c.x - r, c.y - r}, {c.x + r, c.y + r}, {c.x - r, c.y + r}, col);
  }
};

}  // namespace bench
