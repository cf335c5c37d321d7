// End-to-end frame time at 1024x1024, tessref against Mesa llvmpipe in the same process. Scenes
// (all PN triangles, fractional_odd, quadratic normals, Phong shading):
//   pn12:     the default scene (torus, 256 triangles) at level 12;
//   ico64:    an 80-triangle icosphere at level 64;
//   wuson12:  Wuson (assimp-testmodels, 3,732 triangles; scenes/wuson_pn64.json) at level 12;
//   wuson64:  the same at level 64 (22.2 M triangles, ~2 s per frame on each side).
// What one iteration includes:
//   tessref:  render_scene with all hardware threads: framebuffer allocation and clear, vertex
//             shader, TCS/TPG/TES, rasterization and Phong shading. Not the mesh, not image files.
//   llvmpipe: SceneRenderer::draw + read_back: clear, the (split) GL_PATCHES draws, glFinish, and
//             glReadPixels of color (RGBA32F), depth and normals. Not the context, program linking
//             or mesh upload (done once per run).
// Benchmarks are named BM_TessrefFrame/<scene> and BM_LlvmpipeFrame/<scene>/<target>, target
// rgba32f (color + normals as RGBA32F, what tessref's framebuffer holds: the ratio uses it) or
// rgba8 (one RGBA8 attachment), so a filter can pick scenes. The closing table gives both frame
// times and the ratio tessref / llvmpipe (the project's target: <= 0.33).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.h"
#include "common/parallel.h"
#include "pipeline/mesh_source.h"
#include "pipeline/render.h"
#include "pipeline/scene_loader.h"
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

void tessref_frame(benchmark::State& state, std::size_t which) {
  const Frame& f = frame(which);
  if (!f.error.empty()) return state.SkipWithError(f.error.c_str());
  DrawStats stats;
  Framebuffer fb;  // kept from frame to frame, as llvmpipe keeps its render target
  for (auto _ : state) {
    stats = render_scene(f.scene, f.mesh, parallel(), fb);
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
// rgba8: the lighter target, what the driver needs for an 8-bit image only.
void llvmpipe_frame(benchmark::State& state, std::size_t which, bool rgba8) {
  glref::GlContext* ctx = bench::gl_context();
  if (!ctx) return state.SkipWithError("no GL context");
  const Frame& f = frame(which);
  if (!f.error.empty()) return state.SkipWithError(f.error.c_str());
  glref::SceneRendererOptions options;
  if (rgba8) {
    options.color = glref::ColorFormat::Rgba8;
    options.normals_attachment = false;
  }
  glref::SceneRenderer renderer(*ctx, f.scene, f.mesh, options);
  for (auto _ : state) {
    renderer.draw();
    Framebuffer fb = renderer.read_back();
    benchmark::DoNotOptimize(fb.color.data());
  }
  state.SetLabel(specs()[which].name + (rgba8 ? " rgba8 only " : " rgba32f+normals ") +
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
    for (const bool rgba8 : {false, true})
      benchmark::RegisterBenchmark(
          ("BM_LlvmpipeFrame/" + name + (rgba8 ? "/rgba8" : "/rgba32f")).c_str(),
          [i, rgba8](benchmark::State& s) { llvmpipe_frame(s, i, rgba8); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
#endif
  }
  return true;
}();

class RatioReporter : public bench::MedianReporter {
 public:
  void print_ratios() const {
    std::printf("\nscene    tessref ms/frame  llvmpipe ms/frame  tessref/llvmpipe  llvmpipe rgba8-only ms\n");
    for (const FrameSpec& spec : specs()) {
      const Result* t = result("BM_TessrefFrame/" + spec.name + "/real_time");
      const Result* l = result("BM_LlvmpipeFrame/" + spec.name + "/rgba32f/real_time");
      const Result* l8 = result("BM_LlvmpipeFrame/" + spec.name + "/rgba8/real_time");
      if (!t) continue;
      char light[32] = "n/a", gl[32] = "n/a", ratio[32] = "n/a";
      if (l8) std::snprintf(light, sizeof light, "%.1f", l8->real_seconds * 1e3);
      if (l) {
        std::snprintf(gl, sizeof gl, "%.1f", l->real_seconds * 1e3);
        std::snprintf(ratio, sizeof ratio, "%.2f", t->real_seconds / l->real_seconds);
      }
      std::printf("%-7s  %16.1f  %17s  %16s  %22s\n", spec.name.c_str(), t->real_seconds * 1e3, gl,
                  ratio, light);
    }
  }
};

}  // namespace

int main(int argc, char** argv) { return tessref::bench::run_benchmarks<RatioReporter>(argc, argv); }
