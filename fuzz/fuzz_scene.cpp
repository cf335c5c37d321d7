// Fuzzes scene loading: scene JSON plus --set overrides through parse_scene (scene_loader.h).
//
// Input: the lines before a line "%%" are overrides (KEY=VALUE, one per line, as --set takes
// them); the rest is the scene file's text. Without a "%%" line, all of it is the scene.
// Expected: a Scene, or InputError for bad input. A finding: any other exception, a crash, UB,
// or a Scene that breaks a rule the loader promises to check (the asserts below).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "common/error.h"
#include "scene/scene_loader.h"

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_scene: a loaded scene breaks a rule: %s\n", what);
    std::abort();
  }
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  std::string text = input;
  std::vector<std::string> lines;
  for (std::size_t pos = 0; pos < input.size();) {
    std::size_t end = input.find('\n', pos);
    if (end == std::string::npos) end = input.size();
    const std::string line = input.substr(pos, end - pos);
    pos = end + 1;
    if (line == "%%") {
      overrides = lines;
      text = pos < input.size() ? input.substr(pos) : "";
      break;
    }
    lines.push_back(line);
  }
  tessref::Scene s;
  try {
    s = tessref::parse_scene(text, "fuzz.json", ".", overrides);
  } catch (const tessref::InputError&) {
    return 0;
  }
  check(s.width >= 1 && s.height >= 1 && s.width <= tessref::kMaxImageSide && s.height <= tessref::kMaxImageSide,
        "image size in range");
  check(static_cast<long long>(s.width) * s.height <= tessref::kMaxImagePixels, "pixel count in range");
  check(s.lights.size() <= static_cast<std::size_t>(tessref::kMaxLights), "light count in range");
  check(s.camera.near > 0.0f && s.camera.far > s.camera.near && std::isfinite(s.camera.far), "near and far");
  check(s.camera.fov_y_deg > 0.0f && s.camera.fov_y_deg < 180.0f, "field of view");
  check(finite(s.camera.eye) && finite(s.camera.target) && finite(s.camera.up), "finite camera");
  check(finite(s.transform.translate) && finite(s.transform.rotate_deg) && finite(s.transform.scale),
        "finite transform");
  check(s.transform.scale.x != 0.0f && s.transform.scale.y != 0.0f && s.transform.scale.z != 0.0f,
        "non-zero scale");
  check(s.material.shininess > 0.0f && std::isfinite(s.material.shininess), "shininess");
  check(s.shaders.patch_vertices >= 1 && s.shaders.patch_vertices <= 32, "patch_vertices");
  check(s.shaders.batch_lanes >= 1 && s.shaders.batch_lanes <= 256 && s.shaders.max_instructions >= 1,
        "executor limits");
  return 0;
}
