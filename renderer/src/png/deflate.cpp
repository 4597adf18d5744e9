// Deflate for the PNG encoder (deflate.h): ISA-L's igzip, its states kept in a pool, each stream at an
// address that keeps igzip's output a function of its input alone.
#include "png/deflate.h"

#include <algorithm>
#include <cstring>
#include <mutex>
#include <new>
#include <stdexcept>

#include <sys/mman.h>

#include <isa-l/igzip_lib.h>

namespace raster::deflate {
namespace {

// Where an igzip stream may live, so that the same rows always deflate to the same bytes.
//
// ISA-L's level 1 and 2 deflate body (igzip_icf_body_h1_gr_bt.asm, .write_first_byte, in 2.30 and still
// upstream) computes the hash of the input's third byte from a register that holds the isal_zstream's
// address instead of the data: CRC-32C of address bits 16-47. Position 2 of every input is therefore
// filed under a hash-table slot chosen by where the stream lives, and when a later position looks in that
// slot (about one address in a thousand for the test scenes) it finds position 2 and deflates differently:
// a valid stream of the same pixels, other bytes (issue 40: the CLI's PNG against the server's, or two
// servers, differed from the first IDAT bytes on). So each stream is mapped at an address whose bits 16-47
// have one fixed CRC-32C (low 16 bits: every level's hash mask), the same in every process and encoder;
// the slot is then always the same, and one that files position 2 where no test scene's data looks
// (0x1234: the bytes every address but ~1 in 1,000 gave before, so no PNG changed).
namespace stream_address {

// The class: CRC-32C(address bits 16-47) & 0xffff. Streams are looked for from block (address >> 16)
// kFirstBlock, 0x3a00'0000'0000, far from where Linux, glibc and ASan put memory, up to kLastBlock.
constexpr std::uint32_t kSlotBits = 0x1234;
constexpr std::uint64_t kFirstBlock = 0x3a00'0000;
constexpr std::uint64_t kLastBlock = 0x7000'0000;

// igzip's compute_hash: `crc32 r32, r32` from 0, no final xor (CRC-32C, reflected), a byte at a time: the
// search below tries ~65,536 blocks per stream.
struct Crc32cTable {
  std::uint32_t entry[256];
  constexpr Crc32cTable() : entry() {
    for (std::uint32_t b = 0; b < 256; ++b) {
      std::uint32_t c = b;
      for (int i = 0; i < 8; ++i) c = (c >> 1) ^ (0x82F63B78u & (0u - (c & 1u)));
      entry[b] = c;
    }
  }
};
constexpr Crc32cTable kCrc32c;

std::uint32_t crc32c(std::uint32_t v) {
  std::uint32_t c = 0;
  for (int i = 0; i < 4; ++i, v >>= 8) c = (c >> 8) ^ kCrc32c.entry[(c ^ v) & 0xff];
  return c;
}

std::mutex mutex;
std::uint64_t next_block = kFirstBlock;  // blocks below it were mapped or found taken
std::vector<void*> released;             // addresses of the class that were mapped and given back

bool map_at(void* want) {
  void* got = mmap(want, sizeof(isal_zstream), PROT_READ | PROT_WRITE,
                   MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED_NOREPLACE, -1, 0);
  if (got != MAP_FAILED && got != want) munmap(got, sizeof(isal_zstream));  // a kernel that took it as a hint
  return got == want;
}

// A zeroed isal_zstream at an address of the fixed class, or nullptr when none could be mapped (an address
// space laid out otherwise, e.g. by a sanitizer that reserves it): the caller then uses the heap, and the
// bytes are as they were before this (the same but for ~1 address in 1,000).
isal_zstream* take() {
  std::lock_guard lock(mutex);
  while (!released.empty()) {
    void* at = released.back();
    released.pop_back();
    if (map_at(at)) return new (at) isal_zstream{};
  }
  for (; next_block < kLastBlock; ++next_block) {
    if ((crc32c(static_cast<std::uint32_t>(next_block)) & 0xffff) != kSlotBits) continue;
    void* at = reinterpret_cast<void*>(next_block << 16);
    if (map_at(at)) return ++next_block, new (at) isal_zstream{};
  }
  return nullptr;
}

void give(isal_zstream* stream) {
  std::lock_guard lock(mutex);
  munmap(stream, sizeof(isal_zstream));
  released.push_back(stream);
}

}  // namespace stream_address

std::uint32_t level_buffer_bytes(int level) {
  switch (level) {
    case 0:
      return ISAL_DEF_LVL0_DEFAULT;
    case 1:
      return ISAL_DEF_LVL1_DEFAULT;
    case 2:
      return ISAL_DEF_LVL2_DEFAULT;
    default:
      return ISAL_DEF_LVL3_DEFAULT;
  }
}

}  // namespace

// igzip's state for one level: the stream (large: it holds the history window; at a fixed class of
// address, above) and the level's hash buffer, 360 KB together at level 1. Setting one up costs more than
// compressing a small image, so they are kept for reuse: a cache, not a setting (every call names its
// level). Kept in a pool rather than per thread: a service encodes on whichever of its many connection
// threads serves the request, so per-thread state would be set up once per thread (a first request on each
// of rasterd's hundreds of threads paid it) and held by every thread; the pool holds as many as ever encode
// at once, each warm for the next.
struct Deflater {
  explicit Deflater(int igzip_level)
      : stream(stream_address::take()),
        level_buffer_size(level_buffer_bytes(igzip_level)),
        level(igzip_level) {
    if (!stream) heap_stream = std::make_unique<isal_zstream>(), stream = heap_stream.get();
    if (level_buffer_size) level_buffer = std::make_unique<std::uint8_t[]>(level_buffer_size);
  }
  ~Deflater() {
    if (!heap_stream) stream_address::give(stream);
  }
  Deflater(const Deflater&) = delete;
  Deflater& operator=(const Deflater&) = delete;

  isal_zstream* stream;                       // mapped by stream_address::take, or heap_stream
  std::unique_ptr<isal_zstream> heap_stream;  // only when no fixed address could be mapped
  std::unique_ptr<std::uint8_t[]> level_buffer;
  std::uint32_t level_buffer_size = 0;  // bytes
  int level = 0;                        // igzip level 0..3
};

namespace {

class DeflaterPool {
 public:
  std::unique_ptr<Deflater> take(int level) {
    {
      std::lock_guard lock(mutex_);
      auto& spare = spare_[level];
      if (!spare.empty()) {
        std::unique_ptr<Deflater> d = std::move(spare.back());
        spare.pop_back();
        return d;
      }
    }
    return std::make_unique<Deflater>(level);
  }
  std::size_t kept(int level) {
    std::lock_guard lock(mutex_);
    return spare_[level].size();
  }
  void give(std::unique_ptr<Deflater> d) {
    std::lock_guard lock(mutex_);
    auto& spare = spare_[d->level];
    if (spare.size() < kMaxSpare) spare.push_back(std::move(d));  // else freed: more than ever ran at once
  }

 private:
  static constexpr std::size_t kMaxSpare = 64;  // per level: far above any machine's encodes at once
  std::mutex mutex_;
  std::vector<std::unique_ptr<Deflater>> spare_[4];
};

DeflaterPool& deflaters() {
  static DeflaterPool pool;  // process-wide by nature: reusable memory, no behaviour
  return pool;
}

}  // namespace

void DeflaterDelete::operator()(Deflater* d) const {
  delete d;
}

DeflaterPtr make_deflater(int level) {
  return DeflaterPtr(new Deflater(std::clamp(level, 0, 3)));
}

Compressed zlib_compress(const std::vector<std::uint8_t>& in, int level) {
  struct Lease {
    std::unique_ptr<Deflater> d;
    ~Lease() { deflaters().give(std::move(d)); }
  } lease{deflaters().take(std::clamp(level, 0, 3))};  // igzip's levels
  return zlib_compress(*lease.d, in);
}

// Into a buffer sized for the data as it is: it grows only if the data does not compress.
Compressed zlib_compress(Deflater& d, const std::vector<std::uint8_t>& in) {
  isal_zstream& s = *d.stream;
  isal_deflate_init(&s);
  s.level = static_cast<std::uint32_t>(d.level);
  s.level_buf = d.level_buffer.get();
  s.level_buf_size = d.level_buffer_size;
  s.gzip_flag = IGZIP_ZLIB;
  s.flush = NO_FLUSH;
  s.end_of_stream = 1;
  s.next_in = const_cast<std::uint8_t*>(in.data());  // igzip's API is not const-correct; it only reads
  s.avail_in = static_cast<std::uint32_t>(in.size());

  std::size_t capacity = in.size() + in.size() / 64 + 4096;  // stored blocks' overhead is 5 per 65535
  auto out = std::unique_ptr<std::uint8_t[]>(new std::uint8_t[capacity]);
  s.next_out = out.get();
  s.avail_out = static_cast<std::uint32_t>(capacity);
  for (;;) {
    if (isal_deflate(&s) != COMP_OK)
      throw std::runtime_error("PNG encoding failed: igzip rejected its input");
    if (s.internal_state.state == ZSTATE_END) return {std::move(out), s.total_out};
    if (s.avail_out == 0) {  // out of room: grow and go on where it stopped
      auto bigger = std::unique_ptr<std::uint8_t[]>(new std::uint8_t[capacity * 2]);
      std::memcpy(bigger.get(), out.get(), capacity);
      out = std::move(bigger);
      s.next_out = out.get() + capacity;
      s.avail_out = static_cast<std::uint32_t>(capacity);
      capacity *= 2;
    }
  }
}

void prepare(int count, int level) {
  level = std::clamp(level, 0, 3);
  const int wanted = std::clamp(count, 0, 64);
  std::vector<std::unique_ptr<Deflater>> taken;  // held at once, so each take makes a new one if need be
  for (int i = 0; i < wanted; ++i) taken.push_back(deflaters().take(level));
  for (auto& d : taken) deflaters().give(std::move(d));
}

std::size_t kept(int level) {
  return deflaters().kept(std::clamp(level, 0, 3));
}

}  // namespace raster::deflate
