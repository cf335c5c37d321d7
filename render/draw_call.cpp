#include "render/draw_call.h"

#include <chrono>
#include <stdexcept>

#include "check/check.h"

namespace tessref {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The rasterizer's entry for each primitive kind.
RasterStats draw_batch(const TriangleBatch& b, const RasterState& s, const FragmentProgram& fs,
                       Framebuffer& fb, const Parallel& p) {
  return draw_triangles(b, s, fs, fb, p);
}
RasterStats draw_batch(const LineBatch& b, const RasterState& s, const FragmentProgram& fs,
                       Framebuffer& fb, const Parallel& p) {
  return draw_lines(b, s, fs, fb, p);
}
RasterStats draw_batch(const PointBatch& b, const RasterState& s, const FragmentProgram& fs,
                       Framebuffer& fb, const Parallel& p) {
  return draw_points(b, s, fs, fb, p);
}

// DrawOptions::primitives: the batch's primitives, as the rasterizer receives them.
template <class Batch>
void hand_out_primitives(const DrawOptions& options, const Batch& b, int stream = 0) {
  if (!options.primitives || b.primitive_count() == 0) return;
  options.primitives(stream, Batch::kCorners, b.primitive_count(),
                     [&b](std::size_t p, int k) { return b.vertex_data(b.vertex_index(p, k)); });
}

// What the rasterizer draws of a batch the vertex or evaluation stage made: the batch itself, or
// what the geometry shader emits for it (gl_PrimitiveIDIn counting on from `primitive_id`).
template <class Batch>
RasterStats draw_stage_batch(const GeometryProgram* gs, const Batch& b, std::uint32_t& primitive_id,
                             const RasterState& s, const FragmentProgram& fs, Framebuffer& fb, const Parallel& p,
                             DrawStats& stats, const DrawOptions& options) {
  if (!gs) {
    if constexpr (Batch::kCorners > 3) {
      throw std::logic_error("draw: adjacency primitives without a geometry shader");  // refused above
    } else {
      stats.triangles_generated += b.primitive_count();
      hand_out_primitives(options, b);
      return draw_batch(b, s, fs, fb, p);
    }
  }
  GeometryOutput out;
  out.keep_streams = bool(options.primitives);
  run_geometry(*gs, b, primitive_id, p, out);
  primitive_id += std::uint32_t(b.primitive_count());
  RasterStats r;
  const auto draw = [&](const auto& emitted) {
    if (emitted.primitive_count() == 0) return;
    stats.triangles_generated += emitted.primitive_count();
    hand_out_primitives(options, emitted);
    r += draw_batch(emitted, s, fs, fb, p);
  };
  draw(out.triangles);
  draw(out.lines);
  draw(out.points);
  for (std::size_t s = 0; s < out.streams.size(); ++s) hand_out_primitives(options, out.streams[s], int(s) + 1);
  return r;
}

// Untessellated primitives: the vertex shader's gl_Position and outputs become the rasterizer's
// vertices.
template <class Batch>
void draw_primitive_list(const DrawProgram& program, const std::vector<StageVertex>& shaded,
                         const DrawCall& call, const RasterState& state, const FragmentProgram& fs,
                         Framebuffer& fb, const Parallel& parallel, DrawStats& stats, const DrawOptions& options,
                         int instance, const GeometryProgram* gs, std::uint32_t& primitive_id) {
  constexpr std::size_t kCorners = Batch::kCorners;
  const std::size_t corners = call.indices.empty() ? call.count : call.indices.size();
  const std::size_t primitives = corners / kCorners;
  Batch batch;
  batch.num_varyings = program.varyings();
  batch.flat_varyings = program.flat_varyings();
  const std::size_t records = std::size_t(batch.records());
  const std::size_t per_batch = std::max<std::size_t>(1, options.batch_triangles);
  for (std::size_t first = 0; first < primitives; first += per_batch) {
    const std::size_t n = std::min(per_batch, primitives - first);
    auto t = Clock::now();
    batch.vertices.assign(kCorners * n * records, ClipVertex{});
    for (std::size_t k = 0; k < kCorners * n; ++k) {
      const std::size_t at = kCorners * first + k;
      const std::size_t v = call.indices.empty() ? at : call.indices[at];
      if (v >= shaded.size()) throw std::invalid_argument("draw: index " + std::to_string(v) + " past the vertex arrays");
      program.rasterizer_vertex(shaded[v], batch.vertices.data() + k * records);
    }
    stats.vertex_seconds += seconds_since(t);
    t = Clock::now();
    if constexpr (kCorners == 3)
      if (options.untessellated_triangles) options.untessellated_triangles(batch);
    if constexpr (kCorners == 2)
      if (options.line_batch) options.line_batch(batch, nullptr, nullptr);
    if constexpr (kCorners == 1)
      if (options.point_batch) options.point_batch(batch, nullptr, nullptr);
    stats.raster += draw_stage_batch(gs, batch, primitive_id, state, fs, fb, parallel, stats, options);
    stats.raster_seconds += seconds_since(t);
    if (options.check) options.check->after_raster();
    if (options.progress)
      options.progress((double(instance) + double(first + n) / double(primitives)) / double(call.instances));
  }
}

// Isolines and point mode: the evaluated vertices the tessellator collected for this chunk.
template <class Batch>
void draw_tess_primitives(std::vector<ClipVertex>& vertices, const TessEvalProgram& tes,
                          const RasterState& state, const FragmentProgram& fs, Framebuffer& fb,
                          const Parallel& parallel, DrawStats& stats, const DrawOptions& options,
                          const std::vector<TessDumpRecord>& records, const std::vector<std::uint32_t>& emitted,
                          const GeometryProgram* gs, std::uint32_t& primitive_id) {
  if (vertices.empty()) return;
  Batch batch;
  batch.num_varyings = tes.num_varyings();
  batch.flat_varyings = tes.flat_varyings();
  batch.vertices.swap(vertices);
  if constexpr (Batch::kCorners == 2)
    if (options.line_batch) options.line_batch(batch, &records, &emitted);
  if constexpr (Batch::kCorners == 1)
    if (options.point_batch) options.point_batch(batch, &records, &emitted);
  stats.raster += draw_stage_batch(gs, batch, primitive_id, state, fs, fb, parallel, stats, options);
  batch.vertices.swap(vertices);
  vertices.clear();
}

}  // namespace

DrawStats run_draw(const DrawProgram& program, const std::vector<VertexAttribute>& attributes,
                   const DrawCall& call, const RasterState& gl_state, Framebuffer& fb,
                   const Parallel& parallel, const DrawOptions& options) {
  RasterState raster_state = gl_state;
  raster_state.distances = program.distance_varyings();
  if (options.raster_state) options.raster_state(raster_state);
  if (call.patches != program.has_tes())
    throw std::invalid_argument(call.patches
                                    ? "draw: GL_PATCHES needs a tessellation evaluation shader"
                                    : "draw: a program with tessellation shaders draws GL_PATCHES only");
  if (const std::string refusal = program.draw_refusal(); !refusal.empty())
    throw std::invalid_argument("draw: " + refusal);
  if (call.patches && (call.patch_vertices < 1 || call.patch_vertices > kMaxPatchVertices))
    throw std::invalid_argument("draw: GL_PATCH_VERTICES must be 1.." + std::to_string(kMaxPatchVertices));
  // Atomic counters: one thread, so that the values each invocation sees are the same every run.
  const Parallel serial(1);
  const Parallel& par = program.draws_serially() ? serial : parallel;
  const bool indexed = !call.indices.empty();
  const bool by_id = !call.vertex_ids.empty();
  const std::size_t shade_first = indexed || by_id ? 0 : call.first;
  const std::size_t shade_count = by_id ? call.vertex_ids.size() : indexed ? call.vertex_count : call.count;
  // Every shaded vertex is held at once (a StageVertex each), so a huge count against a few
  // vertices of data would end in std::bad_alloc, not in a message.
  if (shade_count > kMaxDrawVertices)
    throw std::invalid_argument("draw: " + std::to_string(shade_count) + " vertices to shade, more than tessref's limit of " +
                                std::to_string(kMaxDrawVertices) + " per draw (" +
                                std::to_string(kMaxDrawVertices * sizeof(StageVertex) >> 20) + " MiB of shaded vertices)");
  std::vector<VertexAttribute> instance_attributes;  // the draw's, then this instance's
  if (call.instance_attributes) instance_attributes = attributes;
  const std::vector<VertexAttribute>& vertex_attributes = call.instance_attributes ? instance_attributes : attributes;

  DrawStats stats;
  const auto tcs = call.patches ? program.control(call.patch_vertices, call.default_outer, call.default_inner) : nullptr;
  const auto tes = call.patches ? program.evaluation() : nullptr;
  const auto program_fs = program.fragment();
  const auto geometry = program.geometry();
  const GeometryProgram* gs = geometry.get();
  if (gs) {
    int given = call.corners;
    if (call.patches) {
      const TessLayout layout = tes->layout();
      given = layout.point_mode ? 1 : layout.domain == TessDomain::Isolines ? 2 : 3;
    }
    check_geometry_input(*gs, given);
  } else if (call.corners > 3) {
    throw std::invalid_argument("draw: adjacency primitives need a geometry shader (GL: GL_INVALID_OPERATION)");
  }
  if (options.fragment_program) options.fragment_program(*program_fs);
  // --check: the fragment shader's outputs watched (check/check.h).
  const auto watched = options.check ? options.check->watch(*program_fs) : nullptr;
  const FragmentProgram* fs = watched ? watched.get() : program_fs.get();
  std::vector<StageVertex> shaded(shade_count);
  std::vector<TessDumpRecord> records;
  TessOptions tess_options;
  const TessGrain grain = program.tess_grain();
  tess_options.patches_per_task = grain.task_patches;
  tess_options.tessellator = program.tessellator();
  tess_options.overlap_chunks = grain.overlap_chunks;
  std::vector<std::uint32_t> emitted;  // isolines and point mode, into records
  if (options.wants_tess_records()) tess_options.dump = &records;
  if (options.wants_emitted()) tess_options.dump_emitted = &emitted;
  // Isolines and point mode: the tessellator hands their vertices over here, chunk by chunk.
  std::vector<ClipVertex> lines, points;
  tess_options.lines = &lines;
  tess_options.points = &points;
  const TessDrawInput* check_input = nullptr;  // --check's control shader re-run: this instance's patches
  if (options.check)
    tess_options.control_check = [&](std::size_t p, const PatchOutput& o) {
      options.check->control_output(p, o, [&](std::size_t q, int lane) { return trace_control(*check_input, *tcs, q, lane); });
    };
  const std::size_t chunk = options.tess_chunk_patches ? options.tess_chunk_patches : grain.chunk_patches;
  const std::vector<CheckedOutput> checked = options.check ? program.checked_outputs() : std::vector<CheckedOutput>{};

  for (int instance = 0; instance < call.instances; ++instance) {
    auto t0 = Clock::now();
    std::uint32_t primitive_id = 0;  // gl_PrimitiveIDIn: counted per instance
    if (call.instance_attributes) {
      instance_attributes.resize(attributes.size());
      call.instance_attributes(instance, instance_attributes);
    }
    program.run_vertices(vertex_attributes, shade_first, shade_count, instance, shaded.data(), par,
                         by_id ? call.vertex_ids.data() : nullptr);
    stats.vertices_shaded += shade_count;
    stats.vertex_seconds += seconds_since(t0);
    if (options.check) {
      const Checker::VertexTrace trace = [&](std::size_t v) { return trace_vertex(program, vertex_attributes, v, instance); };
      for (std::size_t v = 0; v < shaded.size(); ++v)
        for (const CheckedOutput& o : checked)
          options.check->vertex_output(shade_first + v, o.name, &shaded[v].attr[o.slot][0], o.components, call.indices,
                                       call.patches ? call.patch_vertices : 3, trace);
    }
    if (!call.patches) {
      stats.triangles_in += (indexed ? call.indices.size() : call.count) / std::size_t(call.corners);
      switch (call.corners) {
        case 1: draw_primitive_list<PointBatch>(program, shaded, call, raster_state, *fs, fb, par, stats, options, instance, gs, primitive_id); break;
        case 6: draw_primitive_list<PrimitiveBatch<6>>(program, shaded, call, raster_state, *fs, fb, par, stats, options, instance, gs, primitive_id); break;
        case 4: draw_primitive_list<PrimitiveBatch<4>>(program, shaded, call, raster_state, *fs, fb, par, stats, options, instance, gs, primitive_id); break;
        case 2: draw_primitive_list<LineBatch>(program, shaded, call, raster_state, *fs, fb, par, stats, options, instance, gs, primitive_id); break;
        default: draw_primitive_list<TriangleBatch>(program, shaded, call, raster_state, *fs, fb, par, stats, options, instance, gs, primitive_id);
      }
      continue;
    }

    t0 = Clock::now();
    const double raster_before = stats.raster_seconds;
    const TessDrawInput input{shaded, call.indices, call.patch_vertices};
    check_input = &input;
    const std::size_t patches = input.patch_count();
    stats.triangles_in += patches;
    std::size_t done = 0;
    stats.tess += tessellate_chunks(input, chunk, *tcs, *tes, tess_options, par, [&](const TriangleBatch& batch) {
      if (options.check)  // before the chunk is drawn: the TES offence comes first
        options.check->evaluation_outputs(records, batch, [&](std::uint32_t p, const glm::vec3& c) {
          return trace_evaluation(input, *tcs, *tes, tess_options, p, c);
        });
      // The scene's patch ids from here on (the check above re-runs patches by their draw index).
      const std::uint32_t first_id = call.first_patch_id + std::uint32_t(instance) * std::uint32_t(patches);
      if (first_id)
        for (TessDumpRecord& r : records) r.patch_id += first_id;
      const auto r0 = Clock::now();
      stats.raster += draw_stage_batch(gs, batch, primitive_id, raster_state, *fs, fb, par, stats, options);
      draw_tess_primitives<LineBatch>(lines, *tes, raster_state, *fs, fb, par, stats, options, records, emitted, gs, primitive_id);
      draw_tess_primitives<PointBatch>(points, *tes, raster_state, *fs, fb, par, stats, options, records, emitted, gs, primitive_id);
      stats.raster_seconds += seconds_since(r0);
      if (options.check) options.check->after_raster();
      options.hand_out_tess_chunk(records, batch, &emitted);
      done = std::min(patches, done + chunk);
      if (options.progress)
        options.progress((double(instance) + double(done) / double(std::max<std::size_t>(1, patches))) /
                         double(call.instances));
    });
    stats.tessellation_seconds += seconds_since(t0) - (stats.raster_seconds - raster_before);
  }
  return stats;
}

}  // namespace tessref
