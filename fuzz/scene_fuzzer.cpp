// libFuzzer target: scene text -> parse -> plan -> render -> PNG, with small caps so each input is fast.
// Any crash, sanitizer report, or exception other than SceneError is a finding; so is the scene reader
// disagreeing with the oracle (tests/oracle, the DOM reader): accepting what it rejects or the reverse,
// reading a document into a different scene, or not calling a document malformed that the oracle does.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "oracle/scene_dom.h"
#include "raster/raster.h"

namespace {

void check_readers_agree(std::string_view text, const raster::Limits& limits) {
  std::optional<raster::Scene> ours, theirs;
  if (text.find('\0') != std::string_view::npos) {
    // JSON has no raw NUL byte anywhere, and nlohmann takes one for the end of its input: no oracle here.
    try {
      raster::parse_scene(text, limits);
    } catch (const raster::SceneError& e) {
      if (e.kind() == raster::ErrorKind::syntax || e.kind() == raster::ErrorKind::encoding) return;
    }
    std::abort();  // accepted, or called valid JSON
  }
  raster::ErrorKind our_kind{}, their_kind{};
  try {
    ours = raster::parse_scene(text, limits);
  } catch (const raster::SceneError& e) {
    our_kind = e.kind();
  }
  try {
    theirs = raster::scene_json::parse_scene_oracle(text, limits);
  } catch (const raster::SceneError& e) {
    their_kind = e.kind();
  }
  if (ours.has_value() != theirs.has_value()) std::abort();  // one accepts what the other rejects
  if (ours && !(*ours == *theirs)) std::abort();             // read differently
  const bool our_syntax = our_kind == raster::ErrorKind::syntax,
             their_syntax = their_kind == raster::ErrorKind::syntax;
  // Malformed to one of them only. The oracle reports a key given twice as it parses, before a syntax error
  // further on; the reader reports the syntax error first (issue 31). Whether the text is JSON decides.
  const bool json = nlohmann::json::accept(text);
  if (!ours && our_syntax != their_syntax && our_kind != raster::ErrorKind::encoding && our_syntax == json)
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  raster::Limits limits;
  limits.max_width = 256;
  limits.max_height = 256;
  limits.max_pixels = 256 * 256;
  limits.max_primitives = 2000;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check_readers_agree(text, limits);
  try {
    const raster::Scene scene = raster::parse_scene(text, limits);
    raster::PlanOptions options;
    options.max_threads = 1;
    const raster::RenderPlan plan = raster::plan(scene, limits, options);
    const raster::Image image = raster::render(scene, plan);
    raster::encode_png(image, plan.png);
  } catch (const raster::SceneError& e) {
    // rejected input: the expected outcome for most of the corpus. Its message is echoed to clients, so
    // it must be UTF-8 whatever bytes the input held.
    if (raster::first_invalid_utf8(e.what()) != std::string_view::npos) std::abort();
  }
  return 0;
}
