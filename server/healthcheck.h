// `rasterd healthcheck`: the container's HEALTHCHECK. It asks the running server for GET /healthz at the
// address that server was given, read from its /proc/PID/cmdline and environ, so that
// `IMAGE serve --port 9000` is checked on 9000 and not on the image's default port.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rasterd {

// The strings of a NUL-separated /proc buffer (cmdline, environ). A trailing NUL ends the last string; it
// does not start an empty one. Empty strings in the middle are kept: they are arguments too.
std::vector<std::string> split_nul(std::string_view buffer);

// Where to ask, and where each half of it came from (for the one line the check prints).
struct HealthTarget {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string host_source = "the default";
  std::string port_source = "the default";
  std::string error;  // not empty: the port cannot be told (not a port number, or 0 = any free port)
};

// The address `rasterd serve` listens on, decided as the server decides it (parse_service_flags in
// server/flags.cpp): the flags after `serve` (`--port N`, `--port=N`, `--host H`, `--host=H`; the last
// one wins), else RASTERD_PORT, then PORT, and RASTERD_HOST in the environment, else 0.0.0.0:8080. An
// address of every interface (0.0.0.0, ::, empty) is asked on 127.0.0.1. `flag_host` and `flag_port` (the
// healthcheck's own flags) win over all of it.
HealthTarget health_target(const std::vector<std::string>& cmdline,
                           const std::vector<std::string>& environment,
                           const std::optional<std::string>& flag_host = std::nullopt,
                           const std::optional<std::string>& flag_port = std::nullopt);

// GET http://host:port/healthz, 2 s for the connection and 2 s for each read or write. True on a 200;
// `why` says what happened either way.
bool probe_health(const std::string& host, int port, std::string& why);

// The subcommand: `rasterd healthcheck [--pid N] [--host H] [--port N]` (PID 1 by default). Prints one
// line; returns the exit code: 0 healthy, 1 not. Docker reserves 2, so a usage error is a 1 too.
int run_healthcheck(const std::vector<std::string>& args);

}  // namespace rasterd
