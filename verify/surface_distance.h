#pragma once
// Two-sided distance between the driver's tessellated surface and tessref's: from every vertex of
// one to the other's triangles (Embree closest-point queries), both ways. Hausdorff = the larger
// of the two maxima.
#include <cstdint>
#include <functional>
#include <vector>

#include "common/parallel.h"
#include "verify/surface.h"

namespace tessref {

struct SurfaceDistance {
  struct Side {
    std::uint64_t samples = 0;  // distinct vertices (patch, position) measured
    double max = 0.0, rms = 0.0;
    std::int64_t worst_patch = -1;
  };
  Side reference_to_tessref, tessref_to_reference;
  double hausdorff = 0.0;
  // The patches with the largest distance either way, largest first (at most 10; ties by id).
  std::vector<std::pair<std::uint32_t, double>> worst_patches;
};

// tessref_patches: which of tessref's patches to measure from (a capture that stores a sample of
// patches has no surface for the others to be measured against); null: all.
SurfaceDistance surface_distance(const TessSurface& reference, const SurfaceOracle& reference_oracle,
                                 const TessSurface& tessref, const SurfaceOracle& tessref_oracle,
                                 const Parallel& parallel,
                                 const std::function<bool(std::uint32_t)>& tessref_patches = nullptr);

}  // namespace tessref
