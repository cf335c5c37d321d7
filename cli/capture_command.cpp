// `tessref capture [SCENE] --out DIR`: the scene through the system's GL driver (the real-GL
// runner, with the scene's GLSL: the built-in programs' twins or the user's shaders), stored as a
// reference for `tessref verify` (glref/reference_capture.h). Only in builds with the runner.
// With a folder of scenes, every scene (or one shard of them, cli/shard.h) into OUT/<stem>/.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/scene_name.h"
#include "cli/shard.h"
#include "common/error.h"
#include "mesh/camera.h"
#include "mesh/mesh_source.h"
#include "scene/scene_loader.h"
#ifdef TESSREF_HAVE_GLREF
#include "glref/gl_context.h"
#include "glref/gl_error.h"
#include "glref/reference_capture.h"
#endif

namespace tessref::cli {
namespace {

struct CaptureArgs {
  std::string scene, out, shard;
  std::vector<std::string> sets;
  std::string command_line;
  std::size_t tess_records = 0;  // 0: all
};

#ifdef TESSREF_HAVE_GLREF
// One scene into one capture folder, through a context that campaigns share between scenes.
void capture_one(glref::GlContext& context, const std::string& scene_path, const std::vector<std::string>& sets,
                 const std::string& command_line, const std::string& out, std::size_t tess_records) {
  Scene scene = load_scene(scene_path, sets);
  if (scene.tessellation.enabled && scene.tessellation.tessellator != Tessellator::PrimitiveGenerator)
    throw InputError(scene.source + ": tessellation.tessellator is \"" + to_string(scene.tessellation.tessellator) +
                     "\", which only tessref has; a GL driver "
                     "tessellates with its primitive generator (capture the scene with \"primitive_generator\")");
  const nlohmann::json scene_json = load_scene_json(scene_path, sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  scene.camera = fitted_camera(scene, mesh);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
  const glref::CaptureSummary s =
      glref::capture_reference(context, scene, mesh, scene_json, command_line, out, tess_records);
  const std::string sample = s.patch_stride > 1 ? ", " + std::to_string(s.tess_records_stored) + " stored: the patches whose id is a multiple of " +
                                                      std::to_string(s.patch_stride)
                                                : std::string();
  std::printf("tessref capture: %s -> %s (%dx%d, %s, %s): color.png, depth.exr, tess.bin (%zu emitted vertices%s), "
              "tess_patches.bin, manifest.json\n",
              drawn_scene_name(scene, sets).c_str(), out.c_str(), scene.width, scene.height, context.vendor().c_str(),
              context.renderer().c_str(), s.tess_records, sample.c_str());
  std::fflush(stdout);
}
#endif

void run(const CaptureArgs& a) {
#ifdef TESSREF_HAVE_GLREF
  std::error_code ec;
  const bool campaign = !a.scene.empty() && std::filesystem::is_directory(a.scene, ec);
  if (!campaign && !a.shard.empty()) throw InputError("--shard needs a folder of scenes, not one scene");
  std::vector<CampaignScene> scenes;
  if (campaign) scenes = campaign_scenes(a.scene, a.shard.empty() ? Shard{} : parse_shard(a.shard));
  try {
    glref::GlContext context;
    if (!campaign) return capture_one(context, a.scene, a.sets, a.command_line, a.out, a.tess_records);
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      const auto start = std::chrono::steady_clock::now();
      const std::string out = (std::filesystem::path(a.out) / scenes[k].stem).string();
      try {
        capture_one(context, scenes[k].path.string(), a.sets, a.command_line, out, a.tess_records);
      } catch (const InputError& e) {
        throw InputError("scene '" + scenes[k].stem + "' (" + scenes[k].path.string() + "): " + e.what());
      }
      std::fprintf(stderr, "tessref capture: [%zu/%zu] %s (%.1f s)\n", k + 1, scenes.size(), scenes[k].stem.c_str(),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
  } catch (const glref::GlError& e) {
    // No GL 4.5 context, or the driver failed: the machine, not the scene.
    throw InputError(std::string("capture: the GL driver failed: ") + e.what());
  }
#else
  (void)a;
  throw InputError("capture: this build of tessref has no real-GL reference runner (configure with libepoxy and EGL)");
#endif
}

}  // namespace

void add_capture_command(CLI::App& app, int argc, char** argv) {
  auto args = std::make_shared<CaptureArgs>();
  for (int i = 0; i < argc; ++i) args->command_line += (i ? " " : "") + std::string(argv[i]);
  CLI::App* cmd = app.add_subcommand(
      "capture", "Draw a scene through the system's GL driver (EGL, e.g. Mesa llvmpipe) and store a reference "
                 "for `tessref verify`: color, depth, the TES outputs and a manifest. SCENE may be a folder of scenes");
  add_scene_options(cmd, args->scene, args->sets);
  cmd->add_option("--out", args->out,
                  "the capture folder (created if missing); for a folder of scenes, the folder of their capture "
                  "folders, one per scene named after its file")
      ->required();
  cmd->add_option("--tess-records", args->tess_records,
                  "keep tess.bin within this many records by storing every k-th patch's (0: every patch); every "
                  "patch's coordinates are still compared, by digest (tess_patches.bin)")
      ->check(kInteger)
      ->check(CLI::Range(0.0, 1e12));
  cmd->add_option("--shard", args->shard,
                  "with a folder of scenes, only shard I/N of them (0-based; 'auto' as for verify --shard)");
  cmd->callback([args] { run(*args); });
}

}  // namespace tessref::cli
