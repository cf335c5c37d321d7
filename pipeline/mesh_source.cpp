#include "pipeline/mesh_source.h"

#include "pipeline/mesh_loader.h"
#include "pipeline/procedural.h"

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
  }
  validate_mesh(mesh, "procedural mesh");  // generators are exact: this only normalizes
  return mesh;
}

}  // namespace tessref
