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

/// What each stage reserves, in bytes per counted thing: the resident peak each stage adds, measured with
/// tests/memory_estimate_test (VmHWM of a child process per model, face-dense and vertex-dense, in each
/// format) and rounded up; docs/memory.md has the measurements. A reservation is an upper bound of what the
/// stage holds at its peak, including std::vector's growth where a reader cannot size its arrays first.
namespace cost {
// Readers: what the parse holds at its peak, the finished Mesh included (the request body is the caller's).
inline constexpr std::int64_t kObjPerCorner = 64;  ///< per face corner (tinyobjloader's index and ours)
inline constexpr std::int64_t kObjPerVertex = 72;  ///< per v, vt or vn line (doubles there, floats here)
inline constexpr std::int64_t kStlPerFacet = 112;  ///< per triangle: three corners of its own
inline constexpr std::int64_t kPlyPerFace = 48;    ///< per face (its index list, then a triangle)
inline constexpr std::int64_t kPlyPerVertex = 48;  ///< per vertex (position, normal, colour)
inline constexpr std::int64_t kGltfPerByte = 2;    ///< per byte sent: tinygltf's copies of buffers and images
inline constexpr std::int64_t kGltfPerTriangle = 32;  ///< per triangle drawn (a node draws its mesh again)
inline constexpr std::int64_t kGltfPerVertex = 48;    ///< per vertex drawn: position, normal, colour, uv
inline constexpr std::int64_t kScenePerByte = 4;      ///< per byte of scene JSON: its primitives, parsed
// Render: per triangle and per vertex of 3D meshes (records, attributes, transformed corners), per 2D
// primitive, and 4 bytes per bin entry (counted before the bins are filled); the pixel buffers are the
// plan's.
inline constexpr std::int64_t kRenderPerTriangle = 192;
inline constexpr std::int64_t kRenderPerVertex = 48;
inline constexpr std::int64_t kRenderPerPoint = 56;  ///< a point's record (48 bytes) and its place in order
inline constexpr std::int64_t kRenderPerPrimitive = 160;
inline constexpr std::int64_t kRenderPerBinEntry = 4;
}  // namespace cost

}  // namespace raster
