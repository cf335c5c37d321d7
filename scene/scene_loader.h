#pragma once
// Reading scenes: a file (or the built-in default) merged over the default scene, then --set
// overrides, then validation. Bad input throws InputError naming the file and the key.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/json_reader.h"
#include "scene/scene.h"

namespace tessref {

// scenes/default.json as compiled into the library.
const std::string& default_scene_json();

// Reads a scene file; an empty path means the default scene. Objects merge key by key over the
// default scene (anything else replaces), so a file need only give what differs. Overrides are
// "key.path=value" strings (see scene_overrides.h).
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// The same from JSON text: `name` prefixes error messages and relative mesh paths resolve against
// base_dir (a mesh path given by --set resolves against the current directory instead).
Scene parse_scene(const std::string& text, const std::string& name,
                  const std::filesystem::path& base_dir,
                  const std::vector<std::string>& overrides = {});

// What `tessref scene` prints: the scene as load_scene reads it (the default scene, the file and
// the overrides merged), after every check has passed, with file paths resolved.
nlohmann::json load_scene_json(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// Every key the loader reads, with what it allows, in the order it reads them: recorded from the
// loader's own accessors (json_reader.h), for --help and `tessref scene --keys`.
std::vector<SchemaKey> scene_keys();
// A key's value in the default scene, as compact JSON ("" where it has none).
std::string scene_key_default(const std::string& path);

}  // namespace tessref
