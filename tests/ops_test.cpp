// Issue 39, HTTP and operations conventions: Date on every answer, a 304's headers as RFC 9110 says, log
// lines that carry every field and stay one line, process_* and build metrics, the proxy's request id.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "access_log.h"
#include "flags.h"
#include "raster/version.h"
#include "scene_url_support.h"
#include "service_support.h"
#include "test_server.h"

namespace {

using test::TestServer;

const std::string kScene =
    R"({"width": 24, "height": 16, "primitives": [{"type": "triangle", "points": [[1,1],[22,3],[5,15]]}]})";

// The header block of a raw answer, as (lower-case name -> values in order).
std::multimap<std::string, std::string> headers_of(const std::string& raw) {
  std::multimap<std::string, std::string> out;
  const auto end = raw.find("\r\n\r\n");
  std::size_t at = raw.find("\r\n");
  while (at != std::string::npos && at < end) {
    const std::size_t next = raw.find("\r\n", at + 2);
    const std::string line = raw.substr(at + 2, next - at - 2);
    const auto colon = line.find(':');
    if (colon != std::string::npos) {
      std::string name = line.substr(0, colon);
      for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      std::string value = line.substr(colon + 1);
      while (!value.empty() && value.front() == ' ') value.erase(0, 1);
      out.emplace(name, value);
    }
    at = next;
  }
  return out;
}

// An IMF-fixdate ("Thu, 26 Nov 2026 17:24:01 GMT", RFC 9110 5.6.7) as seconds since 1970, -1 when the text
// is not exactly one.
long long imf_fixdate(const std::string& text) {
  std::tm tm{};
  const char* end = ::strptime(text.c_str(), "%a, %d %b %Y %H:%M:%S GMT", &tm);
  if (!end || *end != '\0' || text.size() != 29) return -1;
  return static_cast<long long>(::timegm(&tm));
}

long long now_seconds() {
  return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// The Date an answer carries is an IMF-fixdate within a day of the test's clock (the same machine's).
void expect_date(const std::string& date, const std::string& what) {
  const long long t = imf_fixdate(date);
  ASSERT_GE(t, 0) << what << ": Date is not an IMF-fixdate: \"" << date << "\"";
  EXPECT_LT(std::llabs(t - now_seconds()), 86'400) << what << ": " << date;
}

// RFC 9110 6.6.1: an origin server with a clock sends Date on every answer; caches use it for age. A 200,
// a problem (404) and cpp-httplib's own 414, answered before any route runs. What would break: the header
// set only on the render route, or only where the pre-routing handler ran.
TEST(Ops, EveryAnswerHasADateInImfFixdate) {
  TestServer server;
  auto ok = server.client().Get("/healthz");
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->status, 200);
  expect_date(ok->get_header_value("Date"), "200");

  auto missing = server.client().Get("/no-such-route");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  expect_date(missing->get_header_value("Date"), "404");

  RawClient c(server.port());
  ASSERT_TRUE(c.connected());
  ASSERT_TRUE(c.send("GET /" + std::string(9000, 'a') + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"));
  const std::string raw = c.receive_all();
  ASSERT_EQ(status_of(raw), 414) << raw.substr(0, 200);
  const auto headers = headers_of(raw);
  ASSERT_EQ(headers.count("date"), 1u) << raw;
  expect_date(headers.find("date")->second, "414");
}

// RFC 9110 8.6: a 304 may carry Content-Length only as the length the 200 would have had; none is also
// right. Content-Length: 0 tells a cache the image is empty. What would break: caches storing a 0-byte
// image for a URL.
// cpp-httplib 0.11 adds "Content-Length: 0" to every empty answer; the service writes its 304 as a HEAD
// answer of the length the client's tag carries (server/etag.h).
TEST(Ops, A304CarriesNoWrongContentLength) {
  TestServer server;
  const std::string url = "/render?scene=" + test::base64url(test::deflate(kScene));
  auto first = server.client().Get(url);
  ASSERT_TRUE(first);
  ASSERT_EQ(first->status, 200);
  const std::string tag = first->get_header_value("ETag");
  ASSERT_FALSE(tag.empty());

  RawClient c(server.port());
  ASSERT_TRUE(c.connected());
  ASSERT_TRUE(c.send("GET " + url + " HTTP/1.1\r\nHost: x\r\nIf-None-Match: " + tag +
                     "\r\nConnection: close\r\n\r\n"));
  const std::string raw = c.receive_all();
  ASSERT_EQ(status_of(raw), 304) << raw;
  const auto headers = headers_of(raw);
  const std::string head = raw.substr(0, raw.find("\r\n\r\n"));
  for (auto [at, end] = headers.equal_range("content-length"); at != end; ++at)
    EXPECT_EQ(at->second, std::to_string(first->body.size()))
        << "a 304's Content-Length is not the 200's length; the 304's headers:\n"
        << head;
  EXPECT_LE(headers.count("content-length"), 1u) << head;
  EXPECT_EQ(headers.count("date"), 1u) << head;
}

std::chrono::system_clock::time_point at_2026_11_26_17_24_01_042() {
  using namespace std::chrono;
  return sys_days{year{2026} / 11 / 26} + hours{17} + minutes{24} + seconds{1} + milliseconds{42};
}

rasterd::LogLine sample_line() {
  rasterd::LogLine l;
  l.wall = at_2026_11_26_17_24_01_042();
  l.client = "10.0.0.7";
  l.method = "POST";
  l.path = "/render";
  l.status = 200;
  l.bytes_in = 512;
  l.bytes_out = 2048;
  l.ms = 3.14;
  l.id = "r00000001";
  l.user_agent = "curl/7.88.1";
  return l;
}

// The text line carries every field operators look for, the time in ISO 8601 UTC to the millisecond.
// What would break: a line that cannot be matched with a proxy's (time, client, id) or searched by status.
TEST(Ops, TheTextLogLineCarriesEveryField) {
  const std::string line = sample_line().text();
  EXPECT_EQ(line,
            "2026-11-26T17:24:01.042Z 10.0.0.7 POST /render 200 in=512 out=2048 ms=3.1 id=r00000001 "
            "ua=\"curl/7.88.1\"\n");
}

// Client text (path, user agent) with a newline or a quote cannot split a line or forge a field. What would
// break: a request that writes a fake log line for another client.
TEST(Ops, ClientTextCannotSplitOrForgeALogLine) {
  rasterd::LogLine l = sample_line();
  l.path = "/render\n2026-11-26T00:00:00.000Z 1.2.3.4 GET /admin 200";
  l.user_agent = "x\" id=forged\ny";
  const std::string line = l.text();
  EXPECT_EQ(line.find('\n'), line.size() - 1) << line;
  int quotes = 0;  // unescaped: the user agent's opening and closing ones only
  for (std::size_t i = 0; i < line.size(); ++i) quotes += line[i] == '"' && (i == 0 || line[i - 1] != '\\');
  EXPECT_EQ(quotes, 2) << "a quote in the user agent must be escaped: " << line;

  const std::string json = l.json();
  EXPECT_EQ(json.find('\n'), json.size() - 1) << json;
  const auto j = nlohmann::json::parse(json);
  EXPECT_EQ(j["path"], l.path) << "JSON escapes, and keeps the text as sent";
  EXPECT_EQ(j["user_agent"], l.user_agent);
}

// The JSON line has every field with its type, for log collectors. What would break: a collector's
// parser or a dashboard's field.
TEST(Ops, TheJsonLogLineCarriesEveryField) {
  const std::string json = sample_line().json();
  ASSERT_EQ(json.back(), '\n');
  const auto j = nlohmann::json::parse(json);
  EXPECT_EQ(j["time"], "2026-11-26T17:24:01.042Z");
  EXPECT_EQ(j["client"], "10.0.0.7");
  EXPECT_EQ(j["method"], "POST");
  EXPECT_EQ(j["path"], "/render");
  EXPECT_EQ(j["status"], 200);
  EXPECT_EQ(j["bytes_in"], 512);
  EXPECT_EQ(j["bytes_out"], 2048);
  EXPECT_DOUBLE_EQ(j["ms"].get<double>(), 3.1);
  EXPECT_EQ(j["id"], "r00000001");
  EXPECT_EQ(j["user_agent"], "curl/7.88.1");
}

// A user agent that is not UTF-8 still gives a JSON line that parses (the bad bytes replaced), never an
// exception that loses the line. What would break: nlohmann's dump throwing type_error 316 in the logger.
TEST(Ops, AJsonLogLineSurvivesInvalidUtf8) {
  rasterd::LogLine l = sample_line();
  l.user_agent = "bad \xff\xfe bytes";
  l.path = "/render\xc3";
  std::string json;
  ASSERT_NO_THROW(json = l.json());
  const auto j = nlohmann::json::parse(json);
  EXPECT_EQ(j["user_agent"], "bad \xEF\xBF\xBD\xEF\xBF\xBD bytes");
  EXPECT_EQ(j["status"], 200);
}

// The process_* metrics every Prometheus client exports, and the build's versions. What would break: the
// alert on resident memory against the container's limit (issue 39 found none to set).
TEST(Ops, MetricsHaveProcessAndBuildInfo) {
  TestServer server;
  auto r = server.client().Get("/metrics");
  ASSERT_TRUE(r);
  const std::string& m = r->body;
  EXPECT_GT(metric(m, "process_resident_memory_bytes"), 0) << m;
  EXPECT_GE(metric(m, "process_cpu_seconds_total"), 0) << m;
  EXPECT_GT(metric(m, "process_open_fds"), 0) << m;
  EXPECT_GT(metric(m, "process_max_fds"), 0) << m;
  EXPECT_GE(metric(m, "process_max_fds"), metric(m, "process_open_fds"));
  const long start = metric(m, "process_start_time_seconds");
  EXPECT_LT(std::llabs(start - now_seconds()), 86'400) << "start time " << start;
  const std::string build = "\nrasterd_build_info{version=\"" RASTERD_VERSION "\",render_version=\"" +
                            std::to_string(raster::kRenderVersion) + "\"} 1\n";
  EXPECT_NE(m.find(build), std::string::npos) << "no" << build << "in\n" << m;
}

// A proxy's X-Request-Id comes back unchanged, so its log line and ours match. What would break: each
// replica numbering its own ids, nginx's lines matching none of them.
TEST(Ops, AClientsRequestIdComesBackUnchanged) {
  TestServer server;
  const std::string id = "3f2a9c1e-7b4d-4e21-9a0b-5c6d7e8f9a0b";
  auto r = server.client().Get("/healthz", {{"X-Request-Id", id}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->get_header_value("X-Request-Id"), id);
  auto rendered = server.client().Post("/render", {{"X-Request-Id", "edge.42"}}, kScene, "application/json");
  ASSERT_TRUE(rendered);
  EXPECT_EQ(rendered->status, 200);
  EXPECT_EQ(rendered->get_header_value("X-Request-Id"), "edge.42");
}

}  // namespace

// The face limit bounds every model format, so its flag is --max-model-faces; deployments that still write
// the name it had when only OBJ models were read keep their limit.
TEST(Ops, TheFaceLimitTakesItsNewAndItsOldName) {
  for (const char* flag : {"--max-model-faces", "--max-obj-faces"}) {
    rasterd::ServiceConfig config;
    std::string host;
    int port = 0;
    const char* argv[] = {flag, "1234"};
    EXPECT_EQ(rasterd::parse_service_flags(2, argv, config, host, port), "") << flag;
    EXPECT_EQ(config.limits.max_model_faces, 1234) << flag;
  }
  ::setenv("RASTERD_MAX_OBJ_FACES", "77", 1);
  rasterd::ServiceConfig config;
  std::string host;
  int port = 0;
  EXPECT_EQ(rasterd::parse_service_flags(0, nullptr, config, host, port), "");
  ::unsetenv("RASTERD_MAX_OBJ_FACES");
  EXPECT_EQ(config.limits.max_model_faces, 77);
}
