// The measurements behind the PNG encoder's choices (renderer/src/png/png.cpp): row filter and deflate
// implementation/level, on the benchmark renders, one thread, median of repeated runs. The compressors
// are timed on the same filtered rows; stb_image_write as shipped is the baseline a caller would use.
// Prints a Markdown table.
#include <isa-l/igzip_lib.h>
#include <libdeflate.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "raster/raster.h"
#include "scenes.h"
#include "stb_stock.h"
#include "timing.h"

namespace {

// PNG filter bytes + rows with one fixed filter for every row: 0 None, 1 Sub, 2 Up.
std::vector<std::uint8_t> filter_rows(const raster::Image& image, int filter) {
  const std::size_t c = static_cast<std::size_t>(image.channels());
  const std::size_t stride = static_cast<std::size_t>(image.width) * c;
  std::vector<std::uint8_t> out(static_cast<std::size_t>(image.height) * (stride + 1));
  for (std::size_t y = 0; y < static_cast<std::size_t>(image.height); ++y) {
    std::uint8_t* o = out.data() + y * (stride + 1);
    const std::uint8_t* row = image.pixels.data() + y * stride;
    o[0] = static_cast<std::uint8_t>(filter);
    for (std::size_t i = 0; i < stride; ++i) {
      const std::uint8_t predictor = filter == 1        ? (i >= c ? row[i - c] : 0)
                                     : filter == 2 && y ? row[i - stride]
                                                        : 0;
      o[1 + i] = static_cast<std::uint8_t>(row[i] - predictor);
    }
  }
  return out;
}

std::size_t igzip(const std::vector<std::uint8_t>& in, int level, std::vector<std::uint8_t>& out) {
  static const std::uint32_t sizes[] = {ISAL_DEF_LVL0_DEFAULT, ISAL_DEF_LVL1_DEFAULT, ISAL_DEF_LVL2_DEFAULT,
                                        ISAL_DEF_LVL3_DEFAULT};
  auto stream = std::make_unique<isal_zstream>();
  std::vector<std::uint8_t> level_buffer(sizes[level]);
  isal_deflate_init(stream.get());
  stream->level = static_cast<std::uint32_t>(level);
  stream->level_buf = level_buffer.data();
  stream->level_buf_size = sizes[level];
  stream->gzip_flag = IGZIP_ZLIB;
  stream->end_of_stream = 1;
  stream->next_in = const_cast<std::uint8_t*>(in.data());
  stream->avail_in = static_cast<std::uint32_t>(in.size());
  stream->next_out = out.data();
  stream->avail_out = static_cast<std::uint32_t>(out.size());
  if (isal_deflate(stream.get()) != COMP_OK || stream->internal_state.state != ZSTATE_END) std::abort();
  return stream->total_out;
}

std::size_t deflate(const std::vector<std::uint8_t>& in, int level, std::vector<std::uint8_t>& out) {
  libdeflate_compressor* c = libdeflate_alloc_compressor(level);
  const std::size_t n = libdeflate_zlib_compress(c, in.data(), in.size(), out.data(), out.size());
  libdeflate_free_compressor(c);
  return n;
}

}  // namespace

// Usage: png_sweep [runs]
int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 7;
  std::printf("| scene | filter | compressor | ms | KB |\n|---|---|---|---:|---:|\n");
  for (const char* kind : {"small", "large", "grid"}) {
    const raster::Scene scene = bench::make_scene(kind, 1);
    const raster::RenderPlan plan = raster::plan(scene);
    const raster::Image image = raster::render(scene, plan);
    auto row = [&](const char* filter, const std::string& compressor, double ms, std::size_t bytes) {
      std::printf("| %s | %s | %s | %.2f | %zu |\n", kind, filter, compressor.c_str(), ms, bytes / 1024);
    };
    std::size_t size = 0;
    double ms = bench::median_ms(runs, [&] { size = raster::encode_png(image, plan.png).size(); });
    row("Up", "**rasterd encode_png (whole encode)**", ms, size);
    ms = bench::median_ms(std::max(3, runs / 2), [&] { size = bench::stb_stock_png_size(image); });
    row("stb's heuristic", "stb_image_write as shipped (whole encode)", ms, size);
    std::vector<std::uint8_t> out(image.pixels.size() * 2 + 65536);
    const char* filter_names[] = {"None", "Sub", "Up"};
    for (int filter : {0, 1, 2}) {
      const std::vector<std::uint8_t> rows = filter_rows(image, filter);
      for (int level = 0; level <= 3; ++level) {
        if (filter != 2 && level != 1) continue;  // filters compared at the chosen level only
        ms = bench::median_ms(runs, [&] { size = igzip(rows, level, out); });
        row(filter_names[filter], "igzip (ISA-L) level " + std::to_string(level), ms, size);
      }
      if (filter != 2) continue;
      for (int level : {1, 6}) {
        ms = bench::median_ms(runs, [&] { size = deflate(rows, level, out); });
        row(filter_names[filter], "libdeflate level " + std::to_string(level), ms, size);
      }
    }
  }
  return 0;
}
