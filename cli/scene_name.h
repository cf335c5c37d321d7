#pragma once
// How a command names the scene it ran in its header line.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tessref::cli {

// The scene as drawn: its file (or "<default scene>") and the keys --set changed
// ("<default scene> with --set mesh.type, tessellation.inner").
std::string drawn_scene_name(const Scene& scene, const std::vector<std::string>& sets);

}  // namespace tessref::cli
