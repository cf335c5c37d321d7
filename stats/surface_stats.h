#pragma once
// Surface interrogation of a mesh's patches under one of seed 004's four interpolants: signed
// distances to an analytic surface (Table 3), Gaussian curvature (Table 5) and the cosine between
// the normals of the two patches along each shared edge (Table 6). Samples go to preassigned
// slots (patch by patch, edge by edge), so they do not depend on the thread count.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "mesh/mesh.h"
#include "stages/schemes/bezier_nets.h"

namespace tessref::stats {

using schemes::Interpolant;
using schemes::InterpolantParams;

// Seed 004's sampling density: 20 segments a patch edge (its tessellation factor f = 20), so 21
// points an edge and 231 a patch.
inline constexpr int kSeed004Segments = 20;

// The barycentric grid with `segments` steps an edge, as (u, v) = the weights of corners 1 and 2:
// (i / n, j / n) for i + j <= n, i outer. interior_only drops the points on the patch's
// boundary ((n - 1)(n - 2) / 2 remain). Needs segments >= 1 (>= 3 for interior_only).
std::vector<glm::dvec2> triangle_grid(int segments, bool interior_only);

// Every triangle's patch, in single precision (the paper's), as cubic nets.
std::vector<schemes::CubicNet<float>> build_patches(const Mesh& mesh, Interpolant scheme,
                                                    const InterpolantParams& params);

enum class AnalyticSurface {
  UnitSphere,    // |p| - 1
  Seed004Torus,  // mesh/reference_meshes.h: R = 1, r = 0.5 around the y axis
};

// Table 3: the signed distance (positive outside) of every grid point of every patch,
// patch-major, grid order within a patch. The single-precision net is evaluated in double, the
// point rounded to float and its distance computed in float: the paper's numbers carry float
// rounding (multiples of 2^-24), and this matches them best (docs/stats.md).
std::vector<double> distance_samples(const std::vector<schemes::CubicNet<float>>& patches,
                                     AnalyticSurface surface, int segments, const Parallel& parallel);

// A float net in double, exactly (the nets are built in float, as the programs build them).
schemes::CubicNet<double> widen(const schemes::CubicNet<float>& f);

// Gaussian curvature K = (LN - M^2) / (EG - F^2) of a patch point from its exact derivatives;
// NaN where du x dv vanishes.
double gaussian_curvature(const schemes::SurfacePoint<double>& s);

// Table 5: Gaussian curvature K = (LN - M^2) / (EG - F^2) from the patch's exact first and
// second derivatives (in double, from the single-precision nets) at the interior grid points.
// Points where du x dv vanishes give no sample.
std::vector<double> gaussian_curvature_samples(const std::vector<schemes::CubicNet<float>>& patches,
                                               int segments, const Parallel& parallel);

struct EdgeNormalCosines {
  std::vector<double> cosines;       // edge-major (edges sorted by their vertex pair), then t
  std::size_t edges_sampled = 0;     // edges with exactly two triangles
  std::size_t edges_skipped = 0;     // boundary and non-manifold edges
  std::size_t degenerate_points = 0; // points where a patch had no normal (no sample)
};

// Table 6: along every edge shared by two triangles, at t = k / segments (k = 0..segments, both
// ends included), the cosine between the two patches' normals normalize(du x dv) (in double).
EdgeNormalCosines adjacent_normal_cosines(const Mesh& mesh,
                                          const std::vector<schemes::CubicNet<float>>& patches,
                                          int segments, const Parallel& parallel);

}  // namespace tessref::stats
