// End-to-end frame time at 1024x1024, tessref against Mesa llvmpipe in the same process. Scenes
// (all PN triangles, fractional_odd, quadratic normals, Phong shading):
//   pn12:     the default scene (torus, 256 triangles) at level 12;
//   ico64:    an 80-triangle icosphere at level 64;
//   wuson12:  Wuson (assimp-testmodels, 3,732 triangles; scenes/wuson_pn64.json) at level 12;
//   wuson64:  the same at level 64 (22.2 M triangles, ~2 s per frame on each side);
//   textured: the default scene as user GLSL (scenes/textured.json): the PN twins on tessref's
//             SPIR-V executor and a one-light Phong coloured from a mip-mapped GL_RGB8 texture
//             with implicit LOD; llvmpipe runs the same GLSL files.
// What one iteration includes:
//   tessref:  render_scene with all hardware threads: framebuffer clear, vertex shader,
//             TCS/TPG/TES, rasterization and Phong shading, into RGBA32F colour and float depth
//             (no normals target, as `tessref render` without --normals). Not the mesh, not
//             image files.
//   llvmpipe, fair (BM_LlvmpipeFrame/<scene>/fair, the one the ratio uses): llvmpipe at its best
//             for the same 8-bit image: the GLSL twins compiled for the scene (light count,
//             normal mode and switches as constants, glsl_rewrite.h specialize_uniforms), one RGBA8
//             attachment and 24-bit depth, clear, the (split) GL_PATCHES draws, glFinish and an
//             RGBA8 glReadPixels. Before timing, its image is compared with tessref's (to_rgb8):
//             more than kMaxDifferingPixels pixels over 1/255 and the benchmark fails, so no figure
//             is reported for two different images.
//   llvmpipe, rgba32f (BM_LlvmpipeFrame/<scene>/rgba32f): the verification target, for reference
//             only: the twins as written (light loop bounded by a uniform), RGBA32F colour and
//             normals, 32-bit float depth, all three read back as floats. Not a speed claim.
// Not the context, program linking or mesh upload (done once per run). Both sides run in this one
// process, so they share its malloc settings (scripts/bench.sh sets GLIBC_TUNABLES).
// The closing table gives both frame times, the ratio tessref / fair llvmpipe (the project's
// target: <= 0.33) and the image check.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.h"
#include "common/parallel.h"
#include "io/image_compare.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#ifdef TESSREF_HAVE_GLREF
#include "glref/gl_context.h"
#include "glref/scene_renderer.h"
#endif

#ifndef TESSREF_BENCH_SOURCE_DIR
#define TESSREF_BENCH_SOURCE_DIR "."
#endif

namespace {

using namespace tessref;

struct FrameSpec {
  std::string name;
  std::string file;  // scene file under the source tree; empty: the default scene
  std::vector<std::string> sets;
};

std::vector<std::string> pn_at(int level, std::vector<std::string> more = {}) {
  std::vector<std::string> s{"tessellation.enabled=true",
                             "tessellation.scheme=pn",
                             "tessellation.spacing=fractional_odd",
                             "tessellation.normal_mode=quadratic",
                             "tessellation.adaptive.enabled=false",
                             "image.width=1024",
                             "image.height=1024",
                             "tessellation.inner=" + std::to_string(level),
                             "tessellation.outer=" + std::to_string(level)};
  s.insert(s.end(), more.begin(), more.end());
  return s;
}

const std::vector<FrameSpec>& specs() {
  static const std::vector<FrameSpec> s{
      {"pn12", "", pn_at(12)},
      {"ico64", "", pn_at(64, {"mesh.type=icosphere", "mesh.icosphere.refinements=1"})},
      {"wuson12", "scenes/wuson_pn64.json", pn_at(12)},
      {"wuson64", "scenes/wuson_pn64.json", pn_at(64)},
      {"textured", "scenes/textured.json", {}},
  };
  return s;
}

struct Frame {
  Scene scene;
  Mesh mesh;
  std::string error;  // the scene or its mesh could not be loaded (e.g. assimp-testmodels missing)
};

// Loaded on first use, so that a filter that skips a scene never loads its mesh.
const Frame& frame(std::size_t which) {
  static std::map<std::size_t, Frame> frames;
  const auto it = frames.find(which);
  if (it != frames.end()) return it->second;
  Frame& f = frames[which];
  const FrameSpec& spec = specs()[which];
  try {
    const std::string path =
        spec.file.empty() ? std::string() : std::string(TESSREF_BENCH_SOURCE_DIR) + "/" + spec.file;
    f.scene = load_scene(path, spec.sets);
    std::vector<std::string> warnings;
    f.mesh = build_mesh(f.scene.mesh, warnings);
  } catch (const std::exception& e) {
    f.error = spec.name + ": " + e.what();
    std::fprintf(stderr, "frame_bench: %s\n", f.error.c_str());
  }
  return f;
}

const Parallel& parallel() {
  static const Parallel p;  // all hardware threads
  return p;
}

// How tessref draws a frame here, timed and checked: as `tessref render` without --normals (and
// as llvmpipe's fair target, which has no normals target either).
DrawOptions frame_options() {
  DrawOptions options;
  options.normals = false;
  return options;
}

void tessref_frame(benchmark::State& state, std::size_t which) {
  const Frame& f = frame(which);
  if (!f.error.empty()) return state.SkipWithError(f.error.c_str());
  DrawStats stats;
  Framebuffer fb;  // kept from frame to frame, as llvmpipe keeps its render target
  const DrawOptions options = frame_options();
  for (auto _ : state) {
    stats = render_scene(f.scene, f.mesh, parallel(), fb, options);
    benchmark::DoNotOptimize(fb.color.data());
  }
  state.SetLabel(specs()[which].name);
  state.counters["triangles"] = double(stats.triangles_generated);
  state.counters["domain_points"] = double(stats.tess.domain_points);
  state.counters["fragments"] = double(stats.raster.fragments_shaded);
  state.counters["threads"] = parallel().threads();
  bench::set_work_counters(
      state, bench::work::frame(stats.tess.domain_points, stats.triangles_generated,
                                stats.raster.fragments_shaded,
                                std::uint64_t(f.scene.width) * std::uint64_t(f.scene.height)));
}

#ifdef TESSREF_HAVE_GLREF
// Pixels of the fair pair's images allowed to differ by more than 1/255 (any channel): depth ties
// resolved differently by 24-bit and float depth, and silhouette pixels whose coverage differs
// with the last bit of a TES position. Measured: docs/benchmarks.md.
constexpr std::size_t kMaxDifferingPixels = 64;

void llvmpipe_frame(benchmark::State& state, std::size_t which, bool fair) {
  glref::GlContext* ctx = bench::gl_context();
  if (!ctx) return state.SkipWithError("no GL context");
  const Frame& f = frame(which);
  if (!f.error.empty()) return state.SkipWithError(f.error.c_str());
  const glref::SceneRendererOptions options = fair ? glref::SceneRendererOptions::fair_rgba8()
                                                   : glref::SceneRendererOptions{};
  glref::SceneRenderer renderer(*ctx, f.scene, f.mesh, options);
  if (fair) {
    renderer.draw();
    Framebuffer fb;
    render_scene(f.scene, f.mesh, parallel(), fb, frame_options());  // the timed frame's setup
    // tessref's frame as its PNG holds it against llvmpipe's RGBA8 read-back.
    const ImageComparison check = compare_images(
        to_rgb8(fb), glref::rgb8_top_first(renderer.read_back_rgba8(), fb.width, fb.height),
        f.scene.background, 1);
    const std::size_t over_one = check.pixels - check.within_tolerance;
    state.counters["pixels_over_1"] = double(over_one);
    state.counters["max_diff"] = check.max_difference;
    if (over_one > kMaxDifferingPixels) {
      const std::string why = "the images differ: " + std::to_string(over_one) +
                              " pixels over 1/255 (at most " + std::to_string(kMaxDifferingPixels) +
                              " allowed), max " + std::to_string(check.max_difference) + "/255";
      return state.SkipWithError(why.c_str());
    }
  }
  for (auto _ : state) {
    renderer.draw();
    if (fair) {
      std::vector<glm::u8vec4> color = renderer.read_back_rgba8();
      benchmark::DoNotOptimize(color.data());
    } else {
      Framebuffer fb = renderer.read_back();
      benchmark::DoNotOptimize(fb.color.data());
    }
  }
  state.SetLabel(specs()[which].name + (fair ? " fair (specialized, rgba8+depth24) " : " rgba32f+normals ") +
                 ctx->renderer());
  state.counters["draws"] = double(renderer.last_stats().draws);
  state.counters["readback_ms"] = renderer.last_stats().readback_seconds * 1e3;
}
#endif

[[maybe_unused]] const bool registered = [] {
  for (std::size_t i = 0; i < specs().size(); ++i) {
    const std::string& name = specs()[i].name;
    benchmark::RegisterBenchmark(("BM_TessrefFrame/" + name).c_str(),
                                 [i](benchmark::State& s) { tessref_frame(s, i); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
#ifdef TESSREF_HAVE_GLREF
    for (const bool fair : {true, false})
      benchmark::RegisterBenchmark(
          ("BM_LlvmpipeFrame/" + name + (fair ? "/fair" : "/rgba32f")).c_str(),
          [i, fair](benchmark::State& s) { llvmpipe_frame(s, i, fair); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
#endif
  }
  return true;
}();

class RatioReporter : public bench::MedianReporter {
 public:
  void print_ratios() const {
    std::printf("\nscene     tessref ms/frame  fair llvmpipe ms/frame  tessref/llvmpipe  pixels over 1/255 (max)  llvmpipe rgba32f ms\n");
    for (const FrameSpec& spec : specs()) {
      const Result* t = result("BM_TessrefFrame/" + spec.name + "/real_time");
      const Result* l = result("BM_LlvmpipeFrame/" + spec.name + "/fair/real_time");
      const Result* l32 = result("BM_LlvmpipeFrame/" + spec.name + "/rgba32f/real_time");
      if (!t) continue;
      char gl[32] = "n/a", ratio[32] = "n/a", check[48] = "n/a", heavy[32] = "n/a";
      if (l) {
        std::snprintf(gl, sizeof gl, "%.1f", l->real_seconds * 1e3);
        std::snprintf(ratio, sizeof ratio, "%.2f", t->real_seconds / l->real_seconds);
        std::snprintf(check, sizeof check, "%.0f (%.0f/255)", l->counters.at("pixels_over_1"),
                      l->counters.at("max_diff"));
      }
      if (l32) std::snprintf(heavy, sizeof heavy, "%.1f", l32->real_seconds * 1e3);
      std::printf("%-8s  %16.1f  %22s  %16s  %23s  %19s\n", spec.name.c_str(), t->real_seconds * 1e3, gl,
                  ratio, check, heavy);
    }
  }
};

}  // namespace

int main(int argc, char** argv) { return tessref::bench::run_benchmarks<RatioReporter>(argc, argv); }
