#pragma once
// A scene's buffer objects (buffers.NAME) with their bytes: a file read now, or the inline data.
#include <vector>

#include "draw/vertex_fetch.h"
#include "scene/scene.h"

namespace tessref {

// The scene's buffer called `name`. InputError naming `key` (the key that gave the name) and the
// buffers there are when it has none.
const BufferSetting& find_buffer(const Scene& scene, const std::string& name, const std::string& key);
// One buffer's bytes. InputError naming `source`: buffers.NAME.file when it cannot be read.
draw::Buffer load_buffer(const std::string& source, const BufferSetting& b);
// Every buffer of the scene, in its order.
std::vector<draw::Buffer> load_buffers(const Scene& scene);

}  // namespace tessref
