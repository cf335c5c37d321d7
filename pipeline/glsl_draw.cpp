#include "pipeline/glsl_draw.h"

#include <chrono>
#include <stdexcept>

namespace tessref {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Patches per tessellated chunk: bounds the memory of one chunk's triangles.
constexpr std::size_t kChunkPatches = 256;

}  // namespace

DrawStats draw_glsl_patches(const glsl::GlslProgram& program,
                            const std::vector<glsl::VertexAttribute>& attributes,
                            const GlslDrawCall& call, const RasterState& raster_state,
                            Framebuffer& fb, const Parallel& parallel,
                            const TessOptions& tess_options) {
  if (!program.has_tes())
    throw std::invalid_argument("draw: GL_PATCHES needs a tessellation evaluation shader");
  if (call.patch_vertices < 1 || call.patch_vertices > kMaxPatchVertices)
    throw std::invalid_argument("draw: GL_PATCH_VERTICES must be 1.." + std::to_string(kMaxPatchVertices));
  // Atomic counters: one thread, so that the counts each invocation sees are the same every run.
  const Parallel serial(1);
  const Parallel& par = program.uses_atomic_counters() ? serial : parallel;
  DrawStats stats;
  const auto tcs = program.control(call.patch_vertices, call.default_outer, call.default_inner);
  const auto tes = program.evaluation();
  const auto fs = program.fragment();
  std::vector<StageVertex> shaded(call.count);
  for (int instance = 0; instance < call.instances; ++instance) {
    auto t0 = Clock::now();
    program.run_vertices(attributes, call.first, call.count, instance, shaded.data(), par);
    stats.vertices_shaded += call.count;
    stats.vertex_seconds += seconds_since(t0);

    t0 = Clock::now();
    double raster_seconds = 0.0;
    const TessDrawInput input{shaded, {}, call.patch_vertices};
    stats.triangles_in += input.patch_count();
    stats.tess += tessellate_chunks(input, kChunkPatches, *tcs, *tes, tess_options, par,
                                    [&](const TriangleBatch& batch) {
                                      const auto r0 = Clock::now();
                                      stats.triangles_generated += batch.triangle_count();
                                      stats.raster += draw_triangles(batch, raster_state, *fs, fb, par);
                                      raster_seconds += seconds_since(r0);
                                    });
    stats.raster_seconds += raster_seconds;
    stats.tessellation_seconds += seconds_since(t0) - raster_seconds;
  }
  return stats;
}

}  // namespace tessref
