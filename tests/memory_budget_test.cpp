// Issue 39: the memory budget that admission enforces (server/memory_budget.h), the limits it is sized
// from (server/resources.h), and a small budget through real HTTP. Every verdict is an order of events or
// an answer: no test depends on how long a wait lasts.
#include <stdlib.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <future>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "memory_budget.h"
#include "raster/budget.h"
#include "resources.h"
#include "service_support.h"
#include "test_server.h"

namespace {

using rasterd::MemoryPool;
using test::TestServer;
using Clock = MemoryPool::Clock;

// ---- MemoryPool ----

// Takes add up, gives subtract, the peak is the most held at once. What would break: the reservation
// gauge and the budget's arithmetic (a give lost would shrink the budget for good).
TEST(MemoryPool, TakeGiveAndPeak) {
  MemoryPool pool(100);
  EXPECT_TRUE(pool.take(60, Clock::now()));
  EXPECT_TRUE(pool.take(30, Clock::now()));
  EXPECT_EQ(pool.reserved(), 90);
  EXPECT_EQ(pool.peak(), 90);
  pool.give(60);
  EXPECT_EQ(pool.reserved(), 30);
  EXPECT_EQ(pool.peak(), 90) << "the peak stays";
  EXPECT_TRUE(pool.take(70, Clock::now()));
  EXPECT_EQ(pool.reserved(), 100);
  EXPECT_EQ(pool.peak(), 100);
  EXPECT_FALSE(pool.take(1, Clock::now())) << "full";
  EXPECT_EQ(pool.reserved(), 100) << "a refused take holds nothing";
  pool.give(100);
  EXPECT_EQ(pool.reserved(), 0);
  EXPECT_EQ(pool.capacity(), 100);
}

// More than the capacity can never be had: refused at once even with no deadline to the wait (if it waited,
// this test would never end). What would break: a request that could never fit waiting out the queue's
// bound instead of getting its 413/422.
TEST(MemoryPool, MoreThanTheCapacityIsRefusedAtOnce) {
  MemoryPool pool(100);
  EXPECT_FALSE(pool.take(101, Clock::time_point::max()));
  EXPECT_EQ(pool.reserved(), 0);
}

// A take that does not fit waits until another request gives back, and then succeeds: the log shows the
// give before the take returned. What would break: a waiter that is never woken (notify lost) or one that
// takes what is not free.
TEST(MemoryPool, ATakeWaitsUntilAnotherGives) {
  MemoryPool pool(100);
  ASSERT_TRUE(pool.take(80, Clock::now()));
  std::mutex m;
  std::vector<std::string> log;
  auto note = [&](const char* what) {
    std::lock_guard lock(m);
    log.emplace_back(what);
  };
  std::promise<void> asking;
  std::thread waiter([&] {
    asking.set_value();
    const bool taken = pool.take(50, Clock::time_point::max());  // 80 + 50 > 100: must wait
    note(taken ? "taken" : "refused");
  });
  asking.get_future().wait();
  note("give");
  pool.give(80);
  waiter.join();
  EXPECT_EQ(log, (std::vector<std::string>{"give", "taken"}));
  EXPECT_EQ(pool.reserved(), 50);
}

// A request's account gives back everything it holds when it ends, and wanted() is what it would have
// needed when refused. What would break: a request's memory leaking from the budget (the gauge creeping
// up until every request is refused), or the 422 that says how much was needed.
TEST(MemoryPool, ARequestBudgetGivesBackAllItHeld) {
  MemoryPool pool(1000);
  {
    rasterd::RequestBudget budget(pool, std::chrono::milliseconds(0));
    EXPECT_TRUE(budget.reserve(300));
    EXPECT_TRUE(budget.reserve(200));
    budget.release(100);
    EXPECT_EQ(budget.held(), 400);
    EXPECT_EQ(pool.reserved(), 400);
    EXPECT_FALSE(budget.reserve(5000));
    EXPECT_EQ(budget.wanted(), 5400);
    budget.start_render(Clock::now() - std::chrono::seconds(1), nullptr);
    EXPECT_TRUE(budget.expired()) << "past its deadline";
  }
  EXPECT_EQ(pool.reserved(), 0);
  EXPECT_EQ(pool.peak(), 500);
}

// ---- resources: limits read from fake /proc and /sys trees ----

// A temporary folder standing for "/", removed at the end.
class FakeRoot {
 public:
  FakeRoot() {
    char tmpl[] = "/tmp/rasterd-resources-XXXXXX";
    const char* made = ::mkdtemp(tmpl);
    if (!made) throw std::runtime_error("mkdtemp failed");
    dir_ = made;
  }
  ~FakeRoot() { std::filesystem::remove_all(dir_); }
  void write(const std::string& path, const std::string& text) {
    const std::filesystem::path p = dir_ / path;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
  }
  std::string root() const { return dir_.string() + "/"; }  ///< as resources.h wants it: ends with '/'

 private:
  std::filesystem::path dir_;
};

constexpr const char* kV2Mount = "30 25 0:26 / /sys/fs/cgroup rw,nosuid,nodev,noexec - cgroup2 cgroup2 rw\n";

// cgroup v2: the process's own cgroup has memory.max, those above say "max". What would break: the budget
// of a container under `--memory 1g` taken from the host's memory, so the kernel kills it first.
TEST(Resources, CgroupV2MemoryMax) {
  FakeRoot fs;
  fs.write("proc/self/cgroup", "0::/kubepods/pod1/c1\n");
  fs.write("proc/self/mountinfo", kV2Mount);
  fs.write("sys/fs/cgroup/kubepods/pod1/c1/memory.max", "1073741824\n");
  fs.write("sys/fs/cgroup/kubepods/pod1/memory.max", "max\n");
  fs.write("sys/fs/cgroup/kubepods/memory.max", "max\n");
  fs.write("proc/meminfo", "MemTotal:       16384000 kB\n");
  const rasterd::ResourceLimit limit = rasterd::memory_limit(fs.root());
  EXPECT_EQ(limit.value, 1073741824);
  EXPECT_EQ(limit.source, "cgroup v2 memory.max");
}

// A parent's smaller limit binds a child without one of its own (a Kubernetes pod's limit, its container's
// "max"). What would break: reading only the innermost cgroup.
TEST(Resources, CgroupV2ParentsSmallerLimitBinds) {
  FakeRoot fs;
  fs.write("proc/self/cgroup", "0::/kubepods/pod1/c1\n");
  fs.write("proc/self/mountinfo", kV2Mount);
  fs.write("sys/fs/cgroup/kubepods/pod1/c1/memory.max", "1073741824\n");
  fs.write("sys/fs/cgroup/kubepods/pod1/memory.max", "536870912\n");
  fs.write("sys/fs/cgroup/kubepods/memory.max", "max\n");
  EXPECT_EQ(rasterd::memory_limit(fs.root()).value, 536870912);
}

// Inside a container the mount shows the container's own cgroup as its root: its limit is in the mount's
// top folder. What would break: looking for /sys/fs/cgroup/<the host's path>, which is not there.
TEST(Resources, CgroupV2SeenFromInsideAContainer) {
  FakeRoot fs;
  fs.write("proc/self/cgroup", "0::/docker/abc\n");
  fs.write("proc/self/mountinfo", "30 25 0:26 /docker/abc /sys/fs/cgroup ro - cgroup2 cgroup2 rw\n");
  fs.write("sys/fs/cgroup/memory.max", "2147483648\n");
  EXPECT_EQ(rasterd::memory_limit(fs.root()).value, 2147483648);
}

// cgroup v1 (and a hybrid host's empty v2 line): memory.limit_in_bytes, where v1's "no limit" (2^63 less a
// page) above it is none. What would break: the budget of a container on an older host.
TEST(Resources, CgroupV1MemoryLimitInBytes) {
  FakeRoot fs;
  fs.write("proc/self/cgroup", "5:cpu,cpuacct:/docker/abc\n4:memory:/docker/abc\n0::/\n");
  fs.write("proc/self/mountinfo",
           "40 30 0:35 / /sys/fs/cgroup/memory rw,nosuid - cgroup cgroup rw,memory\n"
           "41 30 0:36 / /sys/fs/cgroup/cpu,cpuacct rw,nosuid - cgroup cgroup rw,cpu,cpuacct\n");
  fs.write("sys/fs/cgroup/memory/docker/abc/memory.limit_in_bytes", "1073741824\n");
  fs.write("sys/fs/cgroup/memory/docker/memory.limit_in_bytes", "9223372036854771712\n");
  fs.write("sys/fs/cgroup/memory/memory.limit_in_bytes", "9223372036854771712\n");
  const rasterd::ResourceLimit limit = rasterd::memory_limit(fs.root());
  EXPECT_EQ(limit.value, 1073741824);
  EXPECT_EQ(limit.source, "cgroup v1 memory.limit_in_bytes");
}

// No cgroup limit anywhere: the machine's memory (MemTotal, in kB). What would break: a budget of 0 (every
// request refused) or of "unlimited" on a bare host.
TEST(Resources, WithoutACgroupLimitTheMachinesMemory) {
  FakeRoot fs;
  fs.write("proc/self/cgroup", "0::/user.slice\n");
  fs.write("proc/self/mountinfo", kV2Mount);
  fs.write("sys/fs/cgroup/user.slice/memory.max", "max\n");
  fs.write("proc/meminfo", "MemTotal:       16384000 kB\nMemFree:         1000000 kB\n");
  const rasterd::ResourceLimit limit = rasterd::memory_limit(fs.root());
  EXPECT_EQ(limit.value, std::int64_t{16384000} * 1024);
  EXPECT_EQ(limit.source, "MemTotal");
}

// cpu.max "150000 100000" is 1.5 CPUs' time: 2 render threads (rounded up). What would break: `--cpus 1.5`
// ignored, threads from the machine's cores.
TEST(Resources, CgroupV2CpuQuota) {
  FakeRoot fs;
  fs.write("proc/self/cgroup", "0::/c1\n");
  fs.write("proc/self/mountinfo", kV2Mount);
  fs.write("sys/fs/cgroup/c1/cpu.max", "150000 100000\n");
  fs.write("sys/fs/cgroup/cpu.max", "max 100000\n");
  const rasterd::ResourceLimit limit = rasterd::cpu_limit(fs.root());
  EXPECT_EQ(limit.value, 2);
  EXPECT_EQ(limit.source, "cgroup CPU quota");
}

// cgroup v1: cpu.cfs_quota_us / cpu.cfs_period_us (-1 above: none). What would break: the quota of a
// container on an older host ignored.
TEST(Resources, CgroupV1CfsQuota) {
  FakeRoot fs;
  fs.write("proc/self/cgroup", "5:cpu,cpuacct:/docker/abc\n4:memory:/docker/abc\n0::/\n");
  fs.write("proc/self/mountinfo",
           "41 30 0:36 / /sys/fs/cgroup/cpu,cpuacct rw,nosuid - cgroup cgroup rw,cpu,cpuacct\n");
  fs.write("sys/fs/cgroup/cpu,cpuacct/docker/abc/cpu.cfs_quota_us", "250000\n");
  fs.write("sys/fs/cgroup/cpu,cpuacct/docker/abc/cpu.cfs_period_us", "100000\n");
  fs.write("sys/fs/cgroup/cpu,cpuacct/docker/cpu.cfs_quota_us", "-1\n");
  fs.write("sys/fs/cgroup/cpu,cpuacct/docker/cpu.cfs_period_us", "100000\n");
  EXPECT_EQ(rasterd::cpu_limit(fs.root()).value, 3);
}

// What --memory-budget accepts. What would break: "1.5G" read as 1 byte or 1 GiB, "12X" as 12 bytes.
TEST(Resources, ParseSize) {
  EXPECT_EQ(rasterd::parse_size("2G"), std::int64_t{2} << 30);
  EXPECT_EQ(rasterd::parse_size("1536M"), std::int64_t{1536} << 20);
  EXPECT_EQ(rasterd::parse_size("1024"), 1024);
  EXPECT_EQ(rasterd::parse_size("2GiB"), std::int64_t{2} << 30);
  EXPECT_EQ(rasterd::parse_size("64k"), 64 << 10);
  EXPECT_EQ(rasterd::parse_size("1.5G"), -1);
  EXPECT_EQ(rasterd::parse_size("12X"), -1);
  EXPECT_EQ(rasterd::parse_size(""), -1);
  EXPECT_EQ(rasterd::parse_size("G"), -1);
}

// Under a 2 GiB cgroup: 2048 MiB less the 480 MiB set aside (96 MiB baseline, 256 MiB of kept render
// arrays, 4 arenas x 32 MiB). What would break: the manifest's numbers in docs/memory.md.
TEST(Resources, DefaultBudgetUnderATwoGibCgroup) {
  EXPECT_EQ(rasterd::default_memory_budget({std::int64_t{2} << 30, "cgroup v2 memory.max"}),
            std::int64_t{2048 - 480} << 20);
}

// ---- A small budget through HTTP ----

constexpr std::int64_t kBudget = std::int64_t{4} << 20;

rasterd::ServiceConfig small_budget() {
  rasterd::ServiceConfig config;
  config.memory_budget = kBudget;
  config.max_queue_wait = std::chrono::milliseconds(50);  // refusals come fast; no verdict depends on it
  config.workers = 2;
  return config;
}

// An OBJ of one small triangle padded with comments to `bytes`: its body is large, what it parses to is
// not (the reader reserves from its counts, comments cost nothing).
std::string padded_obj(std::size_t bytes) {
  std::string s = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string comment = "# " + std::string(97, 'x') + "\n";  // 100 bytes
  while (s.size() + comment.size() <= bytes) s += comment;
  return s;
}

std::string problem_type(const std::string& body) {
  const auto j = nlohmann::json::parse(body, nullptr, false);
  return j.is_object() && j.contains("type") ? j["type"].get<std::string>() : "(not a problem: " + body + ")";
}

// A declared body larger than the whole budget can never be held: 413 from the headers alone, before
// any of it is read (the body never comes; an answer does). What would break: bodies read whole before
// admission, issue 39's 274 connections x 32 MiB.
TEST(MemoryBudget, ABodyLargerThanTheBudgetIsA413BeforeItIsRead) {
  TestServer server(small_budget());
  RawClient c(server.port());
  ASSERT_TRUE(c.connected());
  ASSERT_TRUE(c.send("POST /render HTTP/1.1\r\nHost: x\r\nContent-Type: model/obj\r\nContent-Length: " +
                     std::to_string(kBudget + 1) + "\r\n\r\n"));
  const std::string raw = c.receive_all();
  EXPECT_EQ(status_of(raw), 413) << raw;
  EXPECT_NE(raw.find("urn:rasterd:problem:body-too-large"), std::string::npos) << raw;
}

// A model whose reader needs more than the whole budget: 422 memory-limit (waiting could never help, so not
// a 503). 350,000 triangles of 12 bytes = 4.2 MB, over 4 MiB, from a 2.8 MB body. What would break: the
// reader's reservation missing (the model parsed anyway) or refused as if it were temporary.
TEST(MemoryBudget, AModelThatCouldNeverFitIsA422MemoryLimit) {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 350'000; ++i) obj += "f 1 2 3\n";
  static_assert(sizeof(std::array<std::uint32_t, 3>) * 350'000 > kBudget);
  TestServer server(small_budget());
  auto r = server.client().Post("/render?width=16&height=16", obj, "model/obj");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422) << r->body;
  EXPECT_EQ(problem_type(r->body), "urn:rasterd:problem:memory-limit");
  EXPECT_FALSE(r->has_header("Retry-After"));
}

// Two requests whose bodies together exceed the budget: the first is held after admission (its 3 MiB
// body reserved), the second (2 MiB) cannot get its reservation within the queue's wait and gets a 503
// with Retry-After; released, the first renders. Afterwards nothing is reserved. What would break: requests
// together holding more than the budget (issue 39's OOM kill), or a reservation never given back.
TEST(MemoryBudget, ASecondRequestThatDoesNotFitNowIsA503AndTheFirstCompletes) {
  Gate gate;
  std::promise<void> inside;
  std::atomic<int> admitted{0};
  rasterd::ServiceConfig config = small_budget();
  config.after_admission = [&] {
    if (admitted++ == 0) {  // the first request only: it holds its reservation until the test opens
      inside.set_value();
      gate.wait();
    }
  };
  TestServer server(config);
  const std::string first_body = padded_obj(std::size_t{3} << 20);
  const std::string second_body = padded_obj(std::size_t{2} << 20);
  auto first = std::async(std::launch::async, [&] {
    return server.client().Post("/render?width=16&height=16", first_body, "model/obj");
  });
  inside.get_future().wait();

  auto held = server.client().Get("/metrics");
  ASSERT_TRUE(held);
  EXPECT_EQ(metric(held->body, "rasterd_memory_reserved_bytes"), static_cast<long>(first_body.size()))
      << "the held request's reservation is its declared body";

  auto second = server.client().Post("/render?width=16&height=16", second_body, "model/obj");
  ASSERT_TRUE(second);
  EXPECT_EQ(second->status, 503) << second->body;
  EXPECT_TRUE(second->has_header("Retry-After"));
  EXPECT_EQ(problem_type(second->body), "urn:rasterd:problem:overloaded");

  gate.open();
  auto r = first.get();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;

  auto m = server.client().Get("/metrics");
  ASSERT_TRUE(m);
  EXPECT_EQ(metric(m->body, "rasterd_memory_reserved_bytes"), 0);
  EXPECT_EQ(metric(m->body, "rasterd_memory_budget_bytes"), kBudget);
  EXPECT_GT(metric(m->body, "rasterd_memory_reserved_peak_bytes"), 0);
}

}  // namespace
