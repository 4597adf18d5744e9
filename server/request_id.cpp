#include "request_id.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <ctime>

namespace rasterd {

thread_local RequestContext t_request;

namespace {

// RFC 9110 5.6.7's IMF-fixdate, for the Date header every answer carries (6.6.1).
std::string http_date(std::time_t when) {
  std::tm utc{};
  ::gmtime_r(&when, &utc);
  char buf[40];
  std::strftime(buf, sizeof buf, "%a, %d %b %Y %H:%M:%S GMT", &utc);
  return buf;
}

std::string next_request_id() {
  static std::atomic<std::uint64_t> counter{0};  // process-wide by nature: ids must be unique
  char buf[32];
  std::snprintf(buf, sizeof buf, "r%08llx", static_cast<unsigned long long>(++counter));
  return buf;
}

// A client's own request id is passed on when it is one a log line can carry as it is: short, and made of
// letters, digits and "-_.:". Anything else is replaced, so no client text reaches the logs unescaped.
bool plain_request_id(const std::string& id) {
  return !id.empty() && id.size() <= 64 && std::all_of(id.begin(), id.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' || c == ':';
  });
}

}  // namespace

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

void start_request(httplib::Response& res, const std::string& client_id) {
  t_request = RequestContext{Clock::now(), std::chrono::system_clock::now(), {}, 0};
  res.set_header("Date", http_date(std::chrono::system_clock::to_time_t(t_request.wall)));
  res.set_header("X-Request-Id", plain_request_id(client_id) ? client_id : next_request_id());
}

}  // namespace rasterd
