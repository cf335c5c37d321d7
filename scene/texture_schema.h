#pragma once
// shaders.textures.NAME: an image file name, or an object that says how the application creates
// the texture (target, internal format, levels, glGenerateMipmap, or a buffer texture's range of a
// scene buffer) and samples it (glTexParameter's filters, wraps, border colour, LOD range and bias,
// base and max level, swizzle).
#include <filesystem>

#include "scene/json_reader.h"
#include "scene/scene.h"

namespace tessref {

// `value` is shaders.textures.NAME at `path`; relative file names are resolved against base_dir.
TextureSetting read_texture_setting(const std::string& name, const nlohmann::json& value, const std::string& path,
                                    const JsonSource& source, const std::filesystem::path& base_dir);

}  // namespace tessref
