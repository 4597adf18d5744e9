// Google Benchmark micro-benchmarks, one stage at a time: parse (per scene, plus the flat-array mesh),
// the JSON tokenizer against RapidJSON's (issue 31's choice), the model readers per format (and tinygltf's
// own load beside ours), plan, raster (per scene and thread count),
// encode; and the growth series — raster cost against image
// side (256..4096) and against primitive count (10^3..10^6). `make bench` runs them after the end-to-end
// table and keeps their output in docs/performance.md.
#include <benchmark/benchmark.h>

#include <charconv>
#include <map>
#include <string>

#include <rapidjson/error/en.h>
#include <rapidjson/reader.h>

#include "base/json_cursor.h"
#include "model_files.h"  // tests/: the generated torus in every model format
#include "raster/raster.h"
#include "scenes.h"

// tinygltf's declarations, configured as the library compiles it (renderer/src/model/gltf_document.h),
// whose copy of the implementation the model/tinygltf rows call: its own load, without our reading of the
// result.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

namespace {

const char* const kScenes[] = {"small", "large", "grid"};

// Scenes and their JSON are built once per process, not inside the timed loops.
const raster::Scene& scene(const std::string& kind) {
  static std::map<std::string, raster::Scene> cache;
  auto it = cache.find(kind);
  if (it == cache.end()) it = cache.emplace(kind, bench::make_scene(kind, 1)).first;
  return it->second;
}

const std::string& json(const std::string& kind) {
  static std::map<std::string, std::string> cache;
  auto it = cache.find(kind);
  if (it == cache.end())
    it = cache.emplace(kind, kind == "mesh" ? bench::flat_mesh_json(400) : bench::scene_json(scene(kind)))
             .first;
  return it->second;
}

raster::RenderPlan plan_for(const raster::Scene& s, int threads) {
  raster::PlanOptions options;
  options.max_threads = threads;
  return raster::plan(s, {}, options);
}

void parse(benchmark::State& state, const std::string& kind) {
  const std::string& text = json(kind);
  for (auto _ : state) benchmark::DoNotOptimize(raster::parse_scene(text));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

// The two tokenizers issue 31 chose between, each doing the least a scene reader needs: check the whole
// text and turn every number into a double. RapidJSON's SAX Reader with the flags the issue names (numbers
// as strings, converted with std::from_chars, which is correctly rounded); our pull cursor (json_cursor.h)
// passing over the document. The library is taken unless it is more than 15% slower.
struct NumberSum : rapidjson::BaseReaderHandler<rapidjson::UTF8<>, NumberSum> {
  double sum = 0;
  bool RawNumber(const char* text, rapidjson::SizeType length, bool) {
    double v = 0;
    std::from_chars(text, text + length, v);
    sum += v;
    return true;
  }
};

void tokenize_rapidjson(benchmark::State& state, const std::string& kind) {
  const std::string& text = json(kind);
  constexpr unsigned kFlags = rapidjson::kParseValidateEncodingFlag | rapidjson::kParseIterativeFlag |
                              rapidjson::kParseNumbersAsStringsFlag;
  for (auto _ : state) {
    NumberSum handler;
    rapidjson::StringStream in(text.c_str());
    rapidjson::Reader reader;
    if (reader.Parse<kFlags>(in, handler).IsError()) state.SkipWithError("RapidJSON rejected the scene");
    benchmark::DoNotOptimize(handler.sum);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

void tokenize_cursor(benchmark::State& state, const std::string& kind) {
  const std::string& text = json(kind);
  for (auto _ : state) {
    raster::JsonCursor in(text, 64);
    benchmark::DoNotOptimize(in.skip());
    in.finish();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

// The model readers on one torus of 80,000 corners and 160,000 triangles (quads in OBJ and PLY), written in
// each format: bytes per second, so that formats of different sizes compare per byte (issue 32's targets:
// binary STL >= 1 GB/s; PLY and ASCII STL at least the OBJ path's rate; glTF within 1.2x of tinygltf's own
// load of the same bytes).
const std::string& model_bytes(const std::string& kind) {
  static const test::TestMesh mesh = test::make_mesh(11, 400, 200);
  static std::map<std::string, std::string> cache;
  auto it = cache.find(kind);
  if (it != cache.end()) return it->second;
  std::string bytes;
  if (kind == "obj") bytes = test::write_obj(mesh);
  if (kind == "stl_ascii") bytes = test::write_stl_ascii(mesh);
  if (kind == "stl_binary") bytes = test::write_stl_binary(mesh);
  if (kind == "ply_ascii") bytes = test::write_ply_ascii(mesh);
  if (kind == "ply_binary") bytes = test::write_ply_binary(mesh, false);
  if (kind == "gltf") {
    const test::Gltf g = test::make_gltf(mesh, "", true);
    bytes =
        test::make_gltf(mesh, "data:application/octet-stream;base64," + test::base64(g.buffer), true).json;
  }
  if (kind == "glb") bytes = test::write_glb(test::make_gltf(mesh, "", true));
  return cache.emplace(kind, std::move(bytes)).first->second;
}

void read_model(benchmark::State& state, const std::string& kind) {
  const std::string& bytes = model_bytes(kind);
  const auto format = raster::sniff_model(bytes);
  for (auto _ : state) benchmark::DoNotOptimize(raster::parse_model(bytes, format));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}

void tinygltf_load(benchmark::State& state, const std::string& kind) {
  const std::string& bytes = model_bytes(kind);
  for (auto _ : state) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const bool ok = kind == "glb"
                        ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                                      reinterpret_cast<const unsigned char*>(bytes.data()),
                                                      static_cast<unsigned>(bytes.size()))
                        : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                                     static_cast<unsigned>(bytes.size()), "");
    if (!ok) state.SkipWithError(err.c_str());
    benchmark::DoNotOptimize(model);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}

void plan(benchmark::State& state, const std::string& kind) {
  const raster::Scene& s = scene(kind);
  for (auto _ : state) benchmark::DoNotOptimize(plan_for(s, 1));
}

void render(benchmark::State& state, const raster::Scene& s, int threads) {
  const raster::RenderPlan p = plan_for(s, threads);
  for (auto _ : state) benchmark::DoNotOptimize(raster::render(s, p));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * s.primitives.size()));
}

void encode(benchmark::State& state, const std::string& kind) {
  const raster::Scene& s = scene(kind);
  const raster::RenderPlan p = plan_for(s, 1);
  const raster::Image image = raster::render(s, p);
  std::size_t size = 0;
  for (auto _ : state) size = raster::encode_png(image, p.png).size();
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * image.pixels.size()));
  state.counters["png_KB"] = static_cast<double>(size) / 1024;
}

// Raster cost against image side: 1,000 triangles about 1/8 of the image across, so covered pixels grow
// with the square of the side.
void by_side(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const raster::Scene s = bench::random_scene(side, 1000, side / 16.0);
  render(state, s, 1);
  state.counters["Mpx/s"] = benchmark::Counter(static_cast<double>(side) * side / 1e6,
                                               benchmark::Counter::kIsIterationInvariantRate);
}

// Raster cost against primitive count on 1024x1024: triangles of about +-6 px.
void by_count(benchmark::State& state) {
  const raster::Scene s = bench::random_scene(1024, static_cast<int>(state.range(0)), 6);
  render(state, s, 1);
}

void register_all() {
  for (const char* kind : kScenes)
    benchmark::RegisterBenchmark((std::string("parse/") + kind).c_str(), parse, kind);
  benchmark::RegisterBenchmark("parse/mesh_flat_320k_triangles", parse, std::string("mesh"));
  for (const char* kind : {"small", "grid", "mesh"}) {
    benchmark::RegisterBenchmark((std::string("tokenize/rapidjson_sax/") + kind).c_str(), tokenize_rapidjson,
                                 kind);
    benchmark::RegisterBenchmark((std::string("tokenize/json_cursor/") + kind).c_str(), tokenize_cursor,
                                 kind);
  }
  for (const char* kind : {"obj", "stl_ascii", "stl_binary", "ply_ascii", "ply_binary", "gltf", "glb"})
    benchmark::RegisterBenchmark((std::string("model/") + kind).c_str(), read_model, kind)
        ->Unit(benchmark::kMillisecond);
  for (const char* kind : {"gltf", "glb"})
    benchmark::RegisterBenchmark((std::string("model/tinygltf_load/") + kind).c_str(), tinygltf_load, kind)
        ->Unit(benchmark::kMillisecond);
  for (const char* kind : kScenes)
    benchmark::RegisterBenchmark((std::string("plan/") + kind).c_str(), plan, kind);
  for (const char* kind : kScenes)
    for (int threads : {1, 2})
      benchmark::RegisterBenchmark(
          (std::string("raster/") + kind + "/threads:" + std::to_string(threads)).c_str(),
          [kind, threads](benchmark::State& state) { render(state, scene(kind), threads); })
          ->UseRealTime();
  for (const char* kind : kScenes)
    benchmark::RegisterBenchmark((std::string("encode/") + kind).c_str(), encode, kind);
  benchmark::RegisterBenchmark("series/side", by_side)
      ->RangeMultiplier(2)
      ->Range(256, 4096)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("series/triangles", by_count)
      ->RangeMultiplier(10)
      ->Range(1000, 1'000'000)
      ->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
