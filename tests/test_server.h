// A real rasterd service on 127.0.0.1:<any free port>, installed exactly as main() installs it;
// stopped and joined on destruction.
#pragma once

#include <chrono>
#include <stdexcept>
#include <thread>

#include <httplib.h>

#include "service.h"

namespace test {

class TestServer {
 public:
  explicit TestServer(rasterd::ServiceConfig config = {}) : service_(config) {
    service_.install(server_);
    port_ = server_.bind_to_any_port("127.0.0.1");
    if (port_ <= 0) throw std::runtime_error("bind_to_any_port failed");
    service_.widen_backlog();
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~TestServer() {
    server_.stop();
    thread_.join();
  }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(60);
    return c;
  }
  int port() const { return port_; }
  rasterd::Service& service() { return service_; }

 private:
  httplib::Server server_;
  rasterd::Service service_;
  int port_ = 0;
  std::thread thread_;
};

}  // namespace test
