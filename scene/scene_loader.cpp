#include "scene/scene_loader.h"

#include <functional>
#include <set>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "scene/json_input.h"
#include "scene/json_reader.h"
#include "scene/scene_overrides.h"
#include "scene/draw_schema.h"
#include "scene/scene_schema.h"

namespace tessref {
namespace {

using nlohmann::json;

// Refuses a key given twice in one object: JSON parsers keep the last silently, so a typo'd copy
// would override the intended value without a word. Names the key path ("[]" for array elements).
class DuplicateKeyCheck {
 public:
  bool operator()(int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: frames_.push_back({false, {}, {}}); break;
      case json::parse_event_t::array_start: frames_.push_back({true, {}, {}}); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end: frames_.pop_back(); break;
      case json::parse_event_t::key: {
        Frame& f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second && duplicate_.empty()) duplicate_ = path();
        break;
      }
      case json::parse_event_t::value: break;
    }
    return true;
  }
  const std::string& duplicate() const { return duplicate_; }

 private:
  struct Frame {
    bool array;
    std::string key;
    std::set<std::string> keys;
  };
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) p += f.array ? "[]" : (p.empty() ? "" : ".") + f.key;
    return p;
  }
  std::vector<Frame> frames_;
  std::string duplicate_;
};

json parse_json(const std::string& text, const std::string& name) {
  DuplicateKeyCheck duplicates;
  json j = parse_json_input(text, name, std::ref(duplicates), /*ignore_comments=*/true);
  if (!duplicates.duplicate().empty())
    throw InputError(name + ": " + duplicates.duplicate() +
                     ": the key is given twice in one object (JSON keeps only the last; remove one)");
  return j;
}

}  // namespace

namespace {

// The default scene, the file and the overrides merged, then checked; `merged` keeps the JSON.
Scene parse_merged(const std::string& text, const std::string& name, const std::filesystem::path& base_dir,
                   const std::vector<std::string>& overrides, json& merged) {
  merged = parse_json(default_scene_json(), "<default scene>");
  merge_json(merged, parse_json(text, name));
  JsonSource source{name, {}};
  std::filesystem::path mesh_base = base_dir;
  for (const std::string& text_override : overrides) {
    SceneOverride o = parse_override(text_override);
    apply_override(merged, o);
    source.overridden.push_back(o.key);
    if (o.key == "mesh" || o.key == "mesh.path") mesh_base = std::filesystem::current_path();
  }
  return scene_from_json(merged, source, mesh_base);
}

std::string read_scene_file(const std::filesystem::path& file) { return read_json_text(file, "scene file"); }

}  // namespace

Scene parse_scene(const std::string& text, const std::string& name,
                  const std::filesystem::path& base_dir,
                  const std::vector<std::string>& overrides) {
  json merged;
  return parse_merged(text, name, base_dir, overrides, merged);
}

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  if (file.empty())
    return parse_scene("{}", "<default scene>", std::filesystem::current_path(), overrides);
  return parse_scene(read_scene_file(file), file.string(), file.parent_path(), overrides);
}

json load_scene_json(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  json merged;
  const Scene scene = file.empty()
      ? parse_merged("{}", "<default scene>", std::filesystem::current_path(), overrides, merged)
      : parse_merged(read_scene_file(file), file.string(), file.parent_path(), overrides, merged);
  // Paths as the renderer will open them.
  if (!scene.mesh.path.empty()) merged["mesh"]["path"] = scene.mesh.path.string();
  const std::pair<const char*, const std::filesystem::path*> shaders[] = {
      {"vertex", &scene.shaders.vertex}, {"tess_control", &scene.shaders.tess_control},
      {"tess_evaluation", &scene.shaders.tess_evaluation}, {"geometry", &scene.shaders.geometry},
      {"fragment", &scene.shaders.fragment}};
  for (const auto& [key, path] : shaders)
    if (!path->empty()) merged["shaders"][key] = path->string();
  return merged;
}

std::vector<SchemaKey> scene_keys() {
  std::vector<SchemaKey> keys;
  const json defaults = parse_json(default_scene_json(), "<default scene>");
  JsonSource source{"<default scene>", {}, &keys};
  scene_from_json(defaults, source, ".");
  // The draw keys, which the default scene does not have.
  const json example_json = parse_json(draw_keys_example(), "<draw keys>");
  JsonObject example(example_json, "", source);
  std::vector<BufferSetting> buffers;
  std::vector<DrawSetting> draws;
  FramebufferSetting framebuffer;
  read_draw_keys(example, source, ".", ShaderSettings{}, buffers, draws, framebuffer);
  return keys;
}

std::string scene_key_default(const std::string& path) {
  std::string pointer = "/" + path;
  for (std::size_t at; (at = pointer.find("[]")) != std::string::npos;) pointer.replace(at, 2, "/0");
  for (char& c : pointer) if (c == '.') c = '/';
  const json defaults = parse_json(default_scene_json(), "<default scene>");
  const json::json_pointer p(pointer);
  return defaults.contains(p) ? defaults.at(p).dump() : std::string();
}

}  // namespace tessref
