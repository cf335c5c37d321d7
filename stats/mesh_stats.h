#pragma once
// Seed 004's Table 4: a triangle mesh's counts, how far its vertex normals lean from its face
// normals, and its edges by shape.
#include <cstddef>

#include "mesh/mesh.h"
#include "stats/summary.h"

namespace tessref::stats {

struct EdgeShapes {
  double convex = 0, concave = 0, inflection = 0;
};

struct MeshStats {
  std::size_t vertices = 0, edges = 0, triangles = 0;
  std::size_t boundary_edges = 0;     // edges of one triangle
  std::size_t nonmanifold_edges = 0;  // edges of three or more
  // cos(vertex normal, unit face normal) at every triangle corner, in single precision.
  Summary normal_cosine;
  // Each edge once, by the two end normals against the edge vector d = pb - pa: convex when
  // na.d < 0 < nb.d (the normals part, as on a sphere), concave when na.d > 0 > nb.d, otherwise
  // inflection (an S-shaped boundary curve; also where a normal is orthogonal to the edge).
  EdgeShapes shapes;
  // The same test as seed 004's Table 4 counts reproduce (docs/stats.md): every triangle's three
  // edges (p0->p1, p1->p2, p2->p0) are tested and the counts halved, but the third edge is
  // tested with p2's normal at both ends, so it always lands in `inflection`. Each class's
  // half-edge count is halved and rounded down, which is why the paper's Vase and Monsterfrog
  // rows sum to one less than their #E (itself 3 #T / 2, not the true edge count).
  EdgeShapes seed004_shapes;
};

MeshStats mesh_stats(const Mesh& mesh);

}  // namespace tessref::stats
