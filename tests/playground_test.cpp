// The playground's routes (server/playground.cpp): the page and the example scenes, embedded at build
// time. The page itself is checked in a real browser by scripts/test-browser (make test-browser).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "test_server.h"

namespace {

using test::TestServer;

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Playground, PageIsServedAtTheRoot) {
  TestServer server;
  auto r = server.client().Get("/");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "text/html; charset=utf-8");
  EXPECT_NE(r->get_header_value("Content-Security-Policy").find("connect-src 'self'"), std::string::npos);
  EXPECT_EQ(r->body, read_file(RASTERD_PLAYGROUND_PAGE)) << "the embedded page is the file in the tree";
}

TEST(Playground, ListsAndServesEveryExampleScene) {
  TestServer server;
  auto r = server.client().Get("/examples");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
  std::set<std::string> listed, in_tree;
  for (const auto& name : nlohmann::json::parse(r->body)) listed.insert(name.get<std::string>());
  for (const auto& entry : std::filesystem::directory_iterator(RASTERD_EXAMPLES_DIR))
    if (entry.path().extension() == ".json") in_tree.insert(entry.path().filename().string());
  EXPECT_EQ(listed, in_tree);
  for (const std::string& name : listed) {
    auto scene = server.client().Get(("/examples/" + name).c_str());
    ASSERT_TRUE(scene);
    EXPECT_EQ(scene->status, 200) << name;
    EXPECT_EQ(scene->body, read_file(std::filesystem::path(RASTERD_EXAMPLES_DIR) / name)) << name;
  }
}

TEST(Playground, UnknownExampleIsAProblem404) {
  TestServer server;
  for (const char* path : {"/examples/nope.json", "/examples/nginx.conf", "/examples/..%2FREADME.md"}) {
    auto r = server.client().Get(path);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 404) << path;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json") << path;
  }
}

}  // namespace
