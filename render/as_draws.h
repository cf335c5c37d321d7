#pragma once
// A mesh scene written as the GL draw render makes of it (`tessref scene --as-draws DIR`): the
// welded mesh's positions, normals and indices as buffer files, one glDrawElements(GL_PATCHES or
// GL_TRIANGLES) with the depth test and culling the mesh path draws with, and the program as GLSL
// files (the built-in programs as their GLSL twins). Rendering the written scene gives the mesh
// scene's image: the same bytes with the twins, within the twins' tolerance of the built-in ones.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref {

// scene_json: the merged scene (load_scene_json), scene and mesh: as loaded and built from it.
// Writes dir/scene.json, the buffers and the shader files (dir is created) and returns the scene
// written. InputError for what the draw form cannot say the same way: a scalar-tagged PN scheme
// (its per-vertex tags), a spacing or winding other than the twin evaluation shader's own layout
// line, a scene that already has draws; a file that cannot be written.
nlohmann::json write_scene_as_draws(const nlohmann::json& scene_json, const Scene& scene, const Mesh& mesh,
                                    const std::filesystem::path& dir);

}  // namespace tessref
