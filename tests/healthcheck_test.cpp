// `rasterd healthcheck` (issue 39): the server's address read from NUL-separated /proc buffers as the server
// itself decides it, and the check against real servers: rasterd's, one that answers 503, and ports that
// refuse or never answer.
#include <netinet/in.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <httplib.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "healthcheck.h"
#include "test_server.h"

namespace {

using rasterd::health_target;
using rasterd::split_nul;
using Strings = std::vector<std::string>;
using namespace std::string_literals;

TEST(Healthcheck, SplitsNulSeparatedBuffers) {
  EXPECT_EQ(split_nul("rasterd\0serve\0--port\0009000\0"s), (Strings{"rasterd", "serve", "--port", "9000"}));
  EXPECT_EQ(split_nul("a\0\0b\0"s), (Strings{"a", "", "b"})) << "an empty argument is kept";
  EXPECT_EQ(split_nul("PORT=1\0HOME=/"s), (Strings{"PORT=1", "HOME=/"}))
      << "a buffer cut before its last NUL";
  EXPECT_EQ(split_nul(""), Strings{});
}

TEST(Healthcheck, PortAndHostFromTheServersFlags) {
  const Strings env = {"PORT=8080", "RASTERD_HOST=127.0.0.9"};
  auto t = health_target({"/usr/local/bin/rasterd", "serve", "--port", "9000"}, env);
  EXPECT_EQ(t.error, "");
  EXPECT_EQ(t.port, 9000) << "the flag wins over the image's ENV PORT, as in the server";
  EXPECT_EQ(t.port_source, "--port in its command line");
  EXPECT_EQ(t.host, "127.0.0.9");
  EXPECT_EQ(t.host_source, "RASTERD_HOST in its environment");

  t = health_target({"rasterd", "serve", "--host=127.0.0.2", "--port=9001"}, {});
  EXPECT_EQ(t.port, 9001);
  EXPECT_EQ(t.host, "127.0.0.2");
  EXPECT_EQ(t.host_source, "--host in its command line");

  t = health_target({"rasterd", "serve", "--port", "1", "--workers", "2", "--port=9002"}, {});
  EXPECT_EQ(t.port, 9002) << "the last --port wins, as in the server";
}

TEST(Healthcheck, AFlagsValueIsNotAFlag) {
  // --cors-origins takes "--port" as its value (the server reads it so); the real --port follows.
  auto t = health_target({"rasterd", "serve", "--cors-origins", "--port", "--port", "9003"}, {});
  EXPECT_EQ(t.error, "");
  EXPECT_EQ(t.port, 9003);
  // Flags before `serve` are a wrapper's (here a made-up one), not the server's.
  t = health_target({"wrapper", "--port", "1", "rasterd", "serve", "--host", "127.0.0.3"},
                    {"RASTERD_PORT=9004"});
  EXPECT_EQ(t.port, 9004);
  EXPECT_EQ(t.port_source, "RASTERD_PORT in its environment");
  EXPECT_EQ(t.host, "127.0.0.3");
}

TEST(Healthcheck, PortFromTheServersEnvironment) {
  auto t = health_target({"rasterd", "serve"}, {"PORT=9005", "HOME=/", "RASTERD_PORT=9006"});
  EXPECT_EQ(t.port, 9006) << "RASTERD_PORT wins over PORT wherever it stands";
  t = health_target({"rasterd", "serve"}, {"XPORT=1", "PORT_OLD=2", "PORTS=3", "PORT=9007"});
  EXPECT_EQ(t.port, 9007) << "only the exact name";
  EXPECT_EQ(t.port_source, "PORT in its environment");
  t = health_target({"rasterd", "serve"}, {"PORT=9008", "PORT=1"});
  EXPECT_EQ(t.port, 9008) << "the first of a name, as getenv finds it";
}

TEST(Healthcheck, DefaultsAndEveryInterface) {
  auto t = health_target({}, {});
  EXPECT_EQ(t.error, "");
  EXPECT_EQ(t.host, "127.0.0.1");
  EXPECT_EQ(t.port, 8080);
  EXPECT_EQ(t.port_source, "the default");
  for (const char* any : {"0.0.0.0", "::", ""})
    EXPECT_EQ(health_target({"rasterd", "serve", "--host", any}, {}).host, "127.0.0.1") << "'" << any << "'";
  EXPECT_EQ(health_target({}, {"RASTERD_HOST="}).host, "127.0.0.1");
  EXPECT_EQ(health_target({"rasterd", "serve", "--host", "::1"}, {}).host, "::1");
}

TEST(Healthcheck, ItsOwnFlagsWin) {
  auto t = health_target({"rasterd", "serve", "--port", "9000", "--host", "127.0.0.2"}, {"RASTERD_PORT=1"},
                         "127.0.0.4", "9009");
  EXPECT_EQ(t.port, 9009);
  EXPECT_EQ(t.host, "127.0.0.4");
  EXPECT_EQ(t.port_source, "--port of healthcheck");
  EXPECT_EQ(t.host_source, "--host of healthcheck");
}

TEST(Healthcheck, APortThatCannotBeAskedIsAnError) {
  for (const char* bad : {"abc", "", "70000", "123456", "-1", "80x", " 80"})
    EXPECT_NE(health_target({"rasterd", "serve", "--port", bad}, {}).error, "") << "'" << bad << "'";
  EXPECT_NE(health_target({}, {"PORT=http"}).error, "");
  const auto zero = health_target({"rasterd", "serve", "--port", "0"}, {});
  EXPECT_NE(zero.error.find("port 0"), std::string::npos) << zero.error;
  EXPECT_EQ(health_target({"rasterd", "serve", "--port", "65535"}, {}).error, "");
}

// --- Against real servers -----------------------------------------------------------------------------

// A loopback TCP socket on a free port; listening (connections complete in the kernel, nobody answers)
// or only bound (connections are refused). Closed on destruction.
struct Socket {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  int port = 0;
  explicit Socket(bool listening) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof a;
    if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&a), len) != 0 ||
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0 || (listening && ::listen(fd, 8) != 0))
      throw std::runtime_error("cannot make a loopback socket");
    port = ntohs(a.sin_port);
  }
  ~Socket() { ::close(fd); }
};

TEST(Healthcheck, ProbeOfARealServer) {
  test::TestServer server;
  std::string why;
  EXPECT_TRUE(rasterd::probe_health("127.0.0.1", server.port(), why)) << why;
  EXPECT_EQ(why, "http://127.0.0.1:" + std::to_string(server.port()) + "/healthz answered 200");
}

TEST(Healthcheck, ProbeOfA503IsUnhealthy) {
  httplib::Server server;
  server.Get("/healthz", [](const httplib::Request&, httplib::Response& res) { res.status = 503; });
  const int port = server.bind_to_any_port("127.0.0.1");
  ASSERT_GT(port, 0);
  std::thread thread([&] { server.listen_after_bind(); });
  while (!server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  std::string why;
  EXPECT_FALSE(rasterd::probe_health("127.0.0.1", port, why));
  EXPECT_NE(why.find("answered 503"), std::string::npos) << why;
  server.stop();
  thread.join();
}

TEST(Healthcheck, ProbeOfARefusedOrSilentPortIsUnhealthy) {
  const Socket refused(false), silent(true);
  std::string why;
  EXPECT_FALSE(rasterd::probe_health("127.0.0.1", refused.port, why));
  EXPECT_NE(why.find("cannot connect to"), std::string::npos) << why;
  EXPECT_FALSE(rasterd::probe_health("127.0.0.1", silent.port, why)) << "a server that never answers";
  EXPECT_NE(why.find("no answer from"), std::string::npos) << why;
}

// A process whose /proc/PID/cmdline and environ are a server's, without being one: `sh -c 'read line'
// rasterd serve ARGS...` (sh's $0 and arguments), which waits on a pipe until the test closes it.
class FakeServerProcess {
 public:
  FakeServerProcess(const Strings& serve_args, const Strings& env) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("pipe");
    Strings args = {"sh", "-c", "read line", "rasterd", "serve"};
    args.insert(args.end(), serve_args.begin(), serve_args.end());
    std::vector<char*> argv, envp;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    Strings env_copy = env;
    for (std::string& e : env_copy) envp.push_back(e.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    const int error = ::posix_spawn(&pid_, "/bin/sh", &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    write_end_ = fds[1];
    if (error != 0) throw std::runtime_error("posix_spawn /bin/sh failed");
  }
  ~FakeServerProcess() {
    ::close(write_end_);  // `read` meets the end of its input: sh exits
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = 0;
  int write_end_ = -1;
};

// The binary's `healthcheck` with these arguments: its exit code and what it printed (stdout and stderr).
std::pair<int, std::string> run_healthcheck_binary(const std::string& args) {
  FILE* out = ::popen((RASTERD_BINARY " healthcheck " + args + " 2>&1").c_str(), "r");
  if (!out) return {-1, "popen failed"};
  std::string text;
  char buffer[512];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, out)) text.append(buffer, n);
  const int status = ::pclose(out);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

TEST(Healthcheck, TheSubcommandAsksThePortTheServerWasGiven) {
  test::TestServer server;
  const std::string port = std::to_string(server.port());
  // `IMAGE serve --port P` in an image with ENV PORT=8080 (nothing listens on 8080 in a test, or something
  // else does): the flag is the port.
  const FakeServerProcess by_flag({"--host", "0.0.0.0", "--port", port}, {"PORT=8080"});
  auto [code, text] = run_healthcheck_binary("--pid " + std::to_string(by_flag.pid()));
  EXPECT_EQ(code, 0) << text;
  EXPECT_NE(text.find("http://127.0.0.1:" + port + "/healthz answered 200"), std::string::npos) << text;
  EXPECT_NE(text.find("port: --port in its command line"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << "one line: " << text;

  const FakeServerProcess by_env({}, {"PORT=1", "RASTERD_PORT=" + port, "RASTERD_HOST=127.0.0.1"});
  std::tie(code, text) = run_healthcheck_binary("--pid=" + std::to_string(by_env.pid()));
  EXPECT_EQ(code, 0) << text;
  EXPECT_NE(text.find("port: RASTERD_PORT in its environment"), std::string::npos) << text;
}

TEST(Healthcheck, TheSubcommandFailsWhenTheServerDoesNotAnswer) {
  const Socket refused(false);
  const FakeServerProcess server({"--port", std::to_string(refused.port)}, {});
  auto [code, text] = run_healthcheck_binary("--pid " + std::to_string(server.pid()));
  EXPECT_EQ(code, 1) << text;
  EXPECT_NE(text.find("unhealthy: cannot connect to http://127.0.0.1:" + std::to_string(refused.port)),
            std::string::npos)
      << text;

  const FakeServerProcess any_port({"--port", "0"}, {});
  std::tie(code, text) = run_healthcheck_binary("--pid " + std::to_string(any_port.pid()));
  EXPECT_EQ(code, 1) << text;
  EXPECT_NE(text.find("port 0"), std::string::npos) << text;

  std::tie(code, text) = run_healthcheck_binary("--pid 999999999");  // above Linux's pid_max
  EXPECT_EQ(code, 1) << text;
  EXPECT_NE(text.find("cannot read /proc/999999999/cmdline"), std::string::npos) << text;
  std::tie(code, text) = run_healthcheck_binary("--bogus 1");
  EXPECT_EQ(code, 1) << "a usage error is unhealthy, never Docker's reserved 2: " << text;
}

TEST(Healthcheck, TheSubcommandsOwnFlagsNeedNoProc) {
  test::TestServer server;
  auto [code, text] =
      run_healthcheck_binary("--pid 999999999 --host 127.0.0.1 --port " + std::to_string(server.port()));
  EXPECT_EQ(code, 0) << text;
}

}  // namespace
