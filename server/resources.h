// What this process may use, as its container sees it: memory (the cgroup's limit, else the machine's) and
// CPUs (its affinity mask and the cgroup's CPU quota). The service sizes its memory budget, workers and
// render threads from these, so that the defaults follow `docker run --memory 2g --cpus 2` and Kubernetes'
// limits without flags.
#pragma once

#include <cstdint>
#include <string>

namespace rasterd {

/// A limit and where it was read.
struct ResourceLimit {
  std::int64_t value = 0;  ///< bytes (memory) or CPUs; 0 when nothing limits it
  std::string source;      ///< e.g. "cgroup v1 memory.limit_in_bytes", "MemTotal", "affinity"
};

/// The memory the process may use: the smallest limit of its memory cgroup and the cgroups above it (v2
/// memory.max, v1 memory.limit_in_bytes; "max" and v1's near-2^63 mean none), else physical memory
/// (MemTotal). `root` prefixes every path read ("/" on a real system; tests build a tree elsewhere).
ResourceLimit memory_limit(const std::string& root = "/");

/// The CPUs the process may use: the CPUs of its affinity mask, and fewer when its cgroup's quota allows
/// fewer (v2 cpu.max, v1 cpu.cfs_quota_us / cpu.cfs_period_us, rounded up), at least 1.
ResourceLimit cpu_limit(const std::string& root = "/");

/// The memory budget for a memory limit: what requests may reserve, after the process's own baseline (code,
/// threads' stacks, PNG encoders: kBaselineBytes), the render arrays the library keeps for reuse between
/// renders (raster::kKeptRenderBytes) and the freed memory the heap may keep (kArenas x kTrimBytes) are set
/// aside. Without a cgroup's limit, three quarters of the machine's memory is the limit. At least 64 MiB.
std::int64_t default_memory_budget(const ResourceLimit& limit);
inline constexpr std::int64_t kBaselineBytes = std::int64_t{96} << 20;
/// The heap's share of what is set aside: `rasterd serve` allows glibc kArenas arenas, each keeping at most
/// kTrimBytes of freed memory before it gives it back to the kernel (server/main.cpp).
inline constexpr int kArenas = 4;
/// Allocations from this size up are mapped apart and unmapped when freed, so a request's body never stays
/// behind as a hole in a heap (48 freed 32 MiB bodies held 1.1 GB that no request had reserved). 16 MiB, not
/// less: a 400k-face OBJ's parse arrays below it reuse warm heap pages (at 4 MiB its parse took 165 ms
/// instead of 153, every page faulted in afresh).
inline constexpr std::int64_t kMmapBytes = std::int64_t{16} << 20;
inline constexpr std::int64_t kTrimBytes = std::int64_t{32} << 20;

/// "1536M", "2G", "1073741824" (K, M, G and T are powers of 1024; an optional "i" or "B" after them is
/// allowed). -1 when the text is not such a size.
std::int64_t parse_size(const std::string& text);

}  // namespace rasterd
