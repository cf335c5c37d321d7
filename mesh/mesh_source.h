#pragma once
// The scene's mesh: generated or loaded, always validated.
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref {

// Builds the mesh a scene asks for. InputError for a bad file; warnings for repairs.
Mesh build_mesh(const MeshSettings& settings, std::vector<std::string>& warnings);

}  // namespace tessref
