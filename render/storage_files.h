#pragma once
// `render --storage-buffers PREFIX` and `--images PREFIX`: the files that receive the buffers a
// scene's draws bind as shader storage and the images they bind, after the frame (what the
// shaders wrote into them included).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace tessref {

// "PREFIX.NAME.bin", where characters of NAME other than letters, digits, '-', '_' and '.'
// become '_'.
std::string memory_file_name(const std::string& prefix, std::string name);

// (index into Scene::buffers, memory_file_name(prefix, buffer name)) for every buffer some draw
// binds to a shader storage block, in the scene's buffer order.
std::vector<std::pair<std::size_t, std::string>> storage_buffer_files(const Scene& scene, const std::string& prefix);

}  // namespace tessref
