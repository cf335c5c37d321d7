#pragma once
// The scene format: JSON -> Scene, every key checked (README.md, "Scene format").
#include <filesystem>

#include <nlohmann/json.hpp>

#include "scene/json_reader.h"
#include "scene/scene.h"

namespace tessref {

// Reads a complete scene (the default scene merged with the file and the overrides). Relative
// mesh paths resolve against mesh_base_dir. InputError "<source>: <key.path>: <what>".
// The `shaders` object (or a draw's own, draws[].shaders, complete by then).
ShaderSettings read_shaders(JsonObject o, const JsonSource& source, const std::filesystem::path& base_dir);

Scene scene_from_json(const nlohmann::json& root, const JsonSource& source,
                      const std::filesystem::path& mesh_base_dir);

}  // namespace tessref
