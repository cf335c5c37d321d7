#pragma once
// Cracks between patches: rays aimed at points along every edge two patches share, from both
// sides of the surface; a ray that passes through is a crack. Seed 000 (Vlachos et al., Figure 5):
// PN triangles are watertight when the patches along an edge share its normals, and open where
// the normals are split (per-face normals).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "verify/surface.h"

namespace tessref {

struct CrackReport {
  std::uint64_t patches = 0;
  std::uint64_t shared_edges = 0;    // edges whose two corner positions two patches share
  std::uint64_t unshared_edges = 0;  // on one patch only (the mesh's border) or on more than two
  std::uint64_t rays = 0, rays_through = 0;
  // Rays that met nothing where both boundaries coincide bit for bit (no gap exists there): Embree
  // missing an edge it grazes at a sharp fold. Reported, not counted as cracks.
  std::uint64_t grazing_misses = 0;
  double max_gap = 0.0;  // world units: the largest distance between the two patches' boundaries
  struct Edge {
    std::uint32_t patch_a = 0, patch_b = 0;
    glm::vec3 from{0.0f}, to{0.0f};  // the shared corners
    double gap = 0.0;                // largest boundary distance along it, world units
    std::uint64_t rays_through = 0;
  };
  std::vector<Edge> cracked;  // edges with a ray through, largest gap first (ties: patch ids)
  bool triangles = true;      // false: a quad or isoline domain, not examined
};

// Rays start `standoff` (a share of the surface's bounding-box diagonal) before the aim point; a
// ray counts as through when it meets nothing within `tolerance` of it past the aim point.
CrackReport find_cracks(const TessSurface& surface, const SurfaceOracle& oracle, const Parallel& parallel,
                        double standoff = 1e-3, double tolerance = 1e-5);

}  // namespace tessref
