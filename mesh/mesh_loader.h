#pragma once
// Meshes from files through assimp (OBJ, PLY, STL, OFF, glTF, FBX, ...).
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace tessref {

// Loads every mesh of the file (node transforms applied, in node order) as one triangle mesh:
// triangulated, positions welded so each carries one smooth normal (the file's normals averaged
// per position, or angle-weighted face normals), then validated (validate_mesh). Points and
// lines are skipped. Throws InputError naming the file for anything unreadable; appends what
// was skipped or repaired to `warnings`.
Mesh load_mesh_file(const std::filesystem::path& path, std::vector<std::string>& warnings,
                    bool split_normals = false);

}  // namespace tessref
