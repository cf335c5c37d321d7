// The tessellation executor: TCS -> primitive generator -> TES per patch, over fixed patch batches.
#include "stages/tess_stage.h"
#include "stages/vertex_store.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tessref {

std::size_t TessDrawInput::patch_count() const {
  if (patch_vertices <= 0) return 0;
  const std::size_t n = indices.empty() ? vertices.size() : indices.size();
  return n / std::size_t(patch_vertices);
}

TessStats& TessStats::operator+=(const TessStats& o) {
  patches_in += o.patches_in;
  patches_discarded += o.patches_discarded;
  patches_invalid += o.patches_invalid;
  domain_points += o.domain_points;
  triangles_out += o.triangles_out;
  lines_out += o.lines_out;
  points_out += o.points_out;
  tcs_seconds += o.tcs_seconds;
  tpg_seconds += o.tpg_seconds;
  tes_seconds += o.tes_seconds;
  return *this;
}

glm::vec3 safe_normalize(const glm::vec3& v) {
  const float len2 = glm::dot(v, v);
  // Zero, denormal-underflowed, infinite or NaN length: no direction to keep.
  if (!(len2 > 0.0f) || !std::isfinite(len2)) return glm::vec3(0.0f);
  return v / std::sqrt(len2);
}

void TessControlProgram::run_phase(int phase, const Patch& in, PatchOutput& out) const {
  for (int id = 0; id < output_vertices(); ++id) run(phase, id, in, out);
}

void TessControlProgram::run_patches(const Patch* const* in, PatchOutput* const* out, int count) const {
  for (int k = 0; k < count; ++k)
    for (int phase = 0; phase < phases(); ++phase) run_phase(phase, *in[k], *out[k]);
}

void TessEvalProgram::evaluate_batch(const PatchOutput& patch, int primitive_id,
                                     TessEvalBatch& batch) const {
  const int nv = num_varyings();
  for (int i = 0; i < batch.count; ++i) {
    const glm::vec3 tc(batch.tess_coord[0][i], batch.tess_coord[1][i], batch.tess_coord[2][i]);
    const ClipVertex v = evaluate(tc, patch, primitive_id);
    for (int c = 0; c < 4; ++c) batch.position[c][i] = v.position[c];
    for (int k = 0; k < nv; ++k) batch.varyings[k][i] = v.varyings[k];
  }
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// One patch of the range after the control stage: its generated pattern (null when the patch is
// invalid or discarded) and, for triangle layouts, where its vertices and indices go in the
// output batch.
struct PatchSlot {
  std::shared_ptr<const TessPattern> pattern;
  std::size_t first_vertex = 0;
  std::size_t first_index = 0;
  bool gathered = false;  // its vertices were in the buffer: the control shader ran
};

// What one task (a fixed batch of patches) keeps; reused from range to range.
struct TaskScratch {
  std::vector<ClipVertex> evaluated;  // isolines and points only: the patch's vertices
  std::vector<ClipVertex> lines;
  std::vector<ClipVertex> points;
  std::vector<TessDumpRecord> dump;
  std::vector<std::uint32_t> dump_emitted;  // into dump
  TessStats stats;
  std::vector<Patch> patches;  // gl_in[] of up to kControlBatch patches for one run_patches
  // The last lookup: neighbouring patches usually share their levels.
  TessLevels memo_levels;
  std::shared_ptr<const TessPattern> memo;
};

struct ExecutorScratch {
  std::vector<PatchOutput> outputs;  // per patch of the range: the TCS output, the TES input
  std::vector<PatchSlot> slots;
  std::vector<TaskScratch> tasks;
};

bool same_levels(const TessLevels& a, const TessLevels& b) {
  return std::memcmp(a.outer.data(), b.outer.data(), sizeof(a.outer)) == 0 &&
         std::memcmp(a.inner.data(), b.inner.data(), sizeof(a.inner)) == 0;
}

// Gathers gl_in[] for one patch; false if an index falls outside the vertex buffer.
bool gather_patch(const TessDrawInput& input, std::size_t p, Patch& patch) {
  const std::size_t base = p * std::size_t(input.patch_vertices);
  patch.vertex_count = input.patch_vertices;
  patch.primitive_id = int(p);
  for (int k = 0; k < input.patch_vertices; ++k) {
    const std::size_t v = input.indices.empty() ? base + k : std::size_t(input.indices[base + k]);
    if (v >= input.vertices.size()) return false;
    patch.vertices[k] = input.vertices[v];
  }
  return true;
}

// Control stage and primitive generation for patches [first, last) of the range starting at
// range_first: fills their slots and TCS outputs. The control program runs kControlBatch valid
// patches at a time (run_patches), in patch order.
void control_task(const TessDrawInput& input, std::size_t range_first, std::size_t first,
                  std::size_t last, const TessControlProgram& tcs, const TessLayout& layout,
                  const TessOptions& options, TessPatternCache& cache, ExecutorScratch& ex,
                  TaskScratch& task) {
  const int n_out = tcs.output_vertices();
  task.patches.resize(kControlBatch);
  const Patch* in[kControlBatch];
  PatchOutput* out[kControlBatch];
  std::size_t index[kControlBatch];
  for (std::size_t p = first; p < last;) {
    // Gather up to kControlBatch valid patches; invalid ones get no pattern and are counted.
    int count = 0;
    for (; p < last && count < kControlBatch; ++p) {
      PatchSlot& slot = ex.slots[p - range_first];
      slot.pattern.reset();
      ++task.stats.patches_in;
      Patch& patch = task.patches[std::size_t(count)];
      slot.gathered = gather_patch(input, p, patch);
      if (!slot.gathered) {
        ++task.stats.patches_invalid;
        continue;
      }
      // Outputs an invocation does not write read as zero.
      PatchOutput& o = ex.outputs[p - range_first];
      for (int v = 0; v < n_out; ++v) o.vertices[v] = StageVertex{};
      o.patch = {};
      o.levels = TessLevels{};
      o.vertex_count = n_out;
      in[count] = &patch;
      out[count] = &o;
      index[count] = p;
      ++count;
    }
    // TCS: every invocation finishes phase k before any starts phase k + 1 (barrier()).
    auto t0 = Clock::now();
    tcs.run_patches(in, out, count);
    task.stats.tcs_seconds += seconds_since(t0);

    t0 = Clock::now();
    for (int k = 0; k < count; ++k) {
      if (!task.memo || !same_levels(task.memo_levels, out[k]->levels)) {
        task.memo = cache.get(layout, out[k]->levels, options.profile, options.tessellator);
        task.memo_levels = out[k]->levels;
      }
      if (task.memo->points.discarded) {
        ++task.stats.patches_discarded;
        continue;
      }
      ex.slots[index[k] - range_first].pattern = task.memo;
    }
    task.stats.tpg_seconds += seconds_since(t0);
  }
}

// Evaluates the TES over one patch's pattern into dst (vertex_records(num_varyings) ClipVertex
// records per domain point).
void evaluate_patch(const TessEvalProgram& tes, const PatchOutput& patch, int primitive_id,
                    const TessPattern& pattern, int num_varyings, ClipVertex* dst) {
  TessEvalBatch batch;
  // The batch's rows in the vertex's memory order; varyings the program does not write (and the
  // last record's padding) are stored as 0.
  static const float zeros[kTessEvalBatch] = {};
  const int records = vertex_records(num_varyings);
  const int floats = 16 * records;
  const float* rows[16 * vertex_records(kMaxVaryings)];
  for (int c = 0; c < 4; ++c) rows[c] = batch.position[c];
  for (int k = 0; k + 4 < floats; ++k) rows[4 + k] = k < num_varyings ? batch.varyings[k] : zeros;
  const StoreVerticesKernel store = store_vertices_kernel();
  const std::size_t n = pattern.points.coords.size();
  for (std::size_t start = 0; start < n; start += kTessEvalBatch) {
    batch.count = int(std::min<std::size_t>(kTessEvalBatch, n - start));
    for (int c = 0; c < 3; ++c) batch.tess_coord[c] = pattern.coord[c].data() + start;
    tes.evaluate_batch(patch, primitive_id, batch);
    float* out = reinterpret_cast<float*>(dst + start * std::size_t(records));
    if (records == 1) {  // the common case, one 64-byte record: the SIMD kernel
      store(rows, batch.count, out);
      continue;
    }
    for (int i = 0; i < batch.count; ++i)
      for (int c = 0; c < floats; ++c) out[std::size_t(floats) * i + c] = rows[c][i];
  }
}

void append_dump(std::uint32_t patch_id, const TessPattern& pattern, const ClipVertex* v,
                 int records, std::array<int, 2> at, std::vector<TessDumpRecord>& dump) {
  for (std::size_t i = 0; i < pattern.points.coords.size(); ++i) {
    const float* pos = reinterpret_cast<const float*>(v + i * std::size_t(records));
    const float* vy = pos + 4;
    dump.push_back(TessDumpRecord{patch_id, pattern.points.coords[i],
                                  glm::vec3(vy[at[0]], vy[at[0] + 1], vy[at[0] + 2]),
                                  glm::vec3(vy[at[1]], vy[at[1] + 1], vy[at[1] + 2]),
                                  glm::vec4(pos[0], pos[1], pos[2], pos[3])});
  }
}

// Evaluation stage for patches [first, last): triangles straight into out at their slots'
// offsets; isolines and points into the task's own buffers.
void evaluate_task(std::size_t range_first, std::size_t first, std::size_t last,
                   const TessEvalProgram& tes, const TessOptions& options,
                   ExecutorScratch& ex, TaskScratch& task, TriangleBatch& out) {
  const int nv = std::clamp(tes.num_varyings(), 0, kMaxVaryings);
  const std::size_t records = std::size_t(vertex_records(nv));
  // Varyings past the program's count read as the zeros the store writes, within the records.
  std::array<int, 2> dump_at = tes.dump_varyings();
  for (int& at : dump_at) at = std::clamp(at, 0, int(16 * records) - 4 - 3);
  for (std::size_t p = first; p < last; ++p) {
    const PatchSlot& slot = ex.slots[p - range_first];
    if (!slot.pattern) continue;
    const TessPattern& pattern = *slot.pattern;
    const TessDomainPoints& domain = pattern.points;
    const PatchOutput& patch = ex.outputs[p - range_first];
    const std::size_t n = domain.coords.size();

    auto t0 = Clock::now();
    ClipVertex* evaluated = nullptr;
    if (domain.vertices_per_primitive == 3) {
      evaluated = out.vertices.data() + slot.first_vertex * records;
    } else {
      task.evaluated.resize(n * records);
      evaluated = task.evaluated.data();
    }
    evaluate_patch(tes, patch, int(p), pattern, nv, evaluated);
    task.stats.tes_seconds += seconds_since(t0);
    task.stats.domain_points += n;
    const auto dump_base = std::uint32_t(task.dump.size());
    if (options.dump)
      append_dump(std::uint32_t(p), pattern, evaluated, int(records), dump_at, task.dump);

    // Primitive assembly in the generator's emission order.
    const std::size_t prims = domain.primitive_count();
    const std::size_t used = prims * std::size_t(domain.vertices_per_primitive);
    if (domain.vertices_per_primitive == 3) {
      task.stats.triangles_out += prims;
      std::uint32_t* dst = out.indices.data() + slot.first_index;
      const auto base = std::uint32_t(slot.first_vertex);
      for (std::size_t i = 0; i < used; ++i) dst[i] = base + domain.indices[i];
      continue;
    }
    if (options.dump && options.dump_emitted)
      for (std::size_t i = 0; i < used; ++i) task.dump_emitted.push_back(dump_base + domain.indices[i]);
    std::vector<ClipVertex>* sink = nullptr;
    if (domain.vertices_per_primitive == 2) {
      task.stats.lines_out += prims;
      sink = options.lines ? &task.lines : nullptr;
    } else {
      task.stats.points_out += prims;
      sink = options.points ? &task.points : nullptr;
    }
    if (sink) {
      const std::size_t base = sink->size();
      sink->resize(base + used * records);  // geometric growth; the task's buffers are reused
      ClipVertex* dst = sink->data() + base;
      // Each vertex with all its records (LineBatch / PointBatch layout).
      for (std::size_t i = 0; i < used; ++i)
        std::copy_n(evaluated + domain.indices[i] * records, records, dst + i * records);
    }
  }
}

void validate(const TessDrawInput& input, const TessControlProgram& tcs,
              const TessEvalProgram& tes, const TessOptions& options) {
  // Checked here, before any task runs, rather than in a worker generating the pattern.
  if (options.tessellator != Tessellator::PrimitiveGenerator && tes.layout().domain != TessDomain::Triangles)
    throw std::invalid_argument(std::string("tessellate: ") + to_string(options.tessellator) +
                                " tessellation needs the triangles domain, the TES has " +
                                to_string(tes.layout().domain));
  if (input.patch_vertices < 1 || input.patch_vertices > kMaxPatchVertices)
    throw std::invalid_argument("tessellate: patch_vertices " +
                                std::to_string(input.patch_vertices) + " outside 1.." +
                                std::to_string(kMaxPatchVertices));
  const int n_out = tcs.output_vertices();
  if (n_out < 1 || n_out > kMaxPatchVertices)
    throw std::invalid_argument("tessellate: TCS output_vertices " + std::to_string(n_out) +
                                " outside 1.." + std::to_string(kMaxPatchVertices));
  if (tcs.phases() < 1) throw std::invalid_argument("tessellate: TCS phases() < 1");
  if (tes.num_varyings() < 0 || tes.num_varyings() > kMaxVaryings)
    throw std::invalid_argument("tessellate: TES num_varyings " +
                                std::to_string(tes.num_varyings()) + " outside 0.." +
                                std::to_string(kMaxVaryings));
}

template <class T>
void append(std::vector<T>& dst, const std::vector<T>& src) {
  dst.insert(dst.end(), src.begin(), src.end());
}

void clear(TaskScratch& t) {
  t.lines.clear();
  t.points.clear();
  t.dump.clear();
  t.dump_emitted.clear();
  t.stats = TessStats{};
}

// The body of tessellate(); `ex` keeps its buffers (capacity only) between calls.
TessStats tessellate_range(const TessDrawInput& input, std::size_t first_patch,
                           std::size_t last_patch, const TessControlProgram& tcs,
                           const TessEvalProgram& tes, const TessOptions& options,
                           const Parallel& parallel, TriangleBatch& out, ExecutorScratch& ex,
                           bool overwrite = false) {
  // overwrite: out holds a previous chunk, to be replaced; its memory is written over rather than
  // cleared and constructed again (64 bytes per vertex and 4 per index saved).
  if (overwrite) out.indexed = true;
  out.num_varyings = tes.num_varyings();
  out.flat_varyings = tes.flat_varyings();
  const std::size_t records = std::size_t(out.records());
  if (!out.indexed) {  // earlier contents as consecutive triples: index them as they are
    out.indices.resize(out.vertex_count() / 3 * 3);
    for (std::size_t k = 0; k < out.indices.size(); ++k) out.indices[k] = std::uint32_t(k);
    out.vertices.resize(out.indices.size() * records);
    out.indexed = true;
  }
  const std::size_t first_vertex = overwrite ? 0 : out.vertex_count();
  const std::size_t first_index = overwrite ? 0 : out.indices.size();
  last_patch = std::min(last_patch, input.patch_count());
  if (first_patch >= last_patch) {
    out.vertices.resize(first_vertex * records);
    out.indices.resize(first_index);
    return TessStats{};
  }

  const TessLayout layout = tes.layout();
  TessPatternCache& cache = options.patterns ? *options.patterns : TessPatternCache::shared();
  const std::size_t grain = std::max<std::size_t>(1, options.patches_per_task);
  const std::size_t n = last_patch - first_patch;
  const std::size_t tasks = (n + grain - 1) / grain;
  if (ex.outputs.size() < n) ex.outputs.resize(n);
  if (ex.slots.size() < n) ex.slots.resize(n);
  if (ex.tasks.size() < tasks) ex.tasks.resize(tasks);  // one preassigned slot per task
  for (std::size_t t = 0; t < tasks; ++t) clear(ex.tasks[t]);
  auto task_range = [&](std::size_t t) {
    const std::size_t a = first_patch + t * grain;
    return std::pair{a, std::min(a + grain, last_patch)};
  };

  parallel.for_each(tasks, [&](std::size_t t) {
    const auto [a, b] = task_range(t);
    control_task(input, first_patch, a, b, tcs, layout, options, cache, ex, ex.tasks[t]);
  });
  if (options.control_check)  // once per range: nothing per patch without it
    for (std::size_t i = 0; i < n; ++i)
      if (ex.slots[i].gathered) options.control_check(first_patch + i, ex.outputs[i]);

  // Output ranges in patch order: the batch's bytes never depend on the split into tasks.
  std::size_t vertices = first_vertex, indices = first_index;
  for (std::size_t i = 0; i < n; ++i) {
    PatchSlot& slot = ex.slots[i];
    if (!slot.pattern || slot.pattern->points.vertices_per_primitive != 3) continue;
    slot.first_vertex = vertices;
    slot.first_index = indices;
    vertices += slot.pattern->points.coords.size();
    indices += slot.pattern->points.indices.size();
  }
  if (vertices > std::size_t(UINT32_MAX))
    throw std::length_error("tessellate: more than 2^32 vertices in one batch");
  out.vertices.resize(vertices * records);
  out.indices.resize(indices);

  parallel.for_each(tasks, [&](std::size_t t) {
    const auto [a, b] = task_range(t);
    evaluate_task(first_patch, a, b, tes, options, ex, ex.tasks[t], out);
  });

  TessStats stats;
  for (std::size_t t = 0; t < tasks; ++t) {
    const TaskScratch& r = ex.tasks[t];
    if (options.lines) append(*options.lines, r.lines);
    if (options.points) append(*options.points, r.points);
    if (options.dump && options.dump_emitted) {
      const auto base = std::uint32_t(options.dump->size());
      for (std::uint32_t i : r.dump_emitted) options.dump_emitted->push_back(base + i);
    }
    if (options.dump) append(*options.dump, r.dump);
    stats += r.stats;
  }
  return stats;
}

}  // namespace

TessStats tessellate(const TessDrawInput& input, std::size_t first_patch, std::size_t last_patch,
                     const TessControlProgram& tcs, const TessEvalProgram& tes,
                     const TessOptions& options, const Parallel& parallel, TriangleBatch& out) {
  validate(input, tcs, tes, options);
  ExecutorScratch scratch;
  return tessellate_range(input, first_patch, last_patch, tcs, tes, options, parallel, out,
                          scratch);
}

TessStats tessellate_chunks(const TessDrawInput& input, std::size_t chunk_patches,
                            const TessControlProgram& tcs, const TessEvalProgram& tes,
                            const TessOptions& options, const Parallel& parallel,
                            const std::function<void(const TriangleBatch&)>& consume) {
  validate(input, tcs, tes, options);
  const std::size_t total = input.patch_count();
  const std::size_t chunk = std::max<std::size_t>(1, chunk_patches);
  TessStats stats;
  // Two batches, reused (their capacity stays at about one chunk): while one chunk is consumed
  // (rasterized), the next is tessellated beside it, so that neither stage's last tasks leave
  // threads idle. Not when the consumer reads what tessellation writes besides the batch (the
  // dump records, the control check, isoline and point vertices).
  TriangleBatch batches[2];
  for (TriangleBatch& b : batches) b.indexed = true;
  const TessLayout layout = tes.layout();
  const bool overlap = options.overlap_chunks && parallel.threads() > 1 && !options.dump && !options.dump_emitted && !options.control_check &&
                       layout.domain != TessDomain::Isolines && !layout.point_mode;
  ExecutorScratch scratch;  // likewise the per-patch and per-task buffers
  auto tessellate_chunk = [&](std::size_t first, TriangleBatch& batch) {
    stats += tessellate_range(input, first, std::min(first + chunk, total), tcs, tes, options,
                              parallel, batch, scratch, /*overwrite=*/true);
  };
  if (total == 0) return stats;
  tessellate_chunk(0, batches[0]);
  for (std::size_t first = 0, k = 0; first < total; first += chunk, k ^= 1) {
    const std::size_t next = first + chunk;
    if (next < total && overlap)
      parallel.run_beside([&] { consume(batches[k]); }, [&] { tessellate_chunk(next, batches[k ^ 1]); });
    else {
      consume(batches[k]);
      if (next < total) tessellate_chunk(next, batches[k ^ 1]);
    }
  }
  return stats;
}

}  // namespace tessref
