// The service under load, faults and hostile input (issue 7), through real HTTP on loopback.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <future>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "support.h"
#include "test_server.h"

extern char** environ;

namespace {

using test::TestServer;

// A render that takes a few hundred milliseconds (seconds under sanitizers): 20 smooth triangles over
// 2048x2048, each covering half the image.
std::string slow_scene() {
  nlohmann::json prims = nlohmann::json::array();
  for (int i = 0; i < 20; ++i)
    prims.push_back({{"type", "triangle"},
                     {"points", {{0, 0}, {2048, 0}, {0, 2048}}},
                     {"colors", {"#ff0000", "#00ff00", "#0000ff"}}});
  return nlohmann::json{{"width", 2048}, {"height", 2048}, {"primitives", prims}}.dump();
}

// A raw TCP exchange: sends `request` (optionally dripping the tail), returns what came back.
class RawClient {
 public:
  explicit RawClient(int port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
    timeval tv{20, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  }
  ~RawClient() { ::close(fd_); }
  bool connected() const { return connected_; }
  bool send(const std::string& s) {
    return ::send(fd_, s.data(), s.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(s.size());
  }
  std::string receive_all() {
    std::string out;
    char buf[4096];
    for (ssize_t n; (n = ::recv(fd_, buf, sizeof buf, 0)) > 0;) out.append(buf, static_cast<std::size_t>(n));
    return out;
  }
  bool readable_within(int ms) {
    fd_set set;
    FD_ZERO(&set);
    FD_SET(fd_, &set);
    timeval tv{ms / 1000, (ms % 1000) * 1000};
    return ::select(fd_ + 1, &set, nullptr, nullptr, &tv) > 0;
  }

 private:
  int fd_ = -1;
  bool connected_ = false;
};

int status_of(const std::string& raw) {
  const auto sp = raw.find(' ');
  return sp == std::string::npos ? 0 : std::atoi(raw.c_str() + sp + 1);
}

// The value of the sample line `name value` in a Prometheus text body, -1 when absent.
long metric(const std::string& metrics, const std::string& name) {
  std::string needle(1, '\n');
  needle += name;
  needle += ' ';
  const auto at = metrics.find(needle);
  return at == std::string::npos ? -1 : std::lround(std::stod(metrics.substr(at + needle.size())));
}

TEST(Service, BodyOverTheCapIsRefusedFromItsDeclaredLengthBeforeReading) {
  rasterd::ServiceConfig config;
  config.max_body_bytes = 1000;
  TestServer server(config);
  RawClient c(server.port());
  ASSERT_TRUE(c.connected());
  // Headers only: if the server waited for the 10^8 promised bytes, no answer would come.
  ASSERT_TRUE(c.send("POST /render HTTP/1.1\r\nHost: x\r\nContent-Length: 100000000\r\n\r\n"));
  ASSERT_TRUE(c.readable_within(5000)) << "413 must not wait for the body";
  const std::string raw = c.receive_all();
  EXPECT_EQ(status_of(raw), 413);
  EXPECT_NE(raw.find("application/problem+json"), std::string::npos);
}

// A refused body is never read; what is left of it on the wire must not be parsed as a next request
// (request smuggling). Here the unread body is itself a complete request: exactly one response may come back.
TEST(Service, UnreadBodyOfARefusalIsNotParsedAsARequest) {
  TestServer server;
  RawClient c(server.port());
  ASSERT_TRUE(c.connected());
  const std::string smuggled = "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n";
  ASSERT_TRUE(c.send("POST /render HTTP/1.1\r\nHost: x\r\nContent-Encoding: gzip\r\nContent-Length: " +
                     std::to_string(smuggled.size()) + "\r\n\r\n" + smuggled));
  const std::string raw = c.receive_all();
  EXPECT_EQ(status_of(raw), 415);
  std::size_t responses = 0;
  for (std::size_t at = raw.find("HTTP/1.1 "); at != std::string::npos; at = raw.find("HTTP/1.1 ", at + 1))
    ++responses;
  EXPECT_EQ(responses, 1u) << raw;
}

TEST(Service, MalformedMultipartIsA400NotATimeout) {
  TestServer server;
  RawClient c(server.port());
  ASSERT_TRUE(c.connected());
  const std::string body = "--b\r\nno part headers here, and no closing boundary";
  ASSERT_TRUE(
      c.send("POST /render HTTP/1.1\r\nHost: x\r\nContent-Type: multipart/form-data; "
             "boundary=b\r\nContent-Length: " +
             std::to_string(body.size()) + "\r\n\r\n" + body));
  const std::string raw = c.receive_all();
  EXPECT_EQ(status_of(raw), 400) << raw.substr(0, 300);
  EXPECT_NE(raw.find("incomplete-body"), std::string::npos);
}

TEST(Service, ChunkedBodyIsCutAtTheCap) {
  rasterd::ServiceConfig config;
  config.max_body_bytes = 1000;
  TestServer server(config);
  RawClient c(server.port());
  ASSERT_TRUE(c.connected());
  std::string req = "POST /render HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n";
  for (int i = 0; i < 3; ++i) req += "258\r\n" + std::string(600, ' ') + "\r\n";  // 3 x 600 bytes
  req += "0\r\n\r\n";
  ASSERT_TRUE(c.send(req));
  EXPECT_EQ(status_of(c.receive_all()), 413);
}

TEST(Service, EachSceneLimitHasItsStatus) {
  rasterd::ServiceConfig config;
  config.limits.max_primitives = 3;
  config.limits.max_obj_faces = 1;
  config.limits.max_json_depth = 8;
  TestServer server(config);
  auto post = [&](const std::string& body) {
    return server.client().Post("/render", body, "application/json");
  };
  auto r = post(R"({"width": 4, "height": 4, "primitives": [{}, {}, {}, {}]})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  r = post("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\n");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  EXPECT_EQ(nlohmann::json::parse(r->body)["line"], 5);
  r = post(R"({"width": 4, "height": 4, "x": [[[[[[[[[[1]]]]]]]]]]})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  r = post(R"({"width": 8193, "height": 4})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
}

TEST(Service, SaturatedServiceRefusesAtOnceAndStaysHealthy) {
  rasterd::ServiceConfig config;
  config.workers = 1;
  config.max_queue = 1;
  config.render_threads = 1;
  TestServer server(config);
  const std::string scene = slow_scene();
  auto slow = [&] {
    return std::async(std::launch::async,
                      [&] { return server.client().Post("/render", scene, "application/json"); });
  };
  auto first = slow();
  auto second = slow();
  // Wait until one render runs and one waits.
  for (int i = 0; i < 2000; ++i) {
    const auto m = server.client().Get("/metrics");
    if (m && metric(m->body, "rasterd_renders_in_flight") == 1 &&
        metric(m->body, "rasterd_render_queue_length") == 1)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  auto third = server.client().Post("/render", scene, "application/json");
  auto health = server.client().Get("/healthz");
  const bool busy = first.wait_for(std::chrono::seconds(0)) == std::future_status::timeout;
  ASSERT_TRUE(third);
  EXPECT_EQ(third->status, 503);
  EXPECT_EQ(third->get_header_value("Retry-After"), "1");
  EXPECT_EQ(nlohmann::json::parse(third->body)["status"], 503);
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
  EXPECT_TRUE(busy) << "the refusal and the health check came while the first render was still running";
  // Nobody admitted is dropped.
  auto a = first.get(), b = second.get();
  ASSERT_TRUE(a);
  ASSERT_TRUE(b);
  EXPECT_EQ(a->status, 200);
  EXPECT_EQ(b->status, 200);
  const auto m = server.client().Get("/metrics");
  EXPECT_EQ(metric(m->body, "rasterd_rejected_total{reason=\"queue_full\"}"), 1);
}

// The kernel's count of connections dropped because a listen queue was full (/proc/net/netstat,
// TcpExt ListenOverflows), or -1 where it cannot be read.
long listen_overflows() {
  std::ifstream in("/proc/net/netstat");
  std::string names, values;
  while (std::getline(in, names) && std::getline(in, values)) {
    if (names.rfind("TcpExt:", 0) != 0) continue;
    std::istringstream n(names), v(values);
    std::string name, value;
    while (n >> name && v >> value)
      if (name == "ListenOverflows") return std::stol(value);
  }
  return -1;
}

// A burst of connections well past cpp-httplib's compiled-in listen backlog (5) and its thread count:
// every one is answered, and none overflows the listen queue (with the compiled-in backlog, dropped SYNs
// are retried by the kernel for seconds: measured 31 s for this burst instead of 0.07 s).
TEST(Service, ABurstOfConnectionsIsQueuedNotReset) {
  TestServer server;
  const long overflows_before = listen_overflows();
  std::vector<std::future<int>> burst;
  for (int i = 0; i < 200; ++i)
    burst.push_back(std::async(std::launch::async, [&] {
      auto r = server.client().Get("/healthz");
      return r ? r->status : -1;
    }));
  int ok = 0;
  for (auto& f : burst) ok += f.get() == 200;
  EXPECT_EQ(ok, 200);
  if (overflows_before >= 0) {
    EXPECT_EQ(listen_overflows(), overflows_before) << "the listen queue overflowed";
  }
}

TEST(Service, RenderPastItsDeadlineStopsWithA503) {
  rasterd::ServiceConfig config;
  config.render_deadline = std::chrono::milliseconds(20);
  TestServer server(config);
  auto r = server.client().Post("/render", slow_scene(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 503);
  EXPECT_EQ(nlohmann::json::parse(r->body)["type"], "urn:rasterd:problem:render-timeout");
}

TEST(Service, DrippingBodyIsCutAtTheDeadlineWhileOthersAreServed) {
  rasterd::ServiceConfig config;
  config.body_deadline = std::chrono::milliseconds(600);
  TestServer server(config);
  RawClient slow(server.port());
  ASSERT_TRUE(slow.connected());
  ASSERT_TRUE(slow.send("POST /render HTTP/1.1\r\nHost: x\r\nContent-Length: 100\r\n\r\n{"));
  std::atomic<bool> stop{false}, dripped_all{false};
  std::thread drip([&] {
    for (int i = 0; i < 99 && !stop; ++i) {  // one byte every 100 ms: 10 s in all
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      if (!slow.send(" ")) break;
    }
    dripped_all = !stop;
  });
  auto health = server.client().Get("/healthz");  // someone else is served meanwhile
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
  const std::string raw = slow.receive_all();  // returns when the server closes the connection
  const bool closed_while_dripping = !dripped_all;
  stop = true;
  drip.join();
  EXPECT_EQ(status_of(raw), 408) << raw.substr(0, 200);
  EXPECT_TRUE(closed_while_dripping)
      << "after the 408 the connection is closed, not read on as a next request";
}

TEST(Service, MetricsAndServerTiming) {
  TestServer server;
  auto r = server.client().Post("/render", R"({"width": 16, "height": 16})", "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  // "parse;dur=<ms>, raster;dur=<ms>, encode;dur=<ms>", each a non-negative number
  const std::string timing = r->get_header_value("Server-Timing");
  double parse = -1, raster_ms = -1, encode = -1;
  EXPECT_EQ(std::sscanf(timing.c_str(), "parse;dur=%lf, raster;dur=%lf, encode;dur=%lf", &parse, &raster_ms,
                        &encode),
            3)
      << timing;
  EXPECT_TRUE(parse >= 0 && raster_ms >= 0 && encode >= 0) << timing;
  server.client().Get("/nope");
  // cpp-httplib calls the logger, which counts the request, just after writing the response, on the
  // connection's own worker: a fast client can ask for /metrics before either earlier request is counted,
  // and the two may be counted in either order. Wait (bounded) for both.
  std::string body, content_type;
  for (int i = 0; i < 500; ++i) {
    if (auto m = server.client().Get("/metrics")) {
      body = m->body, content_type = m->get_header_value("Content-Type");
      if (metric(body, R"(rasterd_requests_total{route="other",status="404"})") == 1 &&
          metric(body, R"(rasterd_requests_total{route="/render",status="200"})") == 1)
        break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_EQ(content_type, "text/plain; version=0.0.4");
  EXPECT_EQ(metric(body, R"(rasterd_requests_total{route="/render",status="200"})"), 1);
  EXPECT_EQ(metric(body, R"(rasterd_requests_total{route="other",status="404"})"), 1);
  EXPECT_EQ(metric(body, "rasterd_render_duration_seconds_count"), 1);
  EXPECT_EQ(metric(body, "rasterd_renders_in_flight"), 0);
  EXPECT_GT(metric(body, R"(rasterd_bytes_total{direction="out"})"), 50);
}

// SIGTERM during a batch: every request accepted before the signal gets its 200, then exit 0.
TEST(Service, SigtermLetsAcceptedRendersFinish) {
  int port = 0;
  {  // a free port for the child (the small race with other processes is acceptable on loopback)
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    socklen_t len = sizeof addr;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
    port = ntohs(addr.sin_port);
    ::close(fd);
  }
  const std::string port_text = std::to_string(port);
  const char* argv[] = {RASTERD_BINARY, "serve", "--host",           "127.0.0.1", "--port", port_text.c_str(),
                        "--workers",    "1",     "--render-threads", "1",         nullptr};
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, RASTERD_BINARY, nullptr, nullptr, const_cast<char**>(argv), environ), 0);
  httplib::Client probe("127.0.0.1", port);
  bool up = false;
  for (int i = 0; i < 500 && !up; ++i) {
    auto h = probe.Get("/healthz");
    up = h && h->status == 200;
    if (!up) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(up);
  const std::string scene = slow_scene();
  std::vector<std::future<httplib::Result>> batch;
  for (int i = 0; i < 3; ++i)
    batch.push_back(std::async(std::launch::async, [&] {
      httplib::Client c("127.0.0.1", port);
      c.set_read_timeout(120);
      return c.Post("/render", scene, "application/json");
    }));
  for (int i = 0; i < 2000; ++i) {  // all three accepted: one running, two queued
    const auto m = probe.Get("/metrics");
    if (m && metric(m->body, "rasterd_renders_in_flight") == 1 &&
        metric(m->body, "rasterd_render_queue_length") == 2)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  for (auto& f : batch) {
    auto r = f.get();
    ASSERT_TRUE(r) << "an accepted request lost its response";
    EXPECT_EQ(r->status, 200);
  }
  int wstatus = 0;
  ASSERT_EQ(::waitpid(pid, &wstatus, 0), pid);
  EXPECT_TRUE(WIFEXITED(wstatus));
  EXPECT_EQ(WEXITSTATUS(wstatus), 0);
  httplib::Client after("127.0.0.1", port);
  EXPECT_FALSE(after.Get("/healthz")) << "no new connections after shutdown";
}

}  // namespace
