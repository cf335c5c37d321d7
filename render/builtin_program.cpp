#include "render/builtin_program.h"

#include <algorithm>
#include <bit>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "mesh/vertex_tags.h"

namespace tessref {
namespace {

// Triangles per tessellated chunk (64 bytes per vertex: ~25 MB) and per parallel task.
constexpr std::size_t kChunkTriangles = 1 << 17;
constexpr std::size_t kTaskTriangles = 1 << 12;

// Component k of vertex v of a float attribute array, 0 past its components (GL's (0, 0, 0, 1)
// for the x, y and z the built-in shader reads).
float attribute_float(const VertexAttribute& a, std::size_t v, int k) {
  if (k >= a.components) return 0.0f;
  return std::bit_cast<float>(a.words[(a.constant ? 0 : v) * std::size_t(a.components) + std::size_t(k)]);
}

const VertexAttribute& attribute_at(const std::vector<VertexAttribute>& attributes, std::uint32_t location) {
  for (const VertexAttribute& a : attributes)
    if (a.location == location) return a;
  throw std::invalid_argument("draw: the built-in vertex shader reads location " + std::to_string(location) +
                              ", and no attribute array is there");
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

BuiltinProgram::BuiltinProgram(const programs::TransformVertexShader& vs, const TessellationSettings& settings,
                               const glm::vec2& viewport, const FragmentProgram& fs, std::vector<VertexTags> tags)
    : vs_(vs), settings_(settings), programs_(builtin_tess_programs(settings, vs, viewport)), fs_(fs),
      tags_(std::move(tags)) {}

void BuiltinProgram::run_vertices(const std::vector<VertexAttribute>& attributes, std::size_t first,
                                  std::size_t count, int /*instance*/, StageVertex* out,
                                  const Parallel& parallel, const std::uint32_t* /*vertex_ids*/) const {
  const VertexAttribute& positions = attribute_at(attributes, 0);
  const VertexAttribute& normals = attribute_at(attributes, 1);
  for (const VertexAttribute* a : {&positions, &normals})
    if (a->scalar != shader::Scalar::F32)
      throw std::invalid_argument("draw: the built-in vertex shader reads float arrays at locations 0 and 1");
  constexpr std::size_t kChunk = 4096;
  parallel.for_each((count + kChunk - 1) / kChunk, [&](std::size_t c) {
    const std::size_t end = std::min(count, (c + 1) * kChunk);
    for (std::size_t i = c * kChunk; i < end; ++i) {
      const std::size_t v = first + i;
      const glm::vec3 p(attribute_float(positions, v, 0), attribute_float(positions, v, 1), attribute_float(positions, v, 2));
      const glm::vec3 n(attribute_float(normals, v, 0), attribute_float(normals, v, 1), attribute_float(normals, v, 2));
      const programs::VertexOut o = vs_.main(p, n);
      StageVertex& s = out[i];
      s.attr[kAttrPosition] = glm::vec4(o.v_world_position, 1.0f);
      s.attr[kAttrNormal] = glm::vec4(o.v_world_normal, 0.0f);
      s.attr[kAttrClipPosition] = o.gl_Position;
    }
    if (!tags_.empty()) attach_vertex_tags(out + c * kChunk, first + c * kChunk, end - c * kChunk, tags_, vs_.u_normal_matrix);
  });
}

void BuiltinProgram::rasterizer_vertex(const StageVertex& shaded, ClipVertex* records) const {
  records->position = shaded.attr[kAttrClipPosition];
  for (int c = 0; c < 3; ++c) {
    records->varyings[kVaryingPosition + c] = shaded.attr[kAttrPosition][c];
    records->varyings[kVaryingNormal + c] = shaded.attr[kAttrNormal][c];
  }
}

std::vector<CheckedOutput> BuiltinProgram::checked_outputs() const {
  return {{kAttrClipPosition, "gl_Position", 4}, {kAttrPosition, "v_world_position", 3}, {kAttrNormal, "v_world_normal", 3}};
}

std::shared_ptr<const TessControlProgram> BuiltinProgram::control(int /*patch_vertices*/, const glm::vec4& /*outer*/,
                                                                  const glm::vec2& /*inner*/) const {
  return {std::shared_ptr<const TessControlProgram>(), &programs_.tcs()};  // owned by this program
}

std::shared_ptr<const TessEvalProgram> BuiltinProgram::evaluation() const {
  return {std::shared_ptr<const TessEvalProgram>(), &programs_.tes()};
}

std::shared_ptr<const FragmentProgram> BuiltinProgram::fragment() const {
  return {std::shared_ptr<const FragmentProgram>(), &fs_};
}

TessGrain BuiltinProgram::tess_grain() const {
  // Chunks and tasks sized by triangles, not patches: at level 64 one patch makes ~6,000
  // triangles, at level 1 one. The estimate is the generator's count for the constant levels
  // (adaptive levels: the largest they can reach).
  TessLevels levels = settings_.levels;
  if (settings_.adaptive.enabled) {
    levels.outer.fill(programs_.pn_tcs.levels.screen.max_level);
    levels.inner.fill(programs_.pn_tcs.levels.screen.max_level);
  }
  const std::size_t per_patch = std::max<std::size_t>(
      1, make_pattern(programs_.tes().layout(), levels, TessProfile::llvmpipe(), settings_.tessellator)
             ->points.primitive_count());
  return {std::clamp<std::size_t>(kChunkTriangles / per_patch, 1, 4096),
          std::clamp<std::size_t>(kTaskTriangles / per_patch, 1, 64), /*overlap_chunks=*/true};
}

std::vector<VertexAttribute> mesh_attributes(const Mesh& mesh) {
  std::vector<VertexAttribute> attributes(2);
  for (std::uint32_t location : {0u, 1u}) {
    const std::vector<glm::vec3>& values = location == 0 ? mesh.positions : mesh.normals;
    VertexAttribute& a = attributes[location];
    a.location = location;
    a.components = 3;
    a.words.resize(3 * values.size());
    for (std::size_t v = 0; v < values.size(); ++v)
      for (int k = 0; k < 3; ++k) a.words[3 * v + std::size_t(k)] = std::bit_cast<std::uint32_t>(values[v][k]);
  }
  return attributes;
}

}  // namespace tessref
