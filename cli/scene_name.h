#pragma once
// How a command names the scene it ran: in its header line, and as the arguments of a command
// that runs the same scene again.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tessref::cli {

// The scene as drawn: its source (a file, or "<default scene>") and the keys --set changed
// ("<default scene> with --set mesh.type, tessellation.inner").
std::string scene_label(const std::string& source, const std::vector<std::string>& sets);
inline std::string drawn_scene_name(const Scene& scene, const std::vector<std::string>& sets) {
  return scene_label(scene.source, sets);
}

// An argument as a POSIX shell reads it back: single-quoted unless it is plain.
std::string shell_word(const std::string& s);

// "FILE --set K=V ... " (each word for the shell, a space after each) for a command that must
// run the same scene: scene_file empty for the built-in default scene.
std::string scene_arguments(const std::string& scene_file, const std::vector<std::string>& sets);

}  // namespace tessref::cli
