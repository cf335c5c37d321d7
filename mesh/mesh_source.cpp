#include "mesh/mesh_source.h"

#include "mesh/mesh_loader.h"
#include "mesh/procedural.h"
#include "mesh/reference_meshes.h"

namespace tessref {

Mesh build_mesh(const MeshSettings& s, std::vector<std::string>& warnings) {
  Mesh mesh;
  switch (s.type) {
    case MeshType::Icosphere: mesh = make_icosphere(s.icosphere_refinements, s.icosphere_radius); break;
    case MeshType::Torus:
      mesh = make_torus(s.torus_major_radius, s.torus_minor_radius, s.torus_major_segments,
                        s.torus_minor_segments);
      break;
    case MeshType::Cube: mesh = make_cube(s.cube_size); break;
    case MeshType::File: return load_mesh_file(s.path, warnings, s.split_normals);
    case MeshType::Seed004Torus:
      mesh = make_seed004_torus(s.seed004_torus_grid, s.seed004_torus_analytic_normals
                                                          ? ReferenceNormals::Analytic
                                                          : ReferenceNormals::FaceAverage);
      break;
    case MeshType::RoundedCube: mesh = make_rounded_cube(s.rounded_cube_cut, s.rounded_cube_half_size); break;
    case MeshType::Vase: mesh = make_seed004_vase(); break;
  }
  validate_mesh(mesh, "procedural mesh");  // generators are exact: this only normalizes
  return mesh;
}

}  // namespace tessref
