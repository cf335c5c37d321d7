// `tessref render`: a scene to an image, with a one-line summary of what the pipeline did.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "common/error.h"
#include "common/parallel.h"
#include "pipeline/image_output.h"
#include "pipeline/mesh_source.h"
#include "pipeline/render.h"
#include "pipeline/scene_loader.h"
#include "pipeline/tess_dump.h"

namespace tessref::cli {
namespace {

struct RenderOptions {
  std::string scene;  // empty: the built-in default scene
  std::string output = "tessref.png";
  std::string depth, normals, dump_tess;
  int threads = 0;
  std::vector<std::string> sets;
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A progress bar on stderr, only for a terminal and only once the render has run a second.
class ProgressBar {
 public:
  ProgressBar() : enabled_(isatty(STDERR_FILENO) == 1), start_(Clock::now()) {}
  ~ProgressBar() {
    if (shown_) std::fprintf(stderr, "\r%*s\r", 60, "");
  }
  void update(double fraction) {
    if (!enabled_ || seconds_since(start_) < 1.0) return;
    shown_ = true;
    const int width = 40, filled = static_cast<int>(fraction * width + 0.5);
    std::fprintf(stderr, "\rrendering [%s%s] %3d%%", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100.0 + 0.5));
    std::fflush(stderr);
  }

 private:
  bool enabled_, shown_ = false;
  Clock::time_point start_;
};

std::string ms(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f ms", seconds * 1e3);
  return buf;
}

void run_render(const RenderOptions& o) {
  const Scene scene = load_scene(o.scene, o.sets);
  check_image_path(o.output, false, "color images");
  if (!o.depth.empty()) check_image_path(o.depth, true, "depth images");
  if (!o.normals.empty()) check_image_path(o.normals, true, "normal images");

  auto t = Clock::now();
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  const double mesh_seconds = seconds_since(t);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());

  const Parallel parallel(o.threads);
  std::unique_ptr<TessDumpWriter> dump;
  if (!o.dump_tess.empty()) {
    if (!scene.tessellation.enabled)
      throw InputError("--dump-tess: the scene does not tessellate (tessellation.enabled is false)");
    dump = std::make_unique<TessDumpWriter>(o.dump_tess);
  }
  RenderResult result;
  {
    ProgressBar bar;
    DrawOptions options;
    options.progress = [&](double f) { bar.update(f); };
    if (dump) options.dump_tess = [&](const std::vector<TessDumpRecord>& r) { dump->write(r); };
    result = render_scene(scene, mesh, parallel, options);
  }
  if (dump) dump->close();

  t = Clock::now();
  write_color_image(result.framebuffer, o.output);
  if (!o.depth.empty()) write_depth_image(result.framebuffer, o.depth);
  if (!o.normals.empty()) write_normals_image(result.framebuffer, o.normals);
  const double write_seconds = seconds_since(t);

  const DrawStats& s = result.stats;
  std::string tessellated;
  if (scene.tessellation.enabled)
    tessellated = ", " + std::to_string(s.triangles_generated) + " after tessellation";
  std::printf(
      "tessref render: %s -> %s (%dx%d, %d threads): %llu triangles in%s, %llu rasterized, "
      "%llu fragments shaded; mesh %s, vertex %s, tessellation %s, raster+fs %s, write %s\n",
      scene.source.c_str(), o.output.c_str(), scene.width, scene.height, parallel.threads(),
      static_cast<unsigned long long>(s.triangles_in), tessellated.c_str(),
      static_cast<unsigned long long>(s.raster.triangles_rasterized),
      static_cast<unsigned long long>(s.raster.fragments_shaded), ms(mesh_seconds).c_str(),
      ms(s.vertex_seconds).c_str(), ms(s.tessellation_seconds).c_str(),
      ms(s.raster_seconds).c_str(), ms(write_seconds).c_str());
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto opts = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene (JSON) to an image");
  cmd->add_option("scene", opts->scene,
                  "scene file (see README.md); without one, the built-in default scene");
  cmd->add_option("-o,--output", opts->output,
                  "color image; the extension picks the format (.png: 8-bit, .exr: float)")
      ->capture_default_str();
  cmd->add_option("--threads", opts->threads, "worker threads (0: all hardware threads)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_option("--set", opts->sets,
                  "override a scene value, KEY=VALUE (e.g. camera.eye=2,5,-10); repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--depth", opts->depth, "also write window-space depth (.exr)");
  cmd->add_option("--normals", opts->normals, "also write world normals (.exr)");
  cmd->add_option("--dump-tess", opts->dump_tess,
                  "also write every tessellated vertex (patch id, gl_TessCoord, position, normal): "
                  "binary, or text for *.txt (format: pipeline/tess_dump.h)");
  cmd->callback([opts] { run_render(*opts); });
}

}  // namespace tessref::cli
