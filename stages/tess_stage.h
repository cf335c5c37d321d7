#pragma once
// The programmable tessellation stages (TCS, TES) and the executor that runs
// TCS -> primitive generator -> TES over a range of patches, with GL 4.6 semantics (section 11.2).
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "raster/vertex.h"
#include "stages/tpg.h"
#include "stages/tpg_cache.h"

namespace tessref {

// Limits, at or above GL's minimums where GL names one (MAX_PATCH_VERTICES >= 32).
// gl_Position, 32 locations (GL 4.5's minimum MAX_TESS_CONTROL_INPUT_COMPONENTS, 128), then
// gl_ClipDistance[8] and gl_CullDistance[8] (two slots each) and gl_PointSize: vec4 slots in one
// stage's per-vertex out block.
inline constexpr int kMaxStageLocations = 32;
inline constexpr int kMaxStageAttributes = 1 + kMaxStageLocations + 5;
inline constexpr int kMaxPatchVertices = 32;    // GL_PATCH_VERTICES and layout(vertices = N)
// 'patch out' vec4 slots written by a TCS: GL 4.5's minimum MAX_TESS_PATCH_COMPONENTS, 120.
inline constexpr int kMaxPatchAttributes = 30;

// Attribute slots of the vertex shader output the pipeline hands to the TCS.
inline constexpr int kAttrPosition = 0;  // world position (xyz, 1)
inline constexpr int kAttrNormal = 1;    // world normal (xyz, 0), not necessarily unit length

// Varying slots every built-in TES writes; fragment shaders and --dump-tess read them.
inline constexpr int kVaryingPosition = 0;  // [0..2] world position
inline constexpr int kVaryingNormal = 3;    // [3..5] world normal (unit, or zero if degenerate)
inline constexpr int kBuiltinVaryings = 6;

// One vertex of a stage's out block (VS out, TCS gl_out[i]): fixed-size, like a GLSL block of
// vec4s; slots a program does not write stay zero.
struct StageVertex {
  std::array<glm::vec4, kMaxStageAttributes> attr{};
};

// TCS input: gl_in[0 .. vertex_count) gathered from the vertex buffer by index,
// gl_PatchVerticesIn = vertex_count, gl_PrimitiveID = primitive_id.
struct Patch {
  std::array<StageVertex, kMaxPatchVertices> vertices{};
  int vertex_count = 0;
  int primitive_id = 0;
};

// TCS output, shared by all invocations of one patch: gl_out[], the 'patch out' variables and
// gl_TessLevelOuter/Inner. Also the TES input (gl_in[] of the TES, gl_PatchVerticesIn = vertex_count).
struct PatchOutput {
  std::array<StageVertex, kMaxPatchVertices> vertices{};
  int vertex_count = 0;
  std::array<glm::vec4, kMaxPatchAttributes> patch{};
  TessLevels levels;  // raw: the generator clamps, rounds and discards
};

// A tessellation control shader. The executor runs output_vertices() invocations per patch.
//
// Barrier semantics: a program with k calls to barrier() has phases() == k + 1. The executor runs
// phase p of every invocation (gl_InvocationID 0..N-1) before phase p + 1 of any, so in phase p an
// invocation may read anything any invocation wrote in phases < p. As in GL, an invocation writes
// only its own gl_out[gl_InvocationID]; per-patch outputs and levels may be written by any; reading
// another invocation's output written in the *same* phase is undefined in GL (here invocations run
// in increasing gl_InvocationID order, but programs must not rely on that).
//
// Programs are shared by all threads: run() must be const and must not touch shared state.
class TessControlProgram {
 public:
  virtual ~TessControlProgram() = default;
  virtual int output_vertices() const = 0;  // layout(vertices = N), 1..kMaxPatchVertices
  virtual int phases() const { return 1; }
  virtual void run(int phase, int invocation_id, const Patch& in, PatchOutput& out) const = 0;
  // One phase of every invocation of the patch (gl_InvocationID 0..N-1): what the executor calls.
  // The default runs run() for each invocation in increasing order; a batched program (the GLSL
  // executor) overrides it to run all invocations together.
  virtual void run_phase(int phase, const Patch& in, PatchOutput& out) const;
  // Every phase of several patches: what the executor calls, with up to kControlBatch patches
  // whose outputs are zeroed. The default runs run_phase per patch, phase by phase; the GLSL
  // executor runs several patches in one batch.
  virtual void run_patches(const Patch* const* in, PatchOutput* const* out, int count) const;
};
inline constexpr int kControlBatch = 16;

// A batch of domain points of one patch for the TES, as structure of arrays: gl_TessCoord in,
// gl_Position and varyings out, point i in column i. The batch is at most kTessEvalBatch points.
inline constexpr int kTessEvalBatch = 256;
struct TessEvalBatch {
  int count = 0;
  const float* tess_coord[3] = {};  // gl_TessCoord.x, .y, .z: count values each
  alignas(32) float position[4][kTessEvalBatch];
  alignas(32) float varyings[kMaxVaryings][kTessEvalBatch];  // rows 0 .. num_varyings() - 1
};

// A tessellation evaluation shader: its input layout qualifiers and one invocation per domain
// point. evaluate() returns gl_Position and the varyings; built-in programs follow the varying
// convention above (kVaryingPosition, kVaryingNormal). Must be const and thread-safe.
class TessEvalProgram {
 public:
  virtual ~TessEvalProgram() = default;
  virtual TessLayout layout() const = 0;
  virtual int num_varyings() const { return kBuiltinVaryings; }  // <= kMaxVaryings
  // Varyings that are flat (TriangleBatch::flat_varyings).
  virtual VaryingMask flat_varyings() const { return {}; }
  // The first varyings of the world position and normal that --dump-tess records (TessDumpRecord).
  virtual std::array<int, 2> dump_varyings() const { return {kVaryingPosition, kVaryingNormal}; }
  // tess_coord: gl_TessCoord as generated (triangles: (u, v, w), u weighs gl_in[0], v gl_in[1],
  // w gl_in[2]; quads and isolines: (u, v, 0)).
  virtual ClipVertex evaluate(const glm::vec3& tess_coord, const PatchOutput& patch,
                              int primitive_id) const = 0;
  // What the executor calls: batch.count invocations at once. The default runs evaluate() per
  // point; an override (built-in programs over SIMD kernels, the GLSL executor) must write the
  // same bits as evaluate() would.
  virtual void evaluate_batch(const PatchOutput& patch, int primitive_id,
                              TessEvalBatch& batch) const;
};

// ---------------------------------------------------------------------------------------------
// Executor

// The draw's input: the vertex shader's outputs and the patch index list (GL_PATCHES).
// Patch p uses vertices indices[p * patch_vertices + k]; with no indices, vertex p * patch_vertices + k
// (glDrawArrays). gl_PrimitiveID of patch p is p (the draw's patch index, counted from 0).
struct TessDrawInput {
  std::span<const StageVertex> vertices;
  std::span<const std::uint32_t> indices;  // empty: non-indexed draw
  int patch_vertices = 3;                  // GL_PATCH_VERTICES, 1..kMaxPatchVertices
  std::size_t patch_count() const;
};

// One evaluated domain point, for --dump-tess: read from the TES varyings by the convention above.
struct TessDumpRecord {
  std::uint32_t patch_id = 0;  // gl_PrimitiveID
  glm::vec3 tess_coord{0.0f};
  glm::vec3 position{0.0f};    // varyings[0..2]
  glm::vec3 normal{0.0f};      // varyings[3..5]
  glm::vec4 clip{0.0f};        // gl_Position (not in the dump files)
};

struct TessStats {
  std::uint64_t patches_in = 0;
  std::uint64_t patches_discarded = 0;  // by the generator (outer level <= 0 or NaN)
  std::uint64_t patches_invalid = 0;    // an index past the vertex buffer: dropped, not crashed on
  std::uint64_t domain_points = 0;      // TES invocations
  std::uint64_t triangles_out = 0;
  std::uint64_t lines_out = 0;          // isolines; not appended to the TriangleBatch
  std::uint64_t points_out = 0;         // point_mode; not appended to the TriangleBatch
  // CPU seconds summed over threads (not wall time; the only non-deterministic fields).
  double tcs_seconds = 0.0;
  double tpg_seconds = 0.0;
  double tes_seconds = 0.0;
  TessStats& operator+=(const TessStats& o);
};

struct TessOptions {
  TessProfile profile = TessProfile::llvmpipe();
  // Patches per parallel task. Results are concatenated in patch order, so the output never
  // depends on this nor on the thread count; it only sets the scheduling grain.
  std::size_t patches_per_task = 32;
  // Optional: every TES invocation's record, in patch order then generation order.
  std::vector<TessDumpRecord>* dump = nullptr;
  // Optional, with dump: the vertices isolines and point mode emit, in emission order, as indices
  // into *dump (triangles: the batch's indices).
  std::vector<std::uint32_t>* dump_emitted = nullptr;
  // Optional: isoline segments (2 vertices each) and points (1 each) in emission order, for TES
  // layouts that do not produce triangles, each vertex as vertex_records(tes.num_varyings())
  // records (a LineBatch's or PointBatch's vertices). Without them such primitives are only
  // counted.
  std::vector<ClipVertex>* lines = nullptr;
  std::vector<ClipVertex>* points = nullptr;
  // Which pattern each patch's levels give: the primitive generator (GL) or uniform subdivision
  // (triangle domain only; stages/tpg_uniform.h).
  Tessellator tessellator = Tessellator::PrimitiveGenerator;
  // Where generated patterns are looked up; null: TessPatternCache::shared().
  TessPatternCache* patterns = nullptr;
  // Optional (`render --check`): each patch's control shader output, in patch order on the calling
  // thread, after the control stage of each range and before its evaluation; may throw to stop.
  std::function<void(std::size_t patch, const PatchOutput& out)> control_check;
  // tessellate_chunks: tessellate the next chunk while consume draws this one (TessGrain).
  bool overlap_chunks = false;
};

// Runs TCS -> generate_tessellation -> TES for patches [first_patch, last_patch) of the draw and
// appends their triangles to out in patch order, then emission order within a patch. Each unique
// domain point is evaluated once and stored once: out becomes an indexed batch (its vertices in
// patch order, then generation order), triangles index them. out.num_varyings is set to
// tes.num_varyings(). The bytes appended do not depend on parallel.threads() nor on
// options.patches_per_task. Memory grows with the range asked for: draw large meshes in chunks
// (tessellate_chunks below). Throws std::invalid_argument for a patch_vertices or output_vertices
// outside 1..kMaxPatchVertices or a TES with more than kMaxVaryings varyings.
TessStats tessellate(const TessDrawInput& input, std::size_t first_patch, std::size_t last_patch,
                     const TessControlProgram& tcs, const TessEvalProgram& tes,
                     const TessOptions& options, const Parallel& parallel, TriangleBatch& out);

// Tessellates the whole draw chunk by chunk (chunk_patches patches at a time) and hands each chunk's
// batch to consume (e.g. draw_triangles), in order, so memory is bounded by two chunks (their
// buffers are reused from chunk to chunk). With options.overlap_chunks and several threads the next
// chunk is tessellated while consume runs (Parallel::run_beside), unless options ask for dump
// records, a control check or isoline and point vertices, which consume reads. Calling draw_triangles on each chunk in order
// equals one draw of the whole batch. Typical use by the pipeline:
//
//   PnTcs tcs;  tcs.normal_mode = ...;  tcs.levels = TessLevelSettings::uniform(outer, inner);
//   PnTes tes;  tes.normal_mode = tcs.normal_mode;  tes.spacing = ...;  tes.view_proj = vp;
//   std::vector<StageVertex> cp(n);  // cp[i].attr[kAttrPosition] = (world, 1), [kAttrNormal] = (n, 0)
//   tessellate_chunks(TessDrawInput{cp, mesh.indices, 3}, 256, tcs, tes, {}, parallel,
//                     [&](const TriangleBatch& b) { draw_triangles(b, state, fs, fb, parallel); });
TessStats tessellate_chunks(const TessDrawInput& input, std::size_t chunk_patches,
                            const TessControlProgram& tcs, const TessEvalProgram& tes,
                            const TessOptions& options, const Parallel& parallel,
                            const std::function<void(const TriangleBatch&)>& consume);

// ---------------------------------------------------------------------------------------------
// Helpers shared by the built-in programs (and mirrored in their GLSL twins).

// normalize(v), except that a zero-length (or non-finite-length) v gives the zero vector instead
// of NaN: degenerate input yields a zero normal, which shaders treat as "unlit" rather than NaN.
glm::vec3 safe_normalize(const glm::vec3& v);

}  // namespace tessref
