#include "stages/glsl/glsl_stages.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include <spirv/unified1/spirv.hpp>

#include "stages/glsl/lane_words.h"

namespace tessref::glsl {
namespace {

using shader::Invocations;
using shader::Scalar;

std::uint32_t* words_of(StageVertex& v) { return reinterpret_cast<std::uint32_t*>(v.attr.data()); }
const std::uint32_t* words_of(const StageVertex& v) { return reinterpret_cast<const std::uint32_t*>(v.attr.data()); }
constexpr std::uint32_t kVertexWords = 4 * kMaxStageAttributes;
constexpr std::uint32_t kPatchWords = 4 * kMaxPatchAttributes;

std::uint32_t bits(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
float to_float(std::uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

// Shared (per-patch) variables from and to plain word arrays.
// src / dst hold I/O words [first, first + limit): a vertex's slots (first 0) or a patch's
// (first 4: patch slot L is I/O word 4 + 4L, as glsl_interface.h lays patch locations out).
void copy_in(std::uint32_t* dst, const std::vector<IoWord>& words, const std::uint32_t* src, std::uint32_t limit,
             std::uint32_t first = 0) {
  for (const IoWord& w : words) {
    const int n = shader::scalar_words(w.scalar);
    for (int h = 0; h < n; ++h)
      if (w.io_word + h - first < limit) dst[w.var_word + h] = src[w.io_word + h - first];
  }
}
void copy_out(std::uint32_t* dst, const std::vector<IoWord>& words, const std::uint32_t* src, std::uint32_t limit,
              std::uint32_t first = 0) {
  for (const IoWord& w : words) {
    const int n = shader::scalar_words(w.scalar);
    for (int h = 0; h < n; ++h)
      if (w.io_word + h - first < limit) dst[w.io_word + h - first] = src[w.var_word + h];
  }
}

// Per-patch built-ins and arrays shared by a TCS's or TES's invocations.
void fill_patch_inputs(const StageProgram& sp, Invocations& inv, int group, const StageVertex* vertices,
                       int vertex_count, const std::array<glm::vec4, kMaxPatchAttributes>* patch,
                       const TessLevels* levels, int primitive_id) {
  for (const IoVariable& v : sp.io.inputs) {
    if (!v.slot || v.slot->per_lane) continue;
    std::uint32_t* dst = inv.shared(*v.slot, group);
    switch (v.kind) {
      case IoKind::User:
      case IoKind::Position:
        if (v.arrayed) {
          const std::uint32_t n = std::min<std::uint32_t>(v.elements, std::uint32_t(vertex_count));
          for (std::uint32_t k = 0; k < n; ++k)
            copy_in(dst + k * v.element_words, v.words, words_of(vertices[k]), kVertexWords);
        } else if (v.patch && patch) {
          copy_in(dst, v.words, reinterpret_cast<const std::uint32_t*>(patch->data()), kPatchWords, 4);
        }
        break;
      case IoKind::PrimitiveId: dst[0] = std::uint32_t(primitive_id); break;
      case IoKind::PatchVertices: dst[0] = std::uint32_t(vertex_count); break;
      case IoKind::TessLevelOuter:
        if (levels)
          for (int i = 0; i < 4; ++i) dst[i] = bits(levels->outer[i]);
        break;
      case IoKind::TessLevelInner:
        if (levels)
          for (int i = 0; i < 2; ++i) dst[i] = bits(levels->inner[i]);
        break;
      default: break;
    }
  }
}

const IoVariable* find_kind(const std::vector<IoVariable>& vars, IoKind kind) {
  for (const IoVariable& v : vars)
    if (v.kind == kind) return &v;
  return nullptr;
}

}  // namespace

TessLayout layout_of(const shader::ExecutionModes& modes) {
  TessLayout l;
  l.domain = modes.primitive == spv::ExecutionModeQuads      ? TessDomain::Quads
             : modes.primitive == spv::ExecutionModeIsolines ? TessDomain::Isolines
                                                             : TessDomain::Triangles;
  l.spacing = modes.spacing == spv::ExecutionModeSpacingFractionalOdd    ? TessSpacing::FractionalOdd
              : modes.spacing == spv::ExecutionModeSpacingFractionalEven ? TessSpacing::FractionalEven
                                                                         : TessSpacing::Equal;
  l.winding = modes.order == spv::ExecutionModeVertexOrderCw ? TessWinding::Cw : TessWinding::Ccw;
  l.point_mode = modes.point_mode;
  return l;
}

// ---------------------------------------------------------------------------------------------
// Tessellation control

int GlslControl::output_vertices() const { return sp_.exe->module().modes.output_vertices; }

void GlslControl::run(int, int, const Patch&, PatchOutput&) const {
  // Never called: run_phase runs all invocations of a patch together.
}

int GlslControl::gl_phases() const {
  int phases = 1;
  for (const shader::Block& b : sp_.exe->module().blocks)
    for (const shader::Instruction& ins : b.body) phases += ins.opcode == spv::OpControlBarrier;
  return phases;
}

void GlslControl::run_phase(int, const Patch& in, PatchOutput& out) const {
  const Patch* i = &in;
  PatchOutput* o = &out;
  run_patches(&i, &o, 1);
}

void GlslControl::run_patches(const Patch* const* in, PatchOutput* const* out, int count) const {
  // As many whole patches per batch as the lanes hold: lane l is invocation l % n of patch l / n,
  // each patch a group with its own gl_in[], gl_out[] and patch variables.
  const int n = output_vertices();
  const int lanes = std::clamp(sp_.exe->limits().batch_lanes, 1, shader::kMaxLanes);
  // With side effects, one patch a batch: they then happen in patch order whatever the batch size.
  const int per_batch =
      sp_.side_effects ? 1 : std::max(1, std::min(shader::kMaxLanes, std::max(lanes, n)) / n);
  for (int first = 0; first < count; first += per_batch) {
    const int groups = std::min(per_batch, count - first);
    Invocations& inv = sp_.prepare(groups);
    for (int g = 0; g < groups; ++g) {
      const Patch& p = *in[first + g];
      fill_patch_inputs(sp_, inv, g, p.vertices.data(), p.vertex_count, nullptr, nullptr, p.primitive_id);
    }
    inv.begin(groups * n, groups);
    const IoVariable* id = find_kind(sp_.io.inputs, IoKind::InvocationId);
    for (int l = 0; l < groups * n; ++l) {
      inv.set_group(l, l / n);
      if (id) inv.row(*id->slot, 0)[l] = std::uint32_t(l % n);
    }
    try {
      inv.run();
    } catch (const shader::ShaderRuntimeError& e) {
      sp_.rethrow(e, "patch " + std::to_string(in[first + e.lane / n]->primitive_id) + ", invocation " +
                         std::to_string(e.lane % n));
    }
    sp_.finish(inv);
    for (int g = 0; g < groups; ++g) read_outputs(inv, g, *out[first + g]);
  }
}

void GlslControl::read_outputs(Invocations& inv, int group, PatchOutput& out) const {
  const int n = output_vertices();
  for (const IoVariable& v : sp_.io.outputs) {
    const std::uint32_t* src = inv.shared(*v.slot, group);
    switch (v.kind) {
      case IoKind::User:
      case IoKind::Position:
        if (v.arrayed) {
          for (std::uint32_t k = 0; k < std::min<std::uint32_t>(v.elements, std::uint32_t(n)); ++k)
            copy_out(words_of(out.vertices[k]), v.words, src + k * v.element_words, kVertexWords);
        } else if (v.patch) {
          copy_out(reinterpret_cast<std::uint32_t*>(out.patch.data()), v.words, src, kPatchWords, 4);
        }
        break;
      case IoKind::TessLevelOuter:
        for (int i = 0; i < 4; ++i) out.levels.outer[i] = to_float(src[i]);
        break;
      case IoKind::TessLevelInner:
        for (int i = 0; i < 2; ++i) out.levels.inner[i] = to_float(src[i]);
        break;
      default: break;
    }
  }
}

void PassThroughControl::run(int, int invocation_id, const Patch& in, PatchOutput& out) const {
  out.vertices[invocation_id] = in.vertices[invocation_id];
  out.levels.outer = {outer_.x, outer_.y, outer_.z, outer_.w};
  out.levels.inner = {inner_.x, inner_.y};
}

// ---------------------------------------------------------------------------------------------
// Tessellation evaluation

void GlslEvaluation::evaluate_batch(const PatchOutput& patch, int primitive_id, TessEvalBatch& batch) const {
  const int step = sp_.side_effects ? 1 : std::clamp(sp_.exe->limits().batch_lanes, 1, shader::kMaxLanes);
  for (int first = 0; first < batch.count; first += step)
    evaluate_lanes(patch, primitive_id, batch, first, std::min(step, batch.count - first));
}

void GlslEvaluation::evaluate_lanes(const PatchOutput& patch, int primitive_id, TessEvalBatch& batch,
                                    int first, int n) const {
  Invocations& inv = sp_.prepare();
  fill_patch_inputs(sp_, inv, 0, patch.vertices.data(), patch.vertex_count, &patch.patch, &patch.levels,
                    primitive_id);
  inv.begin(n);
  if (const IoVariable* tc = find_kind(sp_.io.inputs, IoKind::TessCoord))
    for (int c = 0; c < 3; ++c)
      std::memcpy(inv.row(*tc->slot, std::uint32_t(c)), batch.tess_coord[c] + first, 4 * std::size_t(n));
  try {
    inv.run();
  } catch (const shader::ShaderRuntimeError& e) {
    sp_.rethrow(e, "patch " + std::to_string(primitive_id) + ", invocation " + std::to_string(first + e.lane));
  }
  sp_.finish(inv);
  for (int r = 0; r < varyings_; ++r) std::fill_n(batch.varyings[r] + first, n, 0.0f);
  for (int c = 0; c < 4; ++c) std::fill_n(batch.position[c] + first, n, 0.0f);
  for (const IoVariable& v : sp_.io.outputs) {
    if (!v.carries_words()) continue;
    for (const IoWord& w : v.words) {
      const std::uint32_t* row = inv.row(*v.slot, w.var_word);
      auto dst = [&](std::uint32_t io) -> float* {
        const int f = outputs_.float_of(io);
        return f < 0 ? nullptr : f < 4 ? batch.position[f] + first : batch.varyings[f - 4] + first;
      };
      if (w.scalar == Scalar::F64) {  // a double's lanes are interleaved: two varying rows
        float* lo = dst(w.io_word);
        float* hi = dst(w.io_word + 1);
        for (int l = 0; l < n && lo && hi; ++l) {
          std::memcpy(lo + l, row + 2 * l, 4);
          std::memcpy(hi + l, row + 2 * l + 1, 4);
        }
      } else if (float* d = dst(w.io_word)) {
        std::memcpy(d, row, 4 * std::size_t(n));
      }
    }
  }
  if (primitive_id_varying_ >= 0)
    std::fill_n(batch.varyings[primitive_id_varying_] + first, n, std::bit_cast<float>(std::uint32_t(primitive_id)));
}

ClipVertex GlslEvaluation::evaluate(const glm::vec3& tess_coord, const PatchOutput& patch, int primitive_id) const {
  TessEvalBatch batch;
  const float u[1] = {tess_coord.x}, v[1] = {tess_coord.y}, w[1] = {tess_coord.z};
  batch.count = 1;
  batch.tess_coord[0] = u;
  batch.tess_coord[1] = v;
  batch.tess_coord[2] = w;
  evaluate_batch(patch, primitive_id, batch);
  ClipVertex out;
  out.position = glm::vec4(batch.position[0][0], batch.position[1][0], batch.position[2][0], batch.position[3][0]);
  for (int k = 0; k < varyings_; ++k) out.varyings[k] = batch.varyings[k][0];
  return out;
}

// ---------------------------------------------------------------------------------------------
// Fragment

namespace {

// The vector llvmpipe shades a fragment's quad in: 4 x 2 pixels, two quads side by side
// (texture lookups read it: Invocations::set_sampling_vectors).
std::uint32_t sampling_vector(const FragmentBatch& batch, int lane) {
  const auto x = std::uint32_t(std::int32_t(batch.frag_coord[0][lane])), y = std::uint32_t(std::int32_t(batch.frag_coord[1][lane]));
  return (x >> 2) | (y >> 1) << 16;
}

}  // namespace

void GlslFragment::shade_batch(FragmentBatch& batch) const {
  // Whole quads per run: derivatives difference the lanes of a quad. A run does not end between
  // the two quads of one sampling vector, so that no lookup depends on batch_lanes.
  // With side effects, one quad (or sampling vector) a run: they happen in quad order.
  const int unit = samples_textures_ ? 8 : 4;
  const int step = sp_.side_effects ? unit : std::max(unit, std::clamp(sp_.exe->limits().batch_lanes, 1, shader::kMaxLanes) & ~3);
  for (int first = 0; first < batch.lanes();) {
    int n = std::min(step, batch.lanes() - first);
    if (samples_textures_ && first + n < batch.lanes() && sampling_vector(batch, first + n - 4) == sampling_vector(batch, first + n))
      n -= 4;
    shade_lanes(batch, first, n);
    first += n;
  }
}

void GlslFragment::shade_lanes(FragmentBatch& batch, int first, int n) const {
  Invocations& inv = sp_.prepare();
  inv.begin(n);
  // Lanes that are not live (no sample covered, or discarded by the early depth test) run as
  // helpers: no stores to storage blocks, no atomics.
  if (sp_.side_effects) {
    std::uint8_t helper[shader::kMaxLanes];
    for (int l = 0; l < n; ++l) helper[l] = batch.live[first + l] ? 0 : 1;
    inv.set_helpers(helper);
  }
  if (samples_textures_) {
    std::uint32_t vectors[shader::kMaxLanes];
    for (int l = 0; l < n; ++l) vectors[l] = sampling_vector(batch, first + l);
    inv.set_sampling_vectors(vectors);
  }
  for (const IoVariable& v : sp_.io.inputs) {
    switch (v.kind) {
      case IoKind::FragCoord:
        for (int c = 0; c < 4; ++c) std::memcpy(inv.row(*v.slot, std::uint32_t(c)), batch.frag_coord[c] + first, 4 * std::size_t(n));
        break;
      case IoKind::FrontFacing:
        for (int l = 0; l < n; ++l) inv.row(*v.slot, 0)[l] = batch.front_facing[first + l] ? 1u : 0u;
        break;
      case IoKind::HelperInvocation:  // the lanes of a quad that cover no sample (tile_raster.cpp)
        for (int l = 0; l < n; ++l) inv.row(*v.slot, 0)[l] = batch.live[first + l] ? 0u : 1u;
        break;
      case IoKind::SampleMaskIn:  // one sample a pixel: bit 0 where it is covered (GL 4.6 15.2.2)
        for (int l = 0; l < n; ++l) inv.row(*v.slot, 0)[l] = batch.live[first + l] ? 1u : 0u;
        break;
      case IoKind::PrimitiveId:
        if (primitive_id_varying_ >= 0)
          std::memcpy(inv.row(*v.slot, 0), batch.varyings[primitive_id_varying_] + first, 4 * std::size_t(n));
        break;
      case IoKind::User:
      case IoKind::ClipDistance:  // interpolated like the varyings (GL 4.6 15.2.2)
      case IoKind::CullDistance:
        for (const IoWord& w : v.words) {
          std::uint32_t* row = inv.row(*v.slot, w.var_word);
          const int k = inputs_.float_of(w.io_word) - 4;
          const int nw = shader::scalar_words(w.scalar);
          if (k < 0 || k + nw > batch.num_varyings) {
            std::fill_n(row, n * nw, 0u);
          } else if (w.scalar == Scalar::F64) {  // two varying rows into interleaved lanes
            for (int l = 0; l < n; ++l) {
              std::memcpy(row + 2 * l, batch.varyings[k] + first + l, 4);
              std::memcpy(row + 2 * l + 1, batch.varyings[k + 1] + first + l, 4);
            }
          } else {
            std::memcpy(row, batch.varyings[k] + first, 4 * std::size_t(n));
          }
        }
        break;
      default: break;
    }
  }
  try {
    inv.run();
  } catch (const shader::ShaderRuntimeError& e) {
    sp_.rethrow(e, "fragment (" + std::to_string(int(batch.frag_coord[0][first + e.lane])) + ", " +
                       std::to_string(int(batch.frag_coord[1][first + e.lane])) + ")");
  }
  sp_.finish(inv);
  // Outputs at locations 0 .. kMaxDrawBuffers - 1, one per draw buffer; what a program does not
  // write reads 0.
  constexpr std::uint32_t kOutputWords = 4 + 4 * kMaxDrawBuffers;
  for (int k = 0; k < std::max(2, output_locations_); ++k)
    for (int c = 0; c < 4; ++c) std::fill_n(batch.output(k, c) + first, n, 0.0f);
  for (const IoVariable& v : sp_.io.outputs) {
    if (v.kind != IoKind::User) continue;
    for (const IoWord& w : v.words) {
      if (w.scalar == Scalar::F64 || w.io_word >= kOutputWords) continue;
      float* dst = batch.output(int(w.io_word - 4) / 4, int(w.io_word - 4) % 4) + first;
      const std::uint32_t* row = inv.row(*v.slot, w.var_word);
      if (w.scalar == Scalar::F32) std::memcpy(dst, row, 4 * std::size_t(n));
      else for (int l = 0; l < n; ++l) dst[l] = w.scalar == Scalar::I32 ? float(std::int32_t(row[l])) : float(row[l]);
    }
  }
  // gl_FragDepth: what the invocation wrote; GL leaves an invocation that does not write it
  // undefined, and the executor's zeroed outputs give 0.
  if (frag_depth_) std::memcpy(batch.frag_depth + first, inv.row(*frag_depth_->slot, 0), 4 * std::size_t(n));
  const std::uint8_t* killed = inv.discarded();
  for (int l = 0; l < n; ++l)
    if (killed[l]) batch.live[first + l] = 0;
}

GlslFragment::GlslFragment(const StageProgram& sp, const VaryingLayout& inputs, int varyings, int primitive_id_varying)
    : sp_(sp), inputs_(inputs), varyings_(varyings), primitive_id_varying_(primitive_id_varying),
      samples_textures_(sp.exe->samples_textures()) {
  for (const IoVariable& v : sp_.io.outputs) {
    if (v.kind == IoKind::FragDepth) frag_depth_ = &v;
    if (v.kind == IoKind::User)
      for (const IoWord& w : v.words)
        if (w.io_word >= 4)
          output_locations_ = std::min(kMaxDrawBuffers, std::max(output_locations_, int(w.io_word - 4) / 4 + 1));
  }
}

FragmentOutput GlslFragment::shade(const FragmentInput& in) const {
  FragmentBatch batch;
  batch.quads = 1;
  batch.num_varyings = varyings_;
  for (int l = 0; l < 4; ++l) {
    batch.live[l] = l == 0;
    batch.front_facing[l] = in.front_facing;
    for (int c = 0; c < 4; ++c) batch.frag_coord[c][l] = in.frag_coord[c];
    for (int k = 0; k < varyings_; ++k) batch.varyings[k][l] = in.varyings[k];
  }
  shade_batch(batch);
  FragmentOutput out;
  for (int c = 0; c < 4; ++c) {
    out.color[c] = batch.color[c][0];
    out.aux[c] = batch.aux[c][0];
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Vertex

void run_vertex_stage(const StageProgram& sp, const std::vector<VertexAttribute>& attributes,
                      std::size_t first, std::size_t count, int instance, StageVertex* out,
                      const Parallel& parallel, const std::uint32_t* vertex_ids) {
  const std::size_t step = sp.side_effects ? 1 : std::size_t(std::clamp(sp.exe->limits().batch_lanes, 1, shader::kMaxLanes));
  const std::size_t batches = (count + step - 1) / step;
  auto run_batch = [&](std::size_t b) {
    const std::size_t start = b * step;
    const int n = int(std::min<std::size_t>(step, count - start));
    Invocations& inv = sp.prepare();
    inv.begin(n);
    for (const IoVariable& v : sp.io.inputs) {
      if (v.kind == IoKind::VertexId || v.kind == IoKind::InstanceId) {
        for (int l = 0; l < n; ++l)
          inv.row(*v.slot, 0)[l] = v.kind == IoKind::InstanceId ? std::uint32_t(instance)
                                   : vertex_ids                 ? vertex_ids[start + std::size_t(l)]
                                                                : std::uint32_t(first + start + std::size_t(l));
        continue;
      }
      if (v.kind != IoKind::User) continue;
      for (const IoWord& w : v.words) {
        const std::uint32_t location = (w.io_word - 4) / 4, word = (w.io_word - 4) % 4;
        const VertexAttribute* a = nullptr;
        for (const VertexAttribute& candidate : attributes)
          if (candidate.location == location) a = &candidate;
        for (int l = 0; l < n; ++l) {
          // Missing components read as GL's defaults: (0, 0, 0, 1).
          std::uint32_t value[2] = {word == 3 && w.scalar == Scalar::F32 ? bits(1.0f) : 0u, 0u};
          const std::size_t vtx = a && a->constant ? 0 : first + start + std::size_t(l);
          if (a && word < std::uint32_t(a->components) && (vtx + 1) * a->components <= a->words.size()) {
            value[0] = a->words[vtx * a->components + word];
            if (w.scalar == Scalar::F64 && word + 1 < std::uint32_t(a->components)) value[1] = a->words[vtx * a->components + word + 1];
          }
          set_lane(inv, *v.slot, w.var_word, w.scalar, l, value);
        }
      }
    }
    try {
      inv.run();
    } catch (const shader::ShaderRuntimeError& e) {
      sp.rethrow(e, "vertex " + std::to_string(vertex_ids ? vertex_ids[start + std::size_t(e.lane)]
                                                          : first + start + std::size_t(e.lane)));
    }
    sp.finish(inv);
    for (int l = 0; l < n; ++l) out[start + std::size_t(l)] = StageVertex{};
    for (const IoVariable& v : sp.io.outputs) {
      if (!v.carries_words()) continue;
      for (const IoWord& w : v.words) {
        if (w.io_word + shader::scalar_words(w.scalar) > kVertexWords) continue;
        for (int l = 0; l < n; ++l) get_lane(inv, *v.slot, w.var_word, w.scalar, l, words_of(out[start + std::size_t(l)]) + w.io_word);
      }
    }
  };
  if (batches <= 1) {
    if (batches == 1) run_batch(0);
  } else {
    parallel.for_each(batches, run_batch);
  }
}

}  // namespace tessref::glsl
