#include "render/draw.h"

#include <algorithm>
#include <chrono>

#include "common/error.h"
#include "render/builtin_programs.h"
#include "check/check.h"
#include "mesh/vertex_tags.h"
#include "stages/schemes/flat.h"
#include "stages/schemes/pn_triangles.h"
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


// Triangles per tessellated chunk (64 bytes per vertex: ~25 MB) and per parallel task.
constexpr std::size_t kChunkTriangles = 1 << 17;
constexpr std::size_t kTaskTriangles = 1 << 12;

// The tessellation path: each mesh triangle is a 3-vertex patch whose control points are the
// vertex shader's outputs; TCS -> TPG -> TES run chunk by chunk, each chunk rasterized before the
// next is made, so memory stays bounded by the chunk whatever the level.
template <typename Rasterize>
void draw_tessellated(const std::vector<programs::VertexOut>& shaded, const Mesh& mesh,
                      const programs::TransformVertexShader& vs,
                      const TessellationSettings& settings, const Framebuffer& fb,
                      const Parallel& parallel, const DrawOptions& options, Rasterize& rasterize,
                      DrawStats& stats) {
  auto t0 = Clock::now();
  std::vector<StageVertex> control_points = tess_control_points(shaded);
  if (settings.scheme == SurfaceScheme::ScalarTaggedPN)
    attach_vertex_tags(control_points, load_vertex_tags(settings, mesh), vs.u_normal_matrix);
  stats.vertex_seconds += seconds_since(t0);

  const BuiltinTessPrograms programs =
      builtin_tess_programs(settings, vs, glm::vec2(float(fb.width), float(fb.height)));
  const TessControlProgram& tcs = programs.tcs();
  const TessEvalProgram& tes = programs.tes();

  // Chunks and tasks sized by triangles, not patches: at level 64 one patch makes ~6,000
  // triangles, at level 1 one. The estimate is the generator's count for the constant levels
  // (adaptive levels: the largest they can reach).
  TessLevels estimate_levels = settings.levels;
  if (settings.adaptive.enabled) {
    estimate_levels.outer.fill(programs.pn_tcs.levels.screen.max_level);
    estimate_levels.inner.fill(programs.pn_tcs.levels.screen.max_level);
  }
  const std::size_t per_patch = std::max<std::size_t>(
      1, make_pattern(tes.layout(), estimate_levels, TessProfile::llvmpipe(), settings.tessellator)
             ->points.primitive_count());
  const std::size_t chunk = options.tess_chunk_patches
                                ? options.tess_chunk_patches
                                : std::clamp<std::size_t>(kChunkTriangles / per_patch, 1, 4096);

  std::vector<TessDumpRecord> records;
  TessOptions tess_options;
  tess_options.patches_per_task = std::clamp<std::size_t>(kTaskTriangles / per_patch, 1, 64);
  tess_options.tessellator = settings.tessellator;
  if (options.wants_tess_records()) tess_options.dump = &records;
  if (options.check)
    tess_options.control_check = [&](std::size_t p, const PatchOutput& o) { options.check->control_output(p, o); };
  const TessDrawInput input{control_points, mesh.indices, 3};
  const std::size_t patches = input.patch_count();
  std::size_t done = 0;
  auto t1 = Clock::now();
  const double raster_before = stats.raster_seconds;
  const TessStats tess = tessellate_chunks(
      input, chunk, tcs, tes, tess_options, parallel,
      [&](const TriangleBatch& batch) {
        if (options.check)  // before the chunk is drawn: the TES offence comes first
          options.check->evaluation_outputs(records, batch, [&](std::uint32_t p, const glm::vec3& c) {
            return trace_evaluation(input, tcs, tes, tess_options, p, c);
          });
        rasterize(batch);
        options.hand_out_tess_chunk(records, batch);
        done = std::min(patches, done + chunk);
        if (options.progress) options.progress(double(done) / double(std::max<std::size_t>(1, patches)));
      });
  stats.tessellation_seconds += seconds_since(t1) - (stats.raster_seconds - raster_before);
  stats.tess = tess;
}

}  // namespace

BuiltinTessPrograms builtin_tess_programs(const TessellationSettings& settings,
                                          const programs::TransformVertexShader& vs,
                                          const glm::vec2& viewport) {
  TessLevelSettings levels;
  levels.constant = settings.levels;
  levels.adaptive = settings.adaptive.enabled;
  levels.screen.view_proj = vs.u_view_projection;
  levels.screen.viewport_pixels = viewport;
  levels.screen.pixels_per_segment = settings.adaptive.pixels_per_segment;

  BuiltinTessPrograms p;
  p.flat_tcs.levels = levels;
  p.flat_tes.tess_layout = TessLayout{TessDomain::Triangles, settings.spacing, settings.winding, false};
  p.flat_tes.view_proj = vs.u_view_projection;
  parse(to_string(settings.normal_mode), p.pn_tcs.normal_mode);  // same names, same order
  p.pn_tcs.levels = levels;
  p.pn_tes.normal_mode = p.pn_tcs.normal_mode;
  p.pn_tes.spacing = settings.spacing;
  p.pn_tes.winding = settings.winding;
  p.pn_tes.view_proj = vs.u_view_projection;
  for (QuadraticTcs* q : std::initializer_list<QuadraticTcs*>{&p.phong_tcs, &p.nlsa_tcs, &p.nagata_tcs}) {
    q->normal_mode = p.pn_tcs.normal_mode;
    q->levels = levels;
  }
  p.phong_tcs.alpha = settings.phong_alpha;
  p.nagata_tcs.eps = settings.nagata_eps;
  p.quadratic_tes.normal_mode = p.pn_tcs.normal_mode;
  p.quadratic_tes.spacing = settings.spacing;
  p.quadratic_tes.winding = settings.winding;
  p.quadratic_tes.view_proj = vs.u_view_projection;
  p.tagged_pn_tcs.pn = p.pn_tcs;
  p.scheme = settings.scheme;
  p.displaced.displacement = settings.displacement;
  p.displaced.view_proj = vs.u_view_projection;
  return p;
}

std::vector<StageVertex> tess_control_points(const std::vector<programs::VertexOut>& shaded) {
  std::vector<StageVertex> control_points(shaded.size());
  for (std::size_t v = 0; v < shaded.size(); ++v) {
    control_points[v].attr[kAttrPosition] = glm::vec4(shaded[v].v_world_position, 1.0f);
    control_points[v].attr[kAttrNormal] = glm::vec4(shaded[v].v_world_normal, 0.0f);
  }
  return control_points;
}

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
  std::unique_ptr<FragmentProgram> watched;  // --check: the fragment shader's outputs watched
  if (options.check) {
    for (std::size_t v = 0; v < shaded.size(); ++v) {
      options.check->vertex_output(v, "gl_Position", &shaded[v].gl_Position[0], 4, mesh.indices, 3);
      options.check->vertex_output(v, "v_world_position", &shaded[v].v_world_position[0], 3, mesh.indices, 3);
      options.check->vertex_output(v, "v_world_normal", &shaded[v].v_world_normal[0], 3, mesh.indices, 3);
    }
    watched = options.check->watch(fragment_shader);
  }
  const FragmentProgram& fs = watched ? *watched : fragment_shader;

  // Everything after the geometry stages goes through here, batch by batch, in order.
  auto rasterize = [&](const TriangleBatch& batch) {
    auto t = Clock::now();
    stats.triangles_generated += batch.triangle_count();
    stats.raster += draw_triangles(batch, raster_state, fs, fb, parallel);
    stats.raster_seconds += seconds_since(t);
    if (options.check) options.check->after_raster();
  };

  if (tessellation.enabled) {
    draw_tessellated(shaded, mesh, vertex_shader, tessellation, fb, parallel, options, rasterize,
                     stats);
    return stats;
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
      for (std::size_t k = begin; k < end; ++k)
        batch.vertices[k] = to_clip_vertex(shaded[mesh.indices[3 * first + k]]);
    });
    stats.vertex_seconds += seconds_since(t);
    rasterize(batch);
    if (options.progress) options.progress(double(first + count) / double(triangles));
  }
  return stats;
}

}  // namespace tessref
