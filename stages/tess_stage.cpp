// The tessellation executor: TCS -> primitive generator -> TES per patch, over fixed patch batches.
#include "stages/tess_stage.h"

#include <algorithm>
#include <chrono>
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

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// What one task (a fixed batch of patches) produces; concatenated in task order afterwards.
struct TaskResult {
  // Triangles as indices into `evaluated` (each domain point once): expanded straight into the
  // output batch afterwards, so the large triangle stream is written once.
  std::vector<ClipVertex> evaluated;
  std::vector<std::uint32_t> triangles;
  std::vector<ClipVertex> lines;
  std::vector<ClipVertex> points;
  std::vector<TessDumpRecord> dump;
  TessStats stats;
};

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

void run_task(const TessDrawInput& input, std::size_t first, std::size_t last,
              const TessControlProgram& tcs, const TessEvalProgram& tes, const TessLayout& layout,
              const TessOptions& options, TaskResult& result) {
  Patch in;
  PatchOutput tcs_out;
  TessDomainPoints domain;
  const int n_out = tcs.output_vertices();
  const int n_phases = tcs.phases();
  for (std::size_t p = first; p < last; ++p) {
    ++result.stats.patches_in;
    if (!gather_patch(input, p, in)) {
      ++result.stats.patches_invalid;
      continue;
    }
    // TCS: every invocation finishes phase k before any starts phase k + 1 (barrier()).
    auto t0 = Clock::now();
    tcs_out = PatchOutput{};
    tcs_out.vertex_count = n_out;
    for (int phase = 0; phase < n_phases; ++phase)
      for (int id = 0; id < n_out; ++id) tcs.run(phase, id, in, tcs_out);
    result.stats.tcs_seconds += seconds_since(t0);

    t0 = Clock::now();
    generate_tessellation(layout, tcs_out.levels, options.profile, domain);
    result.stats.tpg_seconds += seconds_since(t0);
    if (domain.discarded) {
      ++result.stats.patches_discarded;
      continue;
    }

    // TES: once per unique domain point, in generation order.
    t0 = Clock::now();
    const std::size_t first_point = result.evaluated.size();
    result.evaluated.resize(first_point + domain.coords.size());
    ClipVertex* evaluated = result.evaluated.data() + first_point;
    for (std::size_t i = 0; i < domain.coords.size(); ++i)
      evaluated[i] = tes.evaluate(domain.coords[i], tcs_out, in.primitive_id);
    result.stats.tes_seconds += seconds_since(t0);
    result.stats.domain_points += domain.coords.size();

    if (options.dump) {
      for (std::size_t i = 0; i < domain.coords.size(); ++i) {
        const auto& vy = evaluated[i].varyings;
        result.dump.push_back(TessDumpRecord{
            std::uint32_t(p), domain.coords[i],
            glm::vec3(vy[kVaryingPosition], vy[kVaryingPosition + 1], vy[kVaryingPosition + 2]),
            glm::vec3(vy[kVaryingNormal], vy[kVaryingNormal + 1], vy[kVaryingNormal + 2])});
      }
    }

    // Primitive assembly in the generator's emission order.
    const std::size_t prims = domain.primitive_count();
    const std::size_t used = prims * std::size_t(domain.vertices_per_primitive);
    if (domain.vertices_per_primitive == 3) {
      result.stats.triangles_out += prims;
      for (std::size_t i = 0; i < used; ++i)
        result.triangles.push_back(std::uint32_t(first_point + domain.indices[i]));
      continue;
    }
    std::vector<ClipVertex>* sink = nullptr;
    if (domain.vertices_per_primitive == 2) {
      result.stats.lines_out += prims;
      sink = options.lines ? &result.lines : nullptr;
    } else {
      result.stats.points_out += prims;
      sink = options.points ? &result.points : nullptr;
    }
    if (sink) {
      const std::size_t base = sink->size();
      sink->resize(base + used);  // geometric growth; the task's buffers are reused across chunks
      ClipVertex* dst = sink->data() + base;
      for (std::size_t i = 0; i < used; ++i) dst[i] = evaluated[domain.indices[i]];
    }
  }
}

void validate(const TessDrawInput& input, const TessControlProgram& tcs,
              const TessEvalProgram& tes) {
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

void clear(TaskResult& r) {
  r.evaluated.clear();
  r.triangles.clear();
  r.lines.clear();
  r.points.clear();
  r.dump.clear();
  r.stats = TessStats{};
}

// The body of tessellate(); `results` keeps the tasks' buffers (capacity only) between calls.
TessStats tessellate_range(const TessDrawInput& input, std::size_t first_patch,
                           std::size_t last_patch, const TessControlProgram& tcs,
                           const TessEvalProgram& tes, const TessOptions& options,
                           const Parallel& parallel, TriangleBatch& out,
                           std::vector<TaskResult>& results) {
  out.num_varyings = tes.num_varyings();
  last_patch = std::min(last_patch, input.patch_count());
  if (first_patch >= last_patch) return TessStats{};

  const TessLayout layout = tes.layout();
  const std::size_t grain = std::max<std::size_t>(1, options.patches_per_task);
  const std::size_t n = last_patch - first_patch;
  const std::size_t tasks = (n + grain - 1) / grain;
  if (results.size() < tasks) results.resize(tasks);  // one preassigned slot per task
  for (std::size_t t = 0; t < tasks; ++t) clear(results[t]);
  parallel.for_each(tasks, [&](std::size_t t) {
    const std::size_t a = first_patch + t * grain;
    run_task(input, a, std::min(a + grain, last_patch), tcs, tes, layout, options, results[t]);
  });

  // Concatenate in patch order: each task expands its triangles into its own range of out.
  std::vector<std::size_t> offset(tasks + 1, out.vertices.size());
  for (std::size_t t = 0; t < tasks; ++t) offset[t + 1] = offset[t] + results[t].triangles.size();
  out.vertices.resize(offset[tasks]);
  parallel.for_each(tasks, [&](std::size_t t) {
    const TaskResult& r = results[t];
    ClipVertex* dst = out.vertices.data() + offset[t];
    for (std::size_t i = 0; i < r.triangles.size(); ++i) dst[i] = r.evaluated[r.triangles[i]];
  });
  TessStats stats;
  for (std::size_t t = 0; t < tasks; ++t) {
    const TaskResult& r = results[t];
    if (options.lines) append(*options.lines, r.lines);
    if (options.points) append(*options.points, r.points);
    if (options.dump) append(*options.dump, r.dump);
    stats += r.stats;
  }
  return stats;
}

}  // namespace

TessStats tessellate(const TessDrawInput& input, std::size_t first_patch, std::size_t last_patch,
                     const TessControlProgram& tcs, const TessEvalProgram& tes,
                     const TessOptions& options, const Parallel& parallel, TriangleBatch& out) {
  validate(input, tcs, tes);
  std::vector<TaskResult> results;
  return tessellate_range(input, first_patch, last_patch, tcs, tes, options, parallel, out,
                          results);
}

TessStats tessellate_chunks(const TessDrawInput& input, std::size_t chunk_patches,
                            const TessControlProgram& tcs, const TessEvalProgram& tes,
                            const TessOptions& options, const Parallel& parallel,
                            const std::function<void(const TriangleBatch&)>& consume) {
  validate(input, tcs, tes);
  const std::size_t total = input.patch_count();
  const std::size_t chunk = std::max<std::size_t>(1, chunk_patches);
  TessStats stats;
  TriangleBatch batch;                // reused: its capacity stays at about one chunk
  std::vector<TaskResult> results;    // likewise the tasks' buffers
  for (std::size_t first = 0; first < total; first += chunk) {
    batch.vertices.clear();
    stats += tessellate_range(input, first, std::min(first + chunk, total), tcs, tes, options,
                              parallel, batch, results);
    consume(batch);
  }
  return stats;
}

}  // namespace tessref
