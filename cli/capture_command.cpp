// `tessref capture [SCENE] --out DIR`: the scene through the system's GL driver (the real-GL
// runner, with the scene's GLSL: the built-in programs' twins or the user's shaders), stored as a
// reference for `tessref verify` (glref/reference_capture.h). Only in builds with the runner.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "common/error.h"
#include "pipeline/camera.h"
#include "pipeline/mesh_source.h"
#include "pipeline/scene_loader.h"
#ifdef TESSREF_HAVE_GLREF
#include "glref/gl_context.h"
#include "glref/gl_error.h"
#include "glref/malloc_tuning.h"
#include "glref/reference_capture.h"
#endif

namespace tessref::cli {
namespace {

struct CaptureArgs {
  std::string scene, out;
  std::vector<std::string> sets;
  std::string command_line;
};

void run(const CaptureArgs& a) {
#ifdef TESSREF_HAVE_GLREF
  glref::keep_draw_buffers_off_mmap();
  Scene scene = load_scene(a.scene, a.sets);
  const nlohmann::json scene_json = load_scene_json(a.scene, a.sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  scene.camera = fitted_camera(scene, mesh);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
  try {
    glref::GlContext context;
    const glref::CaptureSummary s = glref::capture_reference(context, scene, mesh, scene_json, a.command_line, a.out);
    std::printf("tessref capture: %s -> %s (%dx%d, %s, %s): color.png, depth.exr, tess.bin (%zu emitted vertices), "
              "manifest.json\n",
              scene.source.c_str(), a.out.c_str(), scene.width, scene.height, context.vendor().c_str(),
              context.renderer().c_str(), s.tess_records);
  } catch (const glref::GlError& e) {
    // No GL 4.5 context, or the driver failed: the machine, not the scene; nothing was written.
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
                 "for `tessref verify`: color, depth, the TES outputs and a manifest");
  add_scene_options(cmd, args->scene, args->sets);
  cmd->add_option("--out", args->out, "the capture folder (created if missing)")->required();
  cmd->callback([args] { run(*args); });
}

}  // namespace tessref::cli
