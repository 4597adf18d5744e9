#include "resources.h"

#include <sched.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "raster/budget.h"

namespace rasterd {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> split(const std::string& s, char by) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, by);) out.push_back(part);
  return out;
}

// A cgroup file's number: "max" (v2's none) and v1's "no limit" (2^63 rounded down to a page) are 0.
std::int64_t cgroup_number(const std::string& text) {
  if (text.empty() || text.starts_with("max")) return 0;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (end == text.c_str() || v <= 0 || v >= (1ll << 62)) return 0;
  return v;
}

// The folders of this process's cgroup for one hierarchy, innermost first up to the hierarchy's mount:
// /proc/self/cgroup names the cgroup ("0::/a/b" for v2, "4:memory:/a/b" for v1), /proc/self/mountinfo where
// that hierarchy is mounted and which cgroup the mount shows as its root (in a container: usually the
// container's own cgroup, mounted at /sys/fs/cgroup).
std::vector<std::string> cgroup_dirs(const std::string& root, bool v2, const std::string& controller) {
  std::string path;
  bool found = false;
  for (const std::string& line : split(read_text(root + "proc/self/cgroup"), '\n')) {
    const auto fields = split(line, ':');
    if (fields.size() < 3) continue;
    const auto controllers = split(fields[1], ',');
    const bool match =
        v2 ? fields[0] == "0" && fields[1].empty()
           : std::find(controllers.begin(), controllers.end(), controller) != controllers.end();
    if (!match) continue;
    path = line.substr(fields[0].size() + fields[1].size() + 2);
    found = true;
    break;
  }
  if (!found) return {};
  for (const std::string& line : split(read_text(root + "proc/self/mountinfo"), '\n')) {
    // "36 25 0:31 /mount-root /mount-point opts - fstype source super-opts"
    const auto dash = line.find(" - ");
    if (dash == std::string::npos) continue;
    const auto before = split(line.substr(0, dash), ' ');
    const auto after = split(line.substr(dash + 3), ' ');
    if (before.size() < 5 || after.size() < 3) continue;
    const bool is_v2 = after[0] == "cgroup2";
    if (v2 != is_v2 || (!v2 && after[0] != "cgroup")) continue;
    if (!v2) {
      const auto opts = split(after[2], ',');
      if (std::find(opts.begin(), opts.end(), controller) == opts.end()) continue;
    }
    const std::string& mount_root = before[3];
    const std::string& mount_point = before[4];
    // The cgroup relative to what the mount shows; outside it (another namespace's view) only the mount's
    // own folder is readable.
    std::string relative = path;
    if (mount_root != "/" && relative.starts_with(mount_root))
      relative = relative.substr(mount_root.size());
    else if (mount_root != "/")
      relative.clear();
    std::vector<std::string> dirs;
    std::string dir = root + mount_point.substr(1) + relative;
    while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
    const std::string top = root + mount_point.substr(1);
    while (true) {
      dirs.push_back(dir + "/");
      if (dir.size() <= top.size()) break;
      dir = dir.substr(0, dir.find_last_of('/'));
    }
    return dirs;
  }
  return {};
}

std::int64_t smallest_limit(const std::vector<std::string>& dirs, const std::string& file) {
  std::int64_t smallest = 0;
  for (const std::string& dir : dirs) {
    const std::int64_t v = cgroup_number(read_text(dir + file));
    if (v > 0 && (smallest == 0 || v < smallest)) smallest = v;
  }
  return smallest;
}

}  // namespace

ResourceLimit memory_limit(const std::string& root) {
  if (const std::int64_t v = smallest_limit(cgroup_dirs(root, true, ""), "memory.max"))
    return {v, "cgroup v2 memory.max"};
  if (const std::int64_t v = smallest_limit(cgroup_dirs(root, false, "memory"), "memory.limit_in_bytes"))
    return {v, "cgroup v1 memory.limit_in_bytes"};
  for (const std::string& line : split(read_text(root + "proc/meminfo"), '\n'))
    if (line.starts_with("MemTotal:"))
      return {std::strtoll(line.c_str() + 9, nullptr, 10) * 1024, "MemTotal"};
  return {};
}

ResourceLimit cpu_limit(const std::string& root) {
  ResourceLimit limit{1, "default"};
  cpu_set_t set;
  if (root == "/" && sched_getaffinity(0, sizeof set, &set) == 0) limit = {CPU_COUNT(&set), "affinity"};
  double quota = 0;  // CPUs' worth of time per period; 0: no quota
  for (const std::string& dir : cgroup_dirs(root, true, "")) {
    const auto fields = split(read_text(dir + "cpu.max"), ' ');
    if (fields.size() == 2 && cgroup_number(fields[0]) > 0 && cgroup_number(fields[1]) > 0) {
      const double q =
          static_cast<double>(cgroup_number(fields[0])) / static_cast<double>(cgroup_number(fields[1]));
      if (quota == 0 || q < quota) quota = q;
    }
  }
  if (quota == 0)
    for (const std::string& dir : cgroup_dirs(root, false, "cpu")) {
      const std::int64_t q = cgroup_number(read_text(dir + "cpu.cfs_quota_us"));
      const std::int64_t p = cgroup_number(read_text(dir + "cpu.cfs_period_us"));
      if (q > 0 && p > 0 && (quota == 0 || static_cast<double>(q) / static_cast<double>(p) < quota))
        quota = static_cast<double>(q) / static_cast<double>(p);
    }
  if (quota > 0) {
    const auto cpus = static_cast<std::int64_t>(std::ceil(quota - 1e-9));
    if (cpus < limit.value || limit.source == "default")
      limit = {std::max<std::int64_t>(1, cpus), "cgroup CPU quota"};
  }
  return limit;
}

std::int64_t default_memory_budget(const ResourceLimit& limit) {
  const std::int64_t set_aside =
      kBaselineBytes + static_cast<std::int64_t>(raster::kKeptRenderBytes) + kArenas * kTrimBytes;
  // Without a cgroup's limit the machine's memory is shared with everything else on it: three quarters.
  const std::int64_t usable = limit.source == "MemTotal" ? limit.value / 4 * 3 : limit.value;
  return std::max<std::int64_t>(usable - set_aside, std::int64_t{64} << 20);
}

std::int64_t parse_size(const std::string& text) {
  std::size_t i = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
  if (i == 0 || i > 15) return -1;
  std::int64_t v = std::stoll(text.substr(0, i));
  std::string unit = text.substr(i);
  if (unit.ends_with("B")) unit.pop_back();
  if (unit.ends_with("i")) unit.pop_back();
  static constexpr std::string_view kUnits = "KMGT";
  if (unit.empty()) return v;
  if (unit.size() != 1) return -1;
  const auto at = kUnits.find(static_cast<char>(std::toupper(static_cast<unsigned char>(unit[0]))));
  if (at == std::string_view::npos) return -1;
  for (std::size_t k = 0; k <= at; ++k) v *= 1024;
  return v;
}

}  // namespace rasterd
