// tessref-glref-render: a tessref scene rendered by the GL driver with tessref's GLSL twins, for
// comparison with `tessref render` (same scene loading, same --set overrides, same image writer).
// --fair sets the driver up at its best for an 8-bit PNG (SceneRendererOptions::fair_rgba8): the
// whole-process half of scripts/bench-startup.sh.

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/error.h"
#include "common/malloc_tuning.h"
#include "glref/gl_context.h"
#include "glref/gl_error.h"
#include "glref/scene_renderer.h"
#include "io/image_compare.h"
#include "io/image_output.h"
#include "mesh/camera.h"
#include "mesh/mesh_source.h"
#include "scene/scene_loader.h"

namespace {

using namespace tessref;
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

struct Options {
  std::string scene, output = "glref.png", depth, compare_with, diff;
  std::vector<std::string> sets;
  std::string platform = "auto", color = "rgba32f";
  int device = -1;
  double require_share = -1.0;  // percent; < 0: report only
  bool fair = false;
};

int run(const Options& o) {
  Scene scene = load_scene(o.scene, o.sets);
  check_image_path(o.output, ImageKind::Color);
  if (!o.depth.empty()) check_image_path(o.depth, ImageKind::Depth);
  if (!o.diff.empty()) check_image_path(o.diff, ImageKind::Color);
  if (!o.diff.empty() && o.compare_with.empty()) throw InputError("--diff needs --compare-with");
  if (o.fair && !o.depth.empty()) throw InputError("--fair has no depth image to write (24-bit depth is not read back)");

  auto t = Clock::now();
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  scene.camera = fitted_camera(scene, mesh);
  const double mesh_ms = ms_since(t);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref-glref-render: warning: %s\n", w.c_str());

  glref::GlContextOptions context_options;
  if (!glref::parse(o.platform, context_options.platform))
    throw InputError("--platform: expected auto, surfaceless or device");
  context_options.device_index = o.device;
  t = Clock::now();
  glref::GlContext context(context_options);
  glref::SceneRendererOptions options;
  options.color = o.color == "rgba8" ? ColorFormat::kRgba8 : ColorFormat::kRgba32F;
  if (o.fair) options = glref::SceneRendererOptions::fair_rgba8();
  glref::SceneRenderer renderer(context, scene, mesh, options);
  const double setup_ms = ms_since(t);
  Framebuffer fb;
  Rgb8Image fair_image;  // --fair: the RGBA8 read-back as the PNG holds it
  if (o.fair) {
    renderer.draw();
    fair_image = glref::rgb8_top_first(renderer.read_back_rgba8(), scene.width, scene.height);
  } else {
    fb = renderer.render();
  }
  const glref::SceneRenderStats stats = renderer.last_stats();

  t = Clock::now();
  if (o.fair) write_rgb8_image(fair_image, o.output);
  else write_color_image(fb, o.output);
  if (!o.depth.empty()) write_depth_image(fb, o.depth);
  const double write_ms = ms_since(t);
  std::printf(
      "tessref-glref-render: %s -> %s (%dx%d, %s): %zu draw calls; mesh %.1f ms, context+programs "
      "%.1f ms, draw+finish %.1f ms, readback %.1f ms, write %.1f ms\n",
      scene.source.c_str(), o.output.c_str(), scene.width, scene.height, context.renderer().c_str(),
      stats.draws, mesh_ms, setup_ms, stats.draw_seconds * 1e3, stats.readback_seconds * 1e3, write_ms);

  if (o.compare_with.empty()) return 0;
  const Rgb8Image other = read_rgb8_image(o.compare_with);
  const ImageComparison c =
      compare_images(o.fair ? fair_image : to_rgb8(fb), other, scene.background, 2, !o.diff.empty());
  std::printf("compare with %s: %s\n", o.compare_with.c_str(), c.summary().c_str());
  if (!o.diff.empty()) write_rgb8_image(c.diff, o.diff);
  if (o.require_share >= 0.0 && 100.0 * c.share_within() < o.require_share) {
    std::fprintf(stderr, "tessref-glref-render: %.4f%% within 2/255, below the required %.4f%%\n",
                 100.0 * c.share_within(), o.require_share);
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  tessref::keep_draw_buffers_off_mmap();
  CLI::App app{"tessref-glref-render: a tessref scene on the GL driver, with tessref's GLSL twins"};
  Options o;
  app.add_option("scene", o.scene, "scene file (as `tessref render`); without one, the default scene");
  app.add_option("-o,--output", o.output, "color image (.png 8-bit, .exr float)")->capture_default_str();
  app.add_option("--set", o.sets, "override a scene value, KEY=VALUE; repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--depth", o.depth, "also write window-space depth (.exr)");
  app.add_option("--compare-with", o.compare_with,
                 "an 8-bit image of the same scene (e.g. from `tessref render`) to compare with");
  app.add_option("--diff", o.diff, "with --compare-with: write the difference image here");
  app.add_option("--require", o.require_share,
                 "with --compare-with: exit 1 if fewer than this percent of pixels are within 2/255");
  app.add_option("--color", o.color, "render target color format")
      ->check(CLI::IsMember({"rgba32f", "rgba8"}))
      ->capture_default_str();
  app.add_flag("--fair", o.fair,
               "the driver at its best for an 8-bit PNG: RGBA8 colour, 24-bit depth, no normals target, "
               "the twins specialized for the scene, an RGBA8 read-back (overrides --color)");
  app.add_option("--platform", o.platform, "EGL platform: auto, surfaceless, device")->capture_default_str();
  app.add_option("--device", o.device, "EGL device index (device platform)");
  try {
    app.parse(argc, argv);
    return run(o);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const tessref::InputError& e) {
    std::fprintf(stderr, "tessref-glref-render: error: %s\n", e.what());
    return 2;
  } catch (const tessref::glref::GlError& e) {
    std::fprintf(stderr, "tessref-glref-render: GL error: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessref-glref-render: internal error: %s\n", e.what());
    return 3;
  }
}
