#include "healthcheck.h"

#include <httplib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>

namespace rasterd {

std::vector<std::string> split_nul(std::string_view buffer) {
  std::vector<std::string> out;
  while (!buffer.empty()) {
    const std::size_t end = buffer.find('\0');
    out.emplace_back(buffer.substr(0, end));
    if (end == std::string_view::npos) break;  // the kernel ends each string with a NUL; a cut buffer may not
    buffer.remove_prefix(end + 1);
  }
  return out;
}

namespace {

// The value of NAME in an environment (the first one, as getenv finds it).
std::optional<std::string> env_value(const std::vector<std::string>& environment, std::string_view name) {
  for (const std::string& entry : environment)
    if (entry.size() > name.size() && entry.compare(0, name.size(), name) == 0 && entry[name.size()] == '=')
      return entry.substr(name.size() + 1);
  return std::nullopt;
}

// "8080" -> 8080; anything but 1..65535 in plain decimal is an error. Port 0 is valid for the server (any
// free port) but cannot be asked: only the server's own "listening on" line names the port it got.
std::string parse_port(const std::string& text, int& port) {
  if (text.empty() || text.size() > 5 ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return "'" + text + "' is not a port number";
  port = std::stoi(text);
  if (port == 0) return "port 0 (any free port) cannot be asked: give the port with --port";
  if (port > 65535) return "'" + text + "' is not a port number";
  return "";
}

std::string url_of(const std::string& host, int port) {
  const bool v6 = host.find(':') != std::string::npos;
  return "http://" + (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port) + "/healthz";
}

bool read_file(const std::string& path, std::string& out, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot read " + path + ": " + std::strerror(errno);
    return false;
  }
  out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) {
    error = "cannot read " + path + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace

HealthTarget health_target(const std::vector<std::string>& cmdline,
                           const std::vector<std::string>& environment,
                           const std::optional<std::string>& flag_host,
                           const std::optional<std::string>& flag_port) {
  std::optional<std::string> host, port;
  std::string host_source, port_source;
  // The server's flags follow `serve`; a wrapper (taskset, tini, sh -c) may come before it. Every token is
  // `--name value` or `--name=value`, so a value is never read as a flag (as parse_service_flags reads them).
  auto at = std::find(cmdline.begin() + std::min<std::size_t>(1, cmdline.size()), cmdline.end(), "serve");
  at = at == cmdline.end() ? cmdline.begin() + std::min<std::size_t>(1, cmdline.size()) : at + 1;
  for (; at != cmdline.end(); ++at) {
    if (at->rfind("--", 0) != 0) continue;
    std::string name = at->substr(2), value;
    if (const std::size_t eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    } else if (at + 1 != cmdline.end()) {
      value = *++at;
    } else {
      break;  // a flag without its value: the server refused to start
    }
    if (name == "port") port = value, port_source = "--port in its command line";
    if (name == "host") host = value, host_source = "--host in its command line";
  }
  if (!port) {
    if ((port = env_value(environment, "RASTERD_PORT")))
      port_source = "RASTERD_PORT in its environment";
    else if ((port = env_value(environment, "PORT")))
      port_source = "PORT in its environment";
  }
  if (!host && (host = env_value(environment, "RASTERD_HOST")))
    host_source = "RASTERD_HOST in its environment";
  if (flag_port) port = flag_port, port_source = "--port of healthcheck";
  if (flag_host) host = flag_host, host_source = "--host of healthcheck";

  HealthTarget target;
  if (port) {
    target.port_source = port_source;
    target.error = parse_port(*port, target.port);
  }
  if (host) {
    target.host_source = host_source;
    // The server listens on every interface: loopback is one of them, and the one a check inside the
    // container (or on the host, for --network host) can always reach.
    target.host = *host == "0.0.0.0" || *host == "::" || host->empty() ? "127.0.0.1" : *host;
  }
  return target;
}

bool probe_health(const std::string& host, int port, std::string& why) {
  httplib::Client client(host, port);
  client.set_connection_timeout(2);
  client.set_read_timeout(2);
  client.set_write_timeout(2);
  const std::string url = url_of(host, port);
  const httplib::Result result = client.Get("/healthz");
  if (!result) {
    switch (result.error()) {  // httplib's own names ("Connection", "Read") say little in a health log
      case httplib::Error::Connection:
        why = "cannot connect to " + url + " (refused or unreachable)";
        break;
      case httplib::Error::ConnectionTimeout:
        why = "cannot connect to " + url + " within 2 s";
        break;
      case httplib::Error::Read:
        why = "no answer from " + url + " (the read failed or took over 2 s)";
        break;
      default:
        why = "no answer from " + url + ": " + httplib::to_string(result.error());
    }
    return false;
  }
  why = url + " answered " + std::to_string(result->status);
  return result->status == 200;
}

int run_healthcheck(const std::vector<std::string>& args) {
  std::string pid = "1";
  std::optional<std::string> flag_host, flag_port;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string name = args[i], value;
    if (name == "--help" || name == "-h") {
      std::cout
          << "rasterd healthcheck [--pid N] [--host H] [--port N]\n\n"
             "GET /healthz of the server PID N (default 1, a container's server) on the host and port it\n"
             "was given: its --host and --port flags, else RASTERD_HOST, RASTERD_PORT or PORT in its\n"
             "environment, else 127.0.0.1:8080. --host and --port here win. Exit code 0: answered 200.\n";
      return 0;
    }
    if (const std::size_t eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    } else if (i + 1 < args.size()) {
      value = args[++i];
    } else {
      std::cerr << "rasterd healthcheck: " << name << " needs a value\n";
      return 1;
    }
    if (name == "--pid") {
      if (value.empty() ||
          !std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        std::cerr << "rasterd healthcheck: --pid takes a process id, got '" << value << "'\n";
        return 1;
      }
      pid = value;
    } else if (name == "--host")
      flag_host = value;
    else if (name == "--port")
      flag_port = value;
    else {
      std::cerr << "rasterd healthcheck: unexpected argument '" << args[i]
                << "' (--pid N, --host H, --port N)\n";
      return 1;
    }
  }

  std::vector<std::string> cmdline, environment;
  if (!flag_host || !flag_port) {  // else nothing of the server's is needed
    std::string text, error;
    for (auto [file, out] : {std::pair{"cmdline", &cmdline}, std::pair{"environ", &environment}}) {
      if (!read_file("/proc/" + pid + "/" + file, text, error)) {
        std::cerr << "rasterd healthcheck: " << error
                  << " (name the server with --pid, or give --host and --port)\n";
        return 1;
      }
      *out = split_nul(text);
    }
  }
  const HealthTarget target = health_target(cmdline, environment, flag_host, flag_port);
  if (!target.error.empty()) {
    std::cerr << "rasterd healthcheck: " << target.error << " (from " << target.port_source << " of PID "
              << pid << ")\n";
    return 1;
  }
  std::string why;
  const bool healthy = probe_health(target.host, target.port, why);
  (healthy ? std::cout : std::cerr) << "rasterd healthcheck: " << (healthy ? "healthy: " : "unhealthy: ")
                                    << why << " (port: " << target.port_source
                                    << ", host: " << target.host_source << "; PID " << pid << ")\n";
  return healthy ? 0 : 1;
}

}  // namespace rasterd
