// `tessref scene [SCENE] [--set ...]`: the scene as render would draw it (the default scene, the
// file and the overrides merged, every check passed) printed as JSON; `--keys` lists every key
// the loader reads with what it allows and its default.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "scene/scene_loader.h"

namespace tessref::cli {
namespace {

struct SceneArgs {
  std::string scene;
  std::vector<std::string> sets;
  bool keys = false;
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
  cmd->callback([args] {
    if (args->keys) {
      std::printf("Scene keys (read in this order; array elements as []):\n%s", scene_keys_text().c_str());
      return;
    }
    std::printf("%s\n", load_scene_json(args->scene, args->sets).dump(2).c_str());
  });
}

}  // namespace tessref::cli
