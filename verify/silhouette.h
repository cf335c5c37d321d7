#pragma once
// Coverage by ray casting: tessref's tessellated surface hit by Embree through every pixel centre
// of the scene camera, against the reference's coverage (its depth below the clear value, 1).
// Each mismatched pixel is measured against the silhouette of tessref's surface in screen space:
// the projected edges that bound it (one adjacent triangle) or separate a front-facing triangle
// from a back-facing one.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "io/image_output.h"
#include "verify/surface.h"

namespace tessref {

struct SilhouetteComparison {
  std::uint64_t pixels = 0, covered_reference = 0, covered_rays = 0;
  std::uint64_t mismatched = 0;
  std::uint64_t beyond_half_pixel = 0;  // mismatches whose centre is over 0.5 px from the silhouette
  double max_distance = 0.0;            // pixels, over the mismatches
  std::uint64_t silhouette_edges = 0;
  // Mismatches by distance: [0, 0.5], (0.5, 1], (1, 2], (2, 4], (4, 8], > 8 pixels.
  std::array<std::uint64_t, 6> by_distance{};
  std::vector<float> distance;  // per pixel, top row first: -1 where both agree, else pixels
  std::vector<std::array<int, 2>> worst_pixels;  // (x, y) of the farthest mismatches, at most 10
};
inline constexpr const char* kSilhouetteBuckets[6] = {"0-0.5", "0.5-1", "1-2", "2-4", "4-8", ">8"};

SilhouetteComparison compare_silhouette(const FloatImage& reference_depth, const TessSurface& surface,
                                        const SurfaceOracle& oracle, const glm::mat4& view_projection,
                                        bool cull_back, const Parallel& parallel);

}  // namespace tessref
