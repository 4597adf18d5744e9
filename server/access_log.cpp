#include "access_log.h"

#include <cstdio>
#include <ctime>

#include <nlohmann/json.hpp>

#include "raster/utf8.h"

namespace rasterd {
namespace {

std::string iso_time(std::chrono::system_clock::time_point t) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(t);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(t.time_since_epoch()).count() % 1000;
  std::tm utc{};
  ::gmtime_r(&seconds, &utc);
  char buf[40];
  const std::size_t n = std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &utc);
  std::snprintf(buf + n, sizeof buf - n, ".%03dZ", static_cast<int>(ms));
  return buf;
}

}  // namespace

std::string LogLine::text() const {
  std::string ua = raster::escape_for_display(user_agent);
  for (std::size_t at = 0; (at = ua.find('"', at)) != std::string::npos; at += 2) ua.replace(at, 1, "\\\"");
  char numbers[120];
  std::snprintf(numbers, sizeof numbers, " %d in=%zu out=%zu ms=%.1f id=", status, bytes_in, bytes_out, ms);
  return iso_time(wall) + " " + (client.empty() ? "-" : client) + " " + method + " " +
         raster::escape_for_display(path) + numbers + id + " ua=\"" + ua + "\"\n";
}

std::string LogLine::json() const {
  const nlohmann::json j = {{"time", iso_time(wall)},
                            {"client", client},
                            {"method", method},
                            {"path", path},
                            {"status", status},
                            {"bytes_in", bytes_in},
                            {"bytes_out", bytes_out},
                            {"ms", static_cast<double>(static_cast<long long>(ms * 10)) / 10},
                            {"id", id},
                            {"user_agent", user_agent}};
  // Client text that is not UTF-8 is replaced (U+FFFD), never a reason to lose the line.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace rasterd
