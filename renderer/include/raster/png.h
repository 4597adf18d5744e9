// PNG: Image -> PNG file bytes, in memory.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "raster/plan.h"

namespace raster {

/// Encodes with the Up row filter and ISA-L's deflate (igzip) at `png.deflate_level`, under the colour type
/// the plan chose (8 bits per channel). Throws std::invalid_argument when that colour type does not fit
/// image.format (a plan made for another image).
std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png);

/// The same bytes, consuming the image: its rows are filtered where they lie (no second image-sized
/// buffer), which is what a render service wants at the end of a request.
std::vector<std::uint8_t> encode_png(Image&& image, const PngPlan& png);

/// Makes sure `encodes_at_once` encoders (igzip's state for png.deflate_level, ~360 KB each at level 1) are
/// set up and kept for the encodes to come. Encoders are kept between calls anyway; a service calls this
/// once at start with its number of render workers, so its first requests do not pay for setting them up
/// (on the 2-core test VM a fresh page costs ~15 us, and the state is ~90 of them).
void prepare_png_encoders(int encodes_at_once, const PngPlan& png = {});

/// Encoders kept for reuse at `deflate_level`: for tests and metrics.
std::size_t kept_png_encoders(int deflate_level);

/// For images not made by a plan: the PngPlan a plan would choose for image.format.
std::vector<std::uint8_t> encode_png(const Image& image);
std::vector<std::uint8_t> encode_png(Image&& image);

}  // namespace raster
