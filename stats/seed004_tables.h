#pragma once
// Seed 004's Tables 3-6 as tessref measures them: which meshes, schemes and settings each row
// uses, and the tables printed in the paper's layout or as JSON. docs/stats.md has the results
// side by side with the paper's and the conventions recovered from its numbers.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/parallel.h"
#include "mesh/mesh.h"
#include "stats/mesh_stats.h"
#include "stats/summary.h"
#include "stats/surface_stats.h"

namespace tessref::stats {

// The four schemes in the paper's row order, with its settings: Phong alpha = 3/4; Nagata's eps
// is per mesh (0 on the sphere, torus and RoundedCube, 0.06 on the Vase).
inline constexpr Interpolant kSeed004Schemes[4] = {Interpolant::Phong, Interpolant::Nagata,
                                                   Interpolant::NLSA, Interpolant::PN};
const char* seed004_scheme_name(Interpolant s);  // "Phong", "Nagata", "NLSA", "PN"

struct NamedMesh {
  std::string name;   // as the paper names it: "Sphere", "Torus", "RoundedCube", "Vase"
  Mesh mesh;
  double nagata_eps;  // the threshold the paper used on this mesh
};
// Tables 4-6's meshes: Vase, RoundedCube, Sphere (i = 2, 320 triangles), Torus (j = 10, 200).
// Bunny and Monsterfrog are not distributed with the paper and are left out.
std::vector<NamedMesh> seed004_meshes();

struct DistanceRow {
  std::string surface;  // "Sphere" | "Torus"
  int step;             // i (sphere) or j (torus)
  Interpolant scheme;
  Summary distance;
};
// Table 3: the sphere at i = 0..3, the torus at j = 5, 10, 15, 17, 19; 231 points a patch.
std::vector<DistanceRow> seed004_table3(const Parallel& parallel);

struct MeshRow {
  std::string name;
  MeshStats stats;
};
std::vector<MeshRow> seed004_table4();

struct SchemeRow {
  std::string mesh;
  Interpolant scheme;
  double nagata_eps;
  Summary value;
};
// Table 5: Gaussian curvature at the 171 interior points of the 21-a-side grid of every patch.
std::vector<SchemeRow> seed004_table5(const Parallel& parallel);
// Table 6: cosines between adjacent patches' normals at 21 points along every shared edge.
std::vector<SchemeRow> seed004_table6(const Parallel& parallel);

// The same measurements for any mesh (tessref stats SCENE): Table 4's row, then Tables 5 and 6
// for each scheme with Nagata's eps as given.
struct MeshReport {
  MeshRow mesh;
  std::vector<SchemeRow> curvature, edge_normals;
};
MeshReport measure_mesh(const std::string& name, const Mesh& mesh, double nagata_eps,
                        const Parallel& parallel);

// The paper's layout, one line a row, numbers in %g with 6 significant digits.
std::string format_table3(const std::vector<DistanceRow>& rows);
std::string format_table4(const std::vector<MeshRow>& rows);
std::string format_table5(const std::vector<SchemeRow>& rows);
std::string format_table6(const std::vector<SchemeRow>& rows);

nlohmann::json to_json(const Summary& s);
nlohmann::json to_json(const std::vector<DistanceRow>& rows);
nlohmann::json to_json(const std::vector<MeshRow>& rows);
nlohmann::json to_json(const std::vector<SchemeRow>& rows);

}  // namespace tessref::stats
