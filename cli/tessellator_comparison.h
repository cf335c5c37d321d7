#pragma once
// One level of `tessref compare-tessellators`: the scene drawn with the primitive generator and
// with uniform subdivision, and how far apart the two tessellated surfaces and images are.
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/parallel.h"
#include "io/image_output.h"
#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref::cli {

struct TessellatorComparison {
  float level = 1.0f;
  int uniform_n = 1;                                   // segments per edge of the uniform grid
  std::uint64_t tpg_triangles = 0, uniform_triangles = 0;  // the whole mesh
  std::uint64_t tpg_pattern_triangles = 0, uniform_pattern_triangles = 0;  // one patch
  double diagonal = 1.0;                               // of the TPG surface's bounding box
  double hausdorff = 0.0;                              // two-sided, over both surfaces' vertices
  double tpg_to_uniform_max = 0.0, uniform_to_tpg_max = 0.0;
  double tpg_to_uniform_rms = 0.0, uniform_to_tpg_rms = 0.0;
  std::int64_t worst_patch = -1;
  // Pixels covered (depth < 1) in one rendering and not the other; those within one pixel of the
  // uniform rendering's silhouette, and the rest (holes, cracks).
  std::uint64_t covered_tpg = 0, covered_uniform = 0;
  std::uint64_t coverage_differs = 0, on_silhouette = 0, off_silhouette = 0;
  std::uint64_t colour_differs = 0;                    // 8-bit RGB differs in any channel
  int max_colour_difference = 0;  // the largest channel difference (of 255) where both cover
  Rgb8Image tpg_image, uniform_image, coverage_image;  // coverage: red TPG only, cyan uniform only

  // Seed 001's refinement pattern against the same TPG rendering (the third tessellator).
  struct Versus {
    int lod = 0, segments = 1;                           // RP_lod, 2^lod segments per edge
    std::uint64_t triangles = 0, pattern_triangles = 0;  // the whole mesh, one patch
    double hausdorff = 0.0, to_tpg_rms = 0.0, from_tpg_rms = 0.0;
    std::uint64_t covered = 0, coverage_differs = 0, off_silhouette = 0;
    std::uint64_t colour_differs = 0;
    int max_colour_difference = 0;
    Rgb8Image image, coverage_image;  // coverage: red TPG only, cyan refinement pattern only
  } refinement;

  nlohmann::json to_json() const;  // distances relative to the diagonal
};

// scene: tessellation enabled, built-in programs, fixed levels (checked by the caller); its camera
// already fitted. All three renderings use `level` for every outer and inner level.
TessellatorComparison compare_tessellators(Scene scene, const Mesh& mesh, float level,
                                           const Parallel& parallel);

}  // namespace tessref::cli
