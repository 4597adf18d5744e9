// Helpers of the service tests: a gate that holds renders, bounded polling, a raw TCP client, and
// reading a status line or a Prometheus sample.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

namespace {

// A latch the test opens: renders admitted while it is closed wait in ServiceConfig::after_admission.
class Gate {
 public:
  void wait() {
    std::unique_lock lock(mutex_);
    opened_.wait(lock, [&] { return open_; });
  }
  void open() {
    {
      std::lock_guard lock(mutex_);
      open_ = true;
    }
    opened_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable opened_;
  bool open_ = false;
};

// Polls `done` until it holds; the limit only keeps a broken build from hanging (ctest would time out).
template <typename Done>
bool eventually(Done&& done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!done()) {
    if (std::chrono::steady_clock::now() > give_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
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
  /// Everything until the server closes the connection (or 20 s of silence; then closed_by_peer() is false).
  std::string receive_all() {
    std::string out;
    char buf[4096];
    ssize_t n;
    while ((n = ::recv(fd_, buf, sizeof buf, 0)) > 0) out.append(buf, static_cast<std::size_t>(n));
    closed_by_peer_ = n == 0;
    return out;
  }
  bool closed_by_peer() const { return closed_by_peer_; }
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
  bool closed_by_peer_ = false;
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

}  // namespace
