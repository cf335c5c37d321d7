#include "pipeline/draw.h"

#include <algorithm>
#include <chrono>

#include "common/error.h"
#include "stages/tess_stage.h"

namespace tessref {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Runs fn(begin, end) over [0, n) in fixed chunks: results go to preassigned slots, so the
// split never shows in them.
template <typename Fn>
void for_chunks(const Parallel& parallel, std::size_t n, std::size_t chunk, Fn&& fn) {
  parallel.for_each((n + chunk - 1) / chunk, [&](std::size_t c) {
    fn(c * chunk, std::min(n, (c + 1) * chunk));
  });
}

ClipVertex to_clip_vertex(const programs::VertexOut& v) {
  ClipVertex out;
  out.position = v.gl_Position;
  for (int c = 0; c < 3; ++c) {
    out.varyings[kVaryingPosition + c] = v.v_world_position[c];
    out.varyings[kVaryingNormal + c] = v.v_world_normal[c];
  }
  return out;
}

}  // namespace

DrawStats draw_mesh(const Mesh& mesh, const programs::TransformVertexShader& vertex_shader,
                    const TessellationSettings& tessellation, const RasterState& raster_state,
                    const FragmentProgram& fragment_shader, Framebuffer& fb,
                    const Parallel& parallel, const DrawOptions& options) {
  DrawStats stats;
  stats.triangles_in = mesh.triangle_count();

  // Vertex shader: one output slot per mesh vertex.
  auto t0 = Clock::now();
  std::vector<programs::VertexOut> shaded(mesh.vertex_count());
  for_chunks(parallel, shaded.size(), 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      shaded[v] = vertex_shader.main(mesh.positions[v], mesh.normals[v]);
  });
  stats.vertices_shaded = shaded.size();
  stats.vertex_seconds += seconds_since(t0);

  // Everything after the geometry stages goes through here, batch by batch, in order.
  auto rasterize = [&](const TriangleBatch& batch) {
    auto t = Clock::now();
    stats.triangles_generated += batch.triangle_count();
    stats.raster += draw_triangles(batch, raster_state, fragment_shader, fb, parallel);
    stats.raster_seconds += seconds_since(t);
  };

  if (tessellation.enabled) {
    // ---- Tessellation path -------------------------------------------------------------------
    // Each mesh triangle is a 3-vertex patch (TessDrawInput: mesh.indices, patch_vertices 3)
    // whose control points are `shaded` as StageVertex (attr[kAttrPosition] = (world position,
    // 1), attr[kAttrNormal] = (world normal, 0)). tessellate_chunks (stages/tess_stage.h) runs
    // TCS -> TPG -> TES chunk by chunk and hands each chunk's batch to `rasterize`, in patch
    // order; its time minus the rasterizer's goes to stats.tessellation_seconds.
    throw InputError(
        "tessellation is not implemented yet: the scene has tessellation.enabled = true "
        "(render with --set tessellation.enabled=false)");
  }

  // ---- Primitive assembly: the mesh's triangles in order, in bounded batches ----------------
  const std::size_t triangles = mesh.triangle_count();
  const std::size_t per_batch = std::max<std::size_t>(1, options.batch_triangles);
  TriangleBatch batch;
  batch.num_varyings = kBuiltinVaryings;
  for (std::size_t first = 0; first < triangles; first += per_batch) {
    auto t = Clock::now();
    const std::size_t count = std::min(per_batch, triangles - first);
    batch.vertices.resize(3 * count);
    for_chunks(parallel, 3 * count, 3 * 4096, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) batch.vertices[k] = to_clip_vertex(shaded[mesh.indices[3 * first + k]]);
    });
    stats.vertex_seconds += seconds_since(t);
    rasterize(batch);
    if (options.progress) options.progress(double(first + count) / double(triangles));
  }
  return stats;
}

}  // namespace tessref
