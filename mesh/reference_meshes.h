#pragma once
// The meshes seed 004 (Boschiroli et al., Sec. 3.2-3.3, Table 4) measures its four interpolants
// on, generated in code. The sphere is make_icosphere (procedural.h) at radius 1; the torus is
// built the way the paper's Table 3 numbers require (docs/stats.md: the recovered conventions).
#include "mesh/mesh.h"

namespace tessref {

// Which vertex normals a generated mesh carries.
enum class ReferenceNormals {
  Analytic,     // the smooth surface's exact normal at the vertex
  FaceAverage,  // the unweighted mean of the unit normals of the faces around the vertex
};

// Seed 004's torus, R = 1, r = 0.5, around the y axis: the domain [0, 2pi)^2 cut into j x j
// quads, each split along one diagonal (2 j^2 triangles, j^2 vertices). The tube angle starts at
// the inner equator (v = pi + 2 pi k / j) and the normals default to face averages: with both,
// every Table 3 and 6 number of the paper is reproduced (odd j and Nagata tell the difference).
// Each quad's first triangle lists its vertices so that its third edge runs along u and the
// second's along v (the order the paper's edge counts of Table 4 imply). Needs j >= 3.
Mesh make_seed004_torus(int j, ReferenceNormals normals = ReferenceNormals::FaceAverage);

// The signed distance (positive outside) to the torus above, in single precision as the paper
// computed it: sqrt((sqrt(x^2 + z^2) - 1)^2 + y^2) - 0.5.
float seed004_torus_distance(const glm::vec3& p);
// |p| - 1 in single precision: the distance to seed 004's unit sphere.
float seed004_sphere_distance(const glm::vec3& p);

// Seed 004's RoundedCube: the cube [-h, h]^3 (h = half_size) with its corners cut at `cut`
// (0 < cut < 1, a fraction of h) along each edge, each corner a triangle and each face an octagon
// fanned around an added centre vertex: 30 vertices, 84 edges, 56 triangles. Normals: face
// averages (as on the paper's torus; the centre vertices get their face's normal exactly). The
// paper gives no dimensions: the defaults are fitted to its Table 6 (cut; the cosines do not
// depend on the size) and Table 5 (size; curvature scales as 1/h^2) rows, docs/stats.md.
Mesh make_rounded_cube(float cut = 0.585f, float half_size = 0.68f);

// Seed 004's Vase: a cylinder (radius 1, height 3, 20 vertices a ring, 12 rings) whose cross
// section turns into a 10-pointed star towards the bottom, closed at the bottom by a fan around
// a centre vertex and open at the top; quads split along one diagonal: 241 vertices,
// 460 triangles. Normals: face averages. The paper gives no dimensions; these are tessref's.
Mesh make_seed004_vase();

// The unweighted mean of the unit face normals around each vertex (in double, then rounded),
// summed in triangle order. Zero where no non-degenerate face touches a vertex.
std::vector<glm::vec3> face_average_normals(const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices);

}  // namespace tessref
