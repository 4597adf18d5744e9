// Budget: the memory and time a render may still spend, kept by the caller (the service keeps one per
// request) and asked by the stages that learn how much they need, before they take it: a reader once its
// prescan has counted faces and vertices, the plan once it knows the pixel buffers, the render once it has
// counted its bins. Nothing here is process-wide; without a budget (Limits::budget null) nothing is asked.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace raster {

/// A caller's account for one render (parse, plan, render). Implementations must be thread-safe: the
/// render's threads ask it too.
class Budget {
 public:
  virtual ~Budget() = default;
  /// Takes `bytes` more for this render before they are allocated. False when they cannot be had; the
  /// asking stage then stops and throws MemoryRefused. May wait (the service waits for other requests to
  /// give memory back, within its queue's bound).
  virtual bool reserve(std::int64_t bytes) noexcept = 0;
  /// Gives back `bytes` of what was reserved, freed before the render ends (a reader's scratch once the mesh
  /// is made, the body once parsed), so a later stage's asks find them free. By default kept to the end.
  virtual void release(std::int64_t bytes) noexcept { (void)bytes; }
  /// True once the render must stop (its deadline passed, or it was cancelled): the readers ask every 65,536
  /// units of work (lines, entries, list items, corners, JSON values, ...) and throw RenderCancelled.
  virtual bool expired() const noexcept = 0;
};

/// Bytes of freed render arrays the library keeps mapped for later renders, at most (process-wide): resident
/// memory that no request's reservation counts, which a service sets aside from its budget.
inline constexpr std::size_t kKeptRenderBytes = std::size_t{256} << 20;

/// Thrown when a Budget refused memory: the render stopped before allocating `bytes`.
class MemoryRefused : public std::runtime_error {
 public:
  MemoryRefused(std::int64_t bytes, const std::string& what)
      : std::runtime_error("not enough memory for " + what + " (" + std::to_string(bytes) + " bytes)"),
        bytes_(bytes) {}
  std::int64_t bytes() const { return bytes_; }  ///< what was asked for when it was refused

 private:
  std::int64_t bytes_;
};

/// Thrown by render() and the readers when the deadline passed or the cancel flag was set; nothing is
/// returned.
class RenderCancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What the plan and the scene reader reserve, in bytes per counted thing. The model readers reserve the
/// arrays they make, at their sizes, once their counts are known (and a reader's scratch, such as an STL's
/// welding table, until it is freed); the records are asked for as geometry makes them. What every case
/// reserves is held between its measured resident peak and 1.3 times it by tests/memory_estimate_test
/// (VmHWM of a child process per model, face-dense and vertex-dense, in each format); docs/memory.md has
/// the measurements.
namespace cost {
/// What a render holds besides what it counts, per render thread: the thread's touched stack and its
/// allocator arena, the shaders' scratch; the 1-2.5 MB by which the measured peaks of
/// tests/memory_estimate_test (two threads) exceed the counted arrays, with room to spare.
inline constexpr std::int64_t kRenderPerThread = std::int64_t{2} << 20;
inline constexpr std::int64_t kScenePerByte = 4;  ///< per byte of scene JSON: its primitives, parsed
// Render, asked by the plan: what the geometry holds per vertex of a mesh (which clip planes it is outside
// of, 1 byte, and its projected position, 16), per vertex under a transform (its world position) and per
// normal it lights with (computed per vertex, or the mesh's own turned into world space; 24, and 1 for a
// computed one's mark of whether its vertex is drawn), per triangle of a
// mesh drawn with feature edges or as a wireframe (its three edges, listed and sorted), per segment (its
// ends and colours), per 2D primitive; the pixel buffers are the plan's. The records are asked for as
// geometry makes them (their bytes, in steps of kRenderRecordStep: most of a dense mesh's triangles get
// none), and 4 bytes per bin entry once the bins are counted.
inline constexpr std::int64_t kRenderPerVertex = 17;
inline constexpr std::int64_t kRenderPerWorldVertex = 24;
inline constexpr std::int64_t kRenderPerNormal = 24 + 1;
inline constexpr std::int64_t kRenderPerEdgeTriangle = 3 * 16;
inline constexpr std::int64_t kRenderPerSegment = 16;
inline constexpr std::int64_t kRenderPerPrimitive = 160;
inline constexpr std::int64_t kRenderRecordStep = std::int64_t{1} << 20;
inline constexpr std::int64_t kRenderPerBinEntry = 4;
}  // namespace cost

}  // namespace raster
