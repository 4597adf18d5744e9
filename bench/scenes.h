// Seeded benchmark scenes, shared by the benchmarks, the load test and the accuracy report.
#pragma once

#include <string>

#include "raster/model.h"
#include "raster/scene.h"

namespace bench {

/// Kinds: "small" (100,000 triangles of about +-12 px, 1024x1024, per-vertex colours), "large" (200
/// triangles of about +-340 px), "flat" (the same 200 large triangles, one colour each), "grid" (64x64
/// jittered grid, 8,192 triangles, flat colours), "mid" (2,000 triangles of about +-30 px on 512x512, the
/// load-test scene). Same seed, same scene.
raster::Scene make_scene(const std::string& kind, unsigned seed = 1);

/// `count` triangles with vertices within +-radius px of a uniformly random centre on a side x side image,
/// per-vertex colours: the series of how cost grows with image size and primitive count.
raster::Scene random_scene(int side, int count, double radius, unsigned seed = 1);

/// A 3D mesh in the flat-array form (positions, indices and colors as flat lists) of an n x n grid of
/// quads (2 n^2 triangles) on a wavy surface, as JSON text: the big-geometry parse case.
std::string flat_mesh_json(int n);

/// Appends a triangle with one colour (ncolors 1) or one per vertex (ncolors 3).
void add_triangle(raster::Scene& scene, const raster::Point2 (&points)[3], const raster::Rgba8* colors,
                  int ncolors);

/// Appends a line of `width` pixels with one colour.
void add_line(raster::Scene& scene, raster::Point2 a, raster::Point2 b, raster::Rgba8 color, float width = 1);

/// The same scene as JSON text (format v1), for end-to-end measurements.
std::string scene_json(const raster::Scene& scene);

}  // namespace bench

namespace bench {

/// 3D benchmark scenes: "sphere" (a UV sphere of 2 x 548 x 548 = 600,608 triangles built in code, smooth-lit
/// with computed normals, 1024x1024) and "bunny" (the Stanford bunny from $RASTERD_BUNNY, else `bunny_path`,
/// smooth-lit, 512x512); for issue 42's points, "triangles_1m" (a UV sphere of 999,698 triangles, smooth-lit)
/// and "points_1m" (1,000,000 points spread evenly over the same sphere, default size), both 1024x1024.
/// Camera and lights are the defaults (auto-framed; ambient, key and fill). Throws if the bunny file cannot
/// be read.
raster::Scene mesh_scene(const std::string& kind,
                         const std::string& bunny_path = "../shared/models/bunny.obj");

/// A model file as the CLI reads it, before its reader runs: its bytes, its format (by its bytes, else its
/// extension: raster::model_format_of) and the files it names, gathered from its folder (OBJ's libraries
/// and textures, glTF's buffers and images; as server/main.cpp gathers them). Throws std::runtime_error
/// when the file cannot be read, raster::SceneError when it is in no format rasterd reads.
struct ModelFile {
  std::string bytes;
  raster::ModelFormat format = raster::ModelFormat::obj;
  raster::Uploads files;  ///< by file name, as the readers look them up
};
ModelFile read_model_file(const std::string& path);

}  // namespace bench
