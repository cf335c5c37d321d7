// End-to-end frame time at 1024x1024, tessref against Mesa llvmpipe in the same process:
//   pn12:   the default scene (torus, 256 triangles) with PN tessellation, level 12, fractional_odd,
//           quadratic normals, Phong shading;
//   ico64:  a 80-triangle icosphere, same settings at level 64.
// What one iteration includes:
//   tessref:  render_scene with all hardware threads: framebuffer allocation and clear, vertex
//             shader, TCS/TPG/TES, rasterization and Phong shading. Not the mesh, not image files.
//   llvmpipe: SceneRenderer::draw + read_back: clear, the (split) GL_PATCHES draws, glFinish, and
//             glReadPixels of color (RGBA32F), depth and normals. Not the context, program linking
//             or mesh upload (done once).
// The closing table gives both frame times and the ratio (llvmpipe / tessref).
#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "common/parallel.h"
#include "pipeline/mesh_source.h"
#include "pipeline/render.h"
#include "pipeline/scene_loader.h"
#include "bench_common.h"
#ifdef TESSREF_HAVE_GLREF
#include "glref/gl_context.h"
#include "glref/scene_renderer.h"
#endif

namespace {

using namespace tessref;

const char* const kSceneNames[] = {"pn12", "ico64"};

struct Frame {
  Scene scene;
  Mesh mesh;
};

const Frame& frame(int which) {
  static const std::array<Frame, 2> frames = [] {
    const std::vector<std::string> pn{"tessellation.enabled=true",  "tessellation.scheme=pn",
                                      "tessellation.spacing=fractional_odd",
                                      "tessellation.normal_mode=quadratic",
                                      "tessellation.adaptive.enabled=false", "image.width=1024",
                                      "image.height=1024"};
    auto make = [](std::vector<std::string> sets) {
      Frame f;
      f.scene = load_scene("", sets);
      std::vector<std::string> warnings;
      f.mesh = build_mesh(f.scene.mesh, warnings);
      return f;
    };
    std::vector<std::string> a = pn, b = pn;
    a.insert(a.end(), {"tessellation.inner=12", "tessellation.outer=12"});
    b.insert(b.end(), {"tessellation.inner=64", "tessellation.outer=64", "mesh.type=icosphere",
                       "mesh.icosphere.refinements=1"});
    return std::array<Frame, 2>{make(a), make(b)};
  }();
  return frames[which];
}

void BM_TessrefFrame(benchmark::State& state) {
  const Frame& f = frame(int(state.range(0)));
  static const Parallel parallel;  // all hardware threads
  std::uint64_t triangles = 0;
  for (auto _ : state) {
    RenderResult r = render_scene(f.scene, f.mesh, parallel);
    benchmark::DoNotOptimize(r.framebuffer.color.data());
    triangles = r.stats.triangles_generated;
  }
  state.SetLabel(kSceneNames[state.range(0)]);
  state.counters["triangles"] = double(triangles);
  state.counters["threads"] = parallel.threads();
}
BENCHMARK(BM_TessrefFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

#ifdef TESSREF_HAVE_GLREF

void BM_LlvmpipeFrame(benchmark::State& state) {
  glref::GlContext* ctx = bench::gl_context();
  if (!ctx) {
    state.SkipWithError("no GL context");
    return;
  }
  const Frame& f = frame(int(state.range(0)));
  glref::SceneRendererOptions options;
  if (state.range(1) == 1) {  // the lighter target: what the driver needs for an 8-bit image only
    options.color = glref::ColorFormat::Rgba8;
    options.normals_attachment = false;
  }
  glref::SceneRenderer renderer(*ctx, f.scene, f.mesh, options);
  for (auto _ : state) {
    renderer.draw();
    Framebuffer fb = renderer.read_back();
    benchmark::DoNotOptimize(fb.color.data());
  }
  state.SetLabel(std::string(kSceneNames[state.range(0)]) +
                 (state.range(1) == 1 ? " rgba8 only " : " rgba32f+normals ") + ctx->renderer());
  state.counters["draws"] = double(renderer.last_stats().draws);
  state.counters["readback_ms"] = renderer.last_stats().readback_seconds * 1e3;
}
// Second argument 0: RGBA32F color + RGBA32F normals, the outputs tessref's framebuffer holds
// (the ratio uses this); 1: one RGBA8 color attachment.
BENCHMARK(BM_LlvmpipeFrame)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
#endif

// Collects the real time per frame of each (implementation, scene) for the ratio table.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  // With --benchmark_repetitions the median is kept (frame times here are bimodal under load).
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
      if (r.run_type != Run::RT_Iteration && !median) continue;
      const std::string key = r.run_name.function_name + "/" + r.run_name.args;
      if (!median && medians_.count(key)) continue;
      if (median) medians_.insert(key);
      ms_[key] = r.GetAdjustedRealTime() * 1e3 / benchmark::GetTimeUnitMultiplier(r.time_unit);
    }
  }
  void print_ratios() const {
    std::printf("\nscene  tessref ms/frame  llvmpipe ms/frame  llvmpipe/tessref  llvmpipe rgba8-only ms\n");
    for (int i = 0; i < 2; ++i) {
      const auto t = ms_.find("BM_TessrefFrame/" + std::to_string(i));
      const auto l = ms_.find("BM_LlvmpipeFrame/" + std::to_string(i) + "/0");
      const auto l8 = ms_.find("BM_LlvmpipeFrame/" + std::to_string(i) + "/1");
      if (t == ms_.end()) continue;
      char light[32] = "n/a";
      if (l8 != ms_.end()) std::snprintf(light, sizeof light, "%.1f", l8->second);
      if (l == ms_.end()) {
        std::printf("%-5s  %16.1f  %17s  %16s  %22s\n", kSceneNames[i], t->second, "n/a", "n/a", light);
        continue;
      }
      std::printf("%-5s  %16.1f  %17.1f  %15.2fx  %22s\n", kSceneNames[i], t->second, l->second,
                  l->second / t->second, light);
    }
  }

 private:
  std::map<std::string, double> ms_;
  std::set<std::string> medians_;
};

}  // namespace

int main(int argc, char** argv) { return tessref::bench::run_benchmarks<RatioReporter>(argc, argv); }
