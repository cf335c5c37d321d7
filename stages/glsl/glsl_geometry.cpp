#include "stages/glsl/glsl_geometry.h"

#include <algorithm>
#include <array>
#include <cstring>

#include <spirv/unified1/spirv.hpp>

#include "stages/glsl/lane_words.h"

namespace tessref::glsl {
namespace {

// What one lane emitted: its vertices (records each) and its primitives' corners as indices into
// them, strips already cut into lists.
struct LaneEmission {
  std::vector<ClipVertex> vertices;
  std::vector<std::uint32_t> indices;
  std::uint32_t strip_first = 0;  // the first vertex of the open strip
  int emitted = 0;                // vertices emitted on stream 0, kept or not (max_vertices)
  // Streams 1..3 (points): their vertices, and how many each emitted, kept or not.
  std::array<std::vector<ClipVertex>, 3> stream_vertices;
  std::array<int, 3> stream_emitted{};
};

}  // namespace

GlslGeometry::GlslGeometry(const StageProgram& sp, const VaryingLayout& inputs, const VaryingLayout& outputs,
                           int varyings, const VaryingMask& flat, int primitive_id_varying)
    : sp_(sp), inputs_(inputs), outputs_(outputs), varyings_(varyings), flat_(flat), primitive_id_varying_(primitive_id_varying) {
  const shader::ExecutionModes& modes = sp.exe->module().modes;
  input_vertices_ = modes.input_vertices;
  output_corners_ = modes.output_primitive == spv::ExecutionModeOutputPoints       ? 1
                    : modes.output_primitive == spv::ExecutionModeOutputLineStrip ? 2
                                                                                  : 3;
  max_vertices_ = modes.output_vertices;
  invocations_ = std::max(1, modes.invocations);
}

void GlslGeometry::run(const float* const* corners, int in_varyings, std::size_t count, std::uint32_t first_id,
                       GeometryOutput& out) const {
  const std::size_t lanes = count * std::size_t(invocations_);
  const std::size_t step = sp_.side_effects ? 1 : std::size_t(std::clamp(sp_.exe->limits().batch_lanes, 1, shader::kMaxLanes));
  for (std::size_t first = 0; first < lanes; first += step)
    run_lanes(corners, in_varyings, first, int(std::min(step, lanes - first)), first_id, out);
}

void GlslGeometry::run_lanes(const float* const* corners, int in_varyings, std::size_t first, int n,
                             std::uint32_t first_id, GeometryOutput& out) const {
  shader::Invocations& inv = sp_.prepare();
  inv.begin(n);
  const auto primitive = [&](int lane) { return (first + std::size_t(lane)) / std::size_t(invocations_); };
  const int in_floats = 4 + in_varyings;
  for (const IoVariable& v : sp_.io.inputs) {
    if (!v.slot) continue;
    for (int l = 0; l < n; ++l) {
      const std::size_t p = primitive(l);
      switch (v.kind) {
        case IoKind::User:
        case IoKind::Position:
          for (std::uint32_t k = 0; k < std::min<std::uint32_t>(v.elements, std::uint32_t(input_vertices_)); ++k) {
            const float* vertex = corners[p * std::size_t(input_vertices_) + k];
            for (const IoWord& w : v.words) {
              std::uint32_t value[2] = {0u, 0u};  // what the previous stage does not write reads 0
              for (int h = 0; h < shader::scalar_words(w.scalar); ++h)
                if (const int f = inputs_.float_of(w.io_word + std::uint32_t(h)); f >= 0 && f < in_floats)
                  std::memcpy(&value[h], vertex + f, 4);
              set_lane(inv, *v.slot, k * v.element_words + w.var_word, w.scalar, l, value);
            }
          }
          break;
        case IoKind::PrimitiveId: inv.row(*v.slot, 0)[l] = first_id + std::uint32_t(p); break;
        case IoKind::InvocationId: inv.row(*v.slot, 0)[l] = std::uint32_t((first + std::size_t(l)) % std::size_t(invocations_)); break;
        default: break;
      }
    }
  }
  const int records = vertex_records(varyings_);
  const IoVariable* primitive_id_out = nullptr;
  for (const IoVariable& v : sp_.io.outputs)
    if (v.kind == IoKind::PrimitiveId) primitive_id_out = &v;
  std::vector<LaneEmission> emissions(std::size_t(n), LaneEmission{});
  const auto end_strip = [&](LaneEmission& e) {
    const auto count = std::uint32_t(e.vertices.size() / std::size_t(records));
    append_strip(output_corners_, e.strip_first, count - e.strip_first, e.indices);
    e.strip_first = count;
  };
  inv.on_emit([&](int lane, int stream, bool end) {
    LaneEmission& e = emissions[std::size_t(lane)];
    // Streams past 0 feed transform feedback only: kept when it records them. Their primitives
    // are points (GL), so ending one ends nothing.
    if (stream != 0 && (end || !out.keep_streams || stream > 3)) return;
    if (end) return end_strip(e);
    // GL leaves vertices past max_vertices undefined; like llvmpipe, they are dropped.
    if ((stream ? e.stream_emitted[std::size_t(stream - 1)] : e.emitted)++ >= max_vertices_) return;
    std::vector<ClipVertex>& vertices = stream ? e.stream_vertices[std::size_t(stream - 1)] : e.vertices;
    const std::size_t at = vertices.size();
    vertices.resize(at + std::size_t(records), ClipVertex{});
    auto* floats = reinterpret_cast<std::uint32_t*>(vertices.data() + at);
    for (const IoVariable& v : sp_.io.outputs) {
      if (!v.carries_words()) continue;
      for (const IoWord& w : v.words) {
        std::uint32_t value[2];
        get_lane(inv, *v.slot, w.var_word, w.scalar, lane, value);
        for (int h = 0; h < shader::scalar_words(w.scalar); ++h)
          if (const int f = outputs_.float_of(w.io_word + std::uint32_t(h)); f >= 0) floats[f] = value[h];
      }
    }
    if (primitive_id_varying_ >= 0)
      floats[4 + primitive_id_varying_] = primitive_id_out ? inv.row(*primitive_id_out->slot, 0)[lane]
                                                           : first_id + std::uint32_t(primitive(lane));
  });
  try {
    inv.run();
  } catch (const shader::ShaderRuntimeError& e) {
    inv.on_emit(nullptr);
    sp_.rethrow(e, "primitive " + std::to_string(first_id + std::uint32_t(primitive(e.lane))) + ", invocation " +
                       std::to_string((first + std::size_t(e.lane)) % std::size_t(invocations_)));
  }
  inv.on_emit(nullptr);
  sp_.finish(inv);
  const auto append = [&](auto& batch) {
    for (LaneEmission& e : emissions) {
      end_strip(e);  // the shader's end ends its last primitive
      const auto base = std::uint32_t(batch.vertex_count());
      batch.vertices.insert(batch.vertices.end(), e.vertices.begin(), e.vertices.end());
      for (const std::uint32_t i : e.indices) batch.indices.push_back(base + i);
    }
  };
  if (output_corners_ == 1) append(out.points);
  else if (output_corners_ == 2) append(out.lines);
  else append(out.triangles);
  if (out.keep_streams)
    for (std::size_t s = 0; s < out.streams.size(); ++s)
      for (const LaneEmission& e : emissions) {
        PointBatch& batch = out.streams[s];
        const auto base = std::uint32_t(batch.vertex_count());
        batch.vertices.insert(batch.vertices.end(), e.stream_vertices[s].begin(), e.stream_vertices[s].end());
        for (std::uint32_t i = 0; i < e.stream_vertices[s].size() / std::size_t(records); ++i) batch.indices.push_back(base + i);
      }
}

}  // namespace tessref::glsl
