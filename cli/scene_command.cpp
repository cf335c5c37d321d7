// `tessref scene [SCENE] [--set ...]`: the scene as render would draw it (the default scene, the
// file and the overrides merged, every check passed) printed as JSON; `--keys` lists every key
// the loader reads with what it allows and its default.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "mesh/mesh_source.h"
#include "render/as_draws.h"
#include "scene/scene_loader.h"

namespace tessref::cli {
namespace {

struct SceneArgs {
  std::string scene;
  std::vector<std::string> sets;
  bool keys = false;
  std::string as_draws;
};

}  // namespace

std::string scene_keys_text() {
  std::string text;
  for (const SchemaKey& k : scene_keys()) {
    std::string line = "  " + k.path;
    line.resize(std::max<std::size_t>(line.size() + 2, 44), ' ');
    line += k.allowed.empty() ? std::string("(see README.md)") : k.allowed;
    const std::string def = scene_key_default(k.path);
    if (!def.empty() && def.size() <= 40) line += "; default " + def;
    else if (k.optional) line += "; optional";
    text += line + "\n";
  }
  return text;
}

void add_scene_command(CLI::App& app) {
  auto args = std::make_shared<SceneArgs>();
  CLI::App* cmd = app.add_subcommand(
      "scene", "Print a scene as render reads it (default scene, file and --set merged, then checked) as JSON");
  add_scene_options(cmd, args->scene, args->sets);
  cmd->add_flag("--keys", args->keys, "list every scene key, what it allows and its default, and exit");
  cmd->add_option("--as-draws", args->as_draws,
                  "write the mesh scene as the GL draw render makes of it into folder DIR: DIR/scene.json, the "
                  "mesh's buffers and the program's GLSL (the built-in programs as their twins)");
  cmd->callback([args] {
    if (args->keys) {
      std::printf("Scene keys (read in this order; array elements as []):\n%s", scene_keys_text().c_str());
      return;
    }
    if (!args->as_draws.empty()) {
      const Scene scene = load_scene(args->scene, args->sets);
      std::vector<std::string> warnings;
      const Mesh mesh = build_mesh(scene.mesh, warnings);
      for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
      write_scene_as_draws(load_scene_json(args->scene, args->sets), scene, mesh, args->as_draws);
      std::printf("tessref scene: %s -> %s/scene.json (%zu vertices, %zu indices)\n", scene.source.c_str(),
                  args->as_draws.c_str(), mesh.vertex_count(), mesh.indices.size());
      return;
    }
    std::printf("%s\n", load_scene_json(args->scene, args->sets).dump(2).c_str());
  });
}

}  // namespace tessref::cli
