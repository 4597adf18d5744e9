#include "playground.h"

#include <string>

#include <nlohmann/json.hpp>

#include "example_scenes.h"   // generated: kExampleScenes
#include "playground_page.h"  // generated: kPlaygroundPage
#include "problem.h"

namespace rasterd {

void serve_playground(const httplib::Request&, httplib::Response& res) {
  const auto& page = embedded::kPlaygroundPage[0];
  // The page talks only to this origin: inline script and style (no build step), images from blob: URLs
  // of its own fetches (which it may read back: connect-src blob:), nothing loaded from or sent to anywhere
  // else.
  res.set_header("Content-Security-Policy",
                 "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
                 "img-src blob: data:; connect-src 'self' blob:; base-uri 'none'; form-action 'none'; "
                 "frame-ancestors 'none'");
  res.set_header("X-Content-Type-Options", "nosniff");
  res.set_header("Cache-Control", "no-cache");  // a new binary's page replaces the old one at once
  res.set_content(reinterpret_cast<const char*>(page.data), page.size, "text/html; charset=utf-8");
}

void serve_example_list(const httplib::Request&, httplib::Response& res) {
  nlohmann::json names = nlohmann::json::array();
  for (const auto& file : embedded::kExampleScenes) names.push_back(file.name);
  res.set_content(names.dump(), "application/json");
}

void serve_example(const httplib::Request& req, httplib::Response& res) {
  for (const auto& file : embedded::kExampleScenes)
    if (file.name == req.matches[1].str()) {
      res.set_content(reinterpret_cast<const char*>(file.data), file.size, "application/json");
      return;
    }
  std::string names;
  for (const auto& file : embedded::kExampleScenes)
    names += (names.empty() ? "" : ", ") + std::string(file.name);
  write_problem(res, problem(404, "not-found", "No such example",
                             "there is no example \"" + req.matches[1].str() + "\"; the examples are " +
                                 names + " (GET /examples lists them)"));
}

}  // namespace rasterd
