#pragma once
// `render --storage-buffers PREFIX`: the files that receive the buffers a scene's draws bind as
// shader storage, after the frame (what the shaders wrote into them included).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace tessref {

// (index into Scene::buffers, "PREFIX.NAME.bin") for every buffer some draw binds to a shader
// storage block, in the scene's buffer order. Characters of NAME other than letters, digits, '-',
// '_' and '.' become '_'.
std::vector<std::pair<std::size_t, std::string>> storage_buffer_files(const Scene& scene, const std::string& prefix);

}  // namespace tessref
