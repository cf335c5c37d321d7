#include "cli/scene_name.h"

namespace tessref::cli {

std::string drawn_scene_name(const Scene& scene, const std::vector<std::string>& sets) {
  std::string keys;
  for (const std::string& set : sets) keys += (keys.empty() ? "" : ", ") + set.substr(0, set.find('='));
  return keys.empty() ? scene.source : scene.source + " with --set " + keys;
}

}  // namespace tessref::cli
