// Deflate for the PNG encoder: bytes in, their zlib stream (header, deflate, Adler-32) out, by ISA-L's
// igzip from states kept for reuse. Same bytes in, same stream out, whichever state and thread encodes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace raster::deflate {

/// igzip's state for one level (deflate.cpp): its stream, its level buffer.
struct Deflater;
struct DeflaterDelete {
  void operator()(Deflater* d) const;
};
using DeflaterPtr = std::unique_ptr<Deflater, DeflaterDelete>;

/// A zlib stream in a buffer that grew only if the data did not compress (its untouched tail has no pages).
struct Compressed {
  std::unique_ptr<std::uint8_t[]> bytes;
  std::size_t size = 0;  ///< bytes of the stream at the front of `bytes`
};

/// `in` at igzip `level` (clamped to 0..3), with a state from the process-wide pool.
Compressed zlib_compress(const std::vector<std::uint8_t>& in, int level);

/// `in` with the caller's state, at its level: for tests that encode from fresh and reused states.
Compressed zlib_compress(Deflater& d, const std::vector<std::uint8_t>& in);

/// A new state at igzip `level` (clamped to 0..3), outside the pool.
DeflaterPtr make_deflater(int level);

/// Makes sure the pool holds `count` states (0..64) for `level`; states it holds for `level`.
void prepare(int count, int level);
std::size_t kept(int level);

}  // namespace raster::deflate
