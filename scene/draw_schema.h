#pragma once
// The scene format's GL draws (README.md, "Draws"): `buffers` and `draws`, every key checked
// against GL's own rules for the call it stands for.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene.h"

namespace tessref {

// Reads root.buffers, root.framebuffer and root.draws (all optional). Relative files resolve against base_dir. A
// draw's own `shaders` takes batch_lanes and max_instructions from the scene's.
void read_draw_keys(JsonObject& root, const JsonSource& source, const std::filesystem::path& base_dir,
                    const ShaderSettings& scene_shaders, std::vector<BufferSetting>& buffers,
                    std::vector<DrawSetting>& draws, FramebufferSetting& framebuffer);

// The draw mode a GL name ("GL_TRIANGLE_STRIP") stands for; nullopt for a name that is none.
std::optional<DrawMode> draw_mode_named(const std::string& gl_name);

// A scene with every draw key once, read only to list the keys (`tessref scene --keys`).
const char* draw_keys_example();

}  // namespace tessref
