#include "inspect/inspect.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "common/error.h"
#include "common/parallel.h"
#include "render/builtin_program.h"
#include "render/draw_scene.h"
#include "render/glsl_scene.h"
#include "render/render.h"
#include "stages/glsl/glsl_stages.h"
#include "mesh/vertex_tags.h"

namespace tessref {
namespace {

// A control program that runs the draw's own and keeps the inspected patch's gl_in[] and output as
// the executor handed them over: the values shown are the executor's, not a second run's.
class ControlTap : public TessControlProgram {
 public:
  ControlTap(const TessControlProgram& inner, std::size_t patch) : inner_(inner), patch_(patch) {}
  int output_vertices() const override { return inner_.output_vertices(); }
  int phases() const override { return inner_.phases(); }
  void run(int phase, int id, const Patch& in, PatchOutput& out) const override { inner_.run(phase, id, in, out); }
  void run_phase(int phase, const Patch& in, PatchOutput& out) const override { inner_.run_phase(phase, in, out); }
  void run_patches(const Patch* const* in, PatchOutput* const* out, int count) const override {
    inner_.run_patches(in, out, count);
    for (int k = 0; k < count; ++k)
      if (std::size_t(in[k]->primitive_id) == patch_) {
        input = *in[k];
        output = *out[k];
      }
  }
  // Written once, on the one thread inspect runs the executor with.
  mutable std::optional<Patch> input;
  mutable std::optional<PatchOutput> output;

 private:
  const TessControlProgram& inner_;
  std::size_t patch_;
};

// The stages after the vertex shader, as the draw builds them.

// The TES at one coordinate, through the entry point the executor calls (evaluate_batch). The
// coordinate rows are zero-padded as the pattern's are (kernels may read whole vectors).
void evaluate_at(const TessEvalProgram& tes, const PatchOutput& patch, int primitive_id,
                 InspectPoint& point, int num_varyings) {
  auto batch = std::make_unique<TessEvalBatch>();
  std::vector<float> rows[3];
  for (int c = 0; c < 3; ++c) {
    rows[c].assign(kTessEvalBatch, 0.0f);
    rows[c][0] = point.tess_coord[c];
    batch->tess_coord[c] = rows[c].data();
  }
  batch->count = 1;
  for (auto& row : batch->varyings) row[0] = 0.0f;  // unwritten varyings read as the store's zeros
  tes.evaluate_batch(patch, primitive_id, *batch);
  for (int c = 0; c < 4; ++c) point.gl_position[c] = batch->position[c][0];
  point.varyings.resize(std::size_t(num_varyings));
  for (int v = 0; v < num_varyings; ++v) point.varyings[std::size_t(v)] = batch->varyings[v][0];
}

// The world position and normal --dump-tess would record from the varyings (tess_stage.cpp's rule:
// indices clamped into the vertex's records).
void fill_dump_fields(InspectPoint& p, std::array<int, 2> at, int num_varyings) {
  const int floats = 16 * vertex_records(num_varyings) - 4;
  auto get = [&](int i) { return i < int(p.varyings.size()) ? p.varyings[std::size_t(i)] : 0.0f; };
  for (int& a : at) a = std::clamp(a, 0, floats - 3);
  p.position = glm::vec3(get(at[0]), get(at[0] + 1), get(at[0] + 2));
  p.normal = glm::vec3(get(at[1]), get(at[1] + 1), get(at[1] + 2));
}

std::string format_float(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(v));
  return text;
}

// --coord: on the domain of the layout (barycentric for triangles, the unit square otherwise).
// w_computed: W was not given but computed as (1 - U) - V.
void check_coord(const glm::vec3& c, TessDomain domain, bool w_computed) {
  static const char* const kNames[3] = {"U", "V", "W"};
  for (int i = 0; i < 3; ++i) {
    if (std::isfinite(c[i]) && c[i] >= 0.0f && c[i] <= 1.0f) continue;
    if (i == 2 && w_computed)
      throw InputError("--coord: U + V must be at most 1 on a triangle patch: W = (1 - U) - V = " + format_float(c[i]) +
                       " (computed from the U,V given)");
    throw InputError("--coord: every component must lie in [0, 1], got " + std::string(kNames[i]) + " = " + format_float(c[i]));
  }
  if (domain == TessDomain::Triangles) {
    const double sum = double(c.x) + double(c.y) + double(c.z);
    if (std::fabs(sum - 1.0) > 1e-6)
      throw InputError("--coord: a triangle patch's gl_TessCoord has u + v + w = 1, got " + std::to_string(sum));
  } else if (c.z != 0.0f) {
    throw InputError(std::string("--coord: the ") + to_string(domain) + " domain's gl_TessCoord is (u, v, 0); give U,V");
  }
}

// The part both front ends share: TCS -> generator -> TES on one patch of `input`, the points
// asked for, and the GLSL programs' source traces (sources empty: none). rerun_vertex(k) runs the
// vertex shader again for corner k (under a trace).
struct PatchStages {
  const std::string& source;  // the scene, for error messages
  const TessDrawInput& input;
  std::size_t patch;  // within input: gl_PrimitiveID
  const TessControlProgram& tcs;
  const TessEvalProgram& tes;
  Tessellator tessellator;
  const std::vector<shader::ShaderSource>& sources;
  std::function<void(std::size_t)> rerun_vertex;
};

void inspect_stages(const PatchStages& st, const InspectRequest& request, InspectResult& r) {
  const Parallel serial(1);
  const ControlTap tap(st.tcs, st.patch);
  const TessEvalProgram& tes = st.tes;
  r.layout = tes.layout();
  r.num_varyings = std::clamp(tes.num_varyings(), 0, kMaxVaryings);
  r.dump_varyings = tes.dump_varyings();
  r.tcs_vertices = tap.output_vertices();
  const auto* glsl_tcs = dynamic_cast<const glsl::GlslControl*>(&st.tcs);
  r.tcs_phases = glsl_tcs ? glsl_tcs->gl_phases() : tap.phases();
  std::vector<TessDumpRecord> records;
  TessOptions options;
  options.dump = &records;
  options.tessellator = st.tessellator;
  TriangleBatch batch;
  TessStats stats;
  try {
    stats = tessellate(st.input, st.patch, st.patch + 1, tap, tes, options, serial, batch);
  } catch (const glsl::StageError& e) {
    throw InputError(st.source + ": " + e.what());
  }
  if (!tap.output)
    throw InputError("--patch: patch " + std::to_string(request.patch) + " indexes a vertex past the vertex arrays; the draw drops it");
  r.tcs_out = *tap.output;
  r.levels = process_tess_levels(r.layout, r.tcs_out.levels, options.profile);
  r.discarded = stats.patches_discarded != 0;
  r.domain_points = records.size();
  r.primitives = stats.triangles_out + stats.lines_out + stats.points_out;
  r.vertices_per_primitive = r.layout.point_mode ? 1 : r.layout.domain == TessDomain::Isolines ? 2 : 3;
  const int primitive_id = int(st.patch);

  // ---- The points asked for ------------------------------------------------------------------
  if (request.vertex && *request.vertex >= records.size())
    throw InputError("--vertex: " + std::to_string(*request.vertex) + " is past the patch's " +
                     std::to_string(records.size()) + " generated domain points" +
                     (r.discarded ? " (the generator discarded the patch)" : ""));
  const bool from_batch = batch.vertex_count() == records.size();  // triangles: the executor's own vertices
  auto generated = [&](std::size_t k) {
    InspectPoint p;
    p.index = k;
    p.tess_coord = records[k].tess_coord;
    if (from_batch) {
      const float* v = batch.vertex_data(k);
      p.gl_position = glm::vec4(v[0], v[1], v[2], v[3]);
      p.varyings.assign(v + 4, v + 4 + r.num_varyings);
      for (std::size_t t = 0; t < batch.triangle_count(); ++t)
        for (int c = 0; c < 3; ++c)
          if (batch.vertex_index(t, c) == k) {
            p.primitives.push_back(t);
            break;
          }
    } else {
      evaluate_at(tes, r.tcs_out, primitive_id, p, r.num_varyings);
    }
    fill_dump_fields(p, r.dump_varyings, r.num_varyings);
    p.position = records[k].position;  // the executor's record itself
    p.normal = records[k].normal;
    return p;
  };
  if (request.vertex) {
    r.points.push_back(generated(*request.vertex));
  } else if (request.coord) {
    InspectPoint p;
    p.tess_coord = *request.coord;
    if (!request.coord_has_w)
      p.tess_coord.z = r.layout.domain == TessDomain::Triangles ? (1.0f - p.tess_coord.x) - p.tess_coord.y : 0.0f;
    check_coord(p.tess_coord, r.layout.domain, !request.coord_has_w && r.layout.domain == TessDomain::Triangles);
    for (std::size_t k = 0; k < records.size(); ++k)
      if (records[k].tess_coord == p.tess_coord) p.index = k;
    evaluate_at(tes, r.tcs_out, primitive_id, p, r.num_varyings);
    fill_dump_fields(p, r.dump_varyings, r.num_varyings);
    r.points.push_back(p);
  } else {
    for (std::size_t k = 0; k < records.size(); ++k) r.points.push_back(generated(k));
  }

  // ---- Source-level traces -------------------------------------------------------------------
  if (!request.trace || st.sources.empty()) return;
  auto source_of = [&](shader::Stage stage) -> const shader::ShaderSource* {
    for (const shader::ShaderSource& s : st.sources)
      if (s.stage == stage) return &s;
    return nullptr;  // no such stage (a draw without a TCS uses default levels)
  };
  try {
    if (const auto* src = source_of(shader::Stage::Vertex); src && (request.trace & kTraceVertex))
      for (std::size_t k = 0; k < r.corners.size(); ++k)
        r.traces.push_back(run_traced(*src, "corner " + std::to_string(k) + " = " + r.vertex_name + " " +
                                                std::to_string(r.corners[k].vertex),
                                      0, [&] { st.rerun_vertex(k); }));
    if (const auto* src = source_of(shader::Stage::TessControl); src && (request.trace & kTraceControl))
      for (int i = 0; i < r.tcs_vertices; ++i)
        r.traces.push_back(run_traced(*src, "invocation " + std::to_string(i), i, [&] {
          PatchOutput out = r.tcs_out;
          const Patch* in = &*tap.input;
          PatchOutput* o = &out;
          st.tcs.run_patches(&in, &o, 1);
        }));
    if (const auto* src = source_of(shader::Stage::TessEval);
        src && (request.trace & kTraceEvaluation) && r.points.size() == 1) {
      const glm::vec3 c = r.points[0].tess_coord;
      char at[96];
      std::snprintf(at, sizeof at, "gl_TessCoord (%.9g, %.9g, %.9g)", double(c.x), double(c.y), double(c.z));
      r.traces.push_back(run_traced(*src, at, 0, [&] {
        InspectPoint p = r.points[0];
        evaluate_at(tes, r.tcs_out, primitive_id, p, r.num_varyings);
      }));
    }
  } catch (const glsl::StageError& e) {
    throw InputError(st.source + ": " + e.what());
  }
}

void check_request(const InspectRequest& request) {
  if (request.coord && request.vertex)
    throw InputError("--coord and --vertex: give one of them (a coordinate, or a generated point's index)");
}

}  // namespace

InspectResult inspect_patch(const Scene& scene, const Mesh& mesh, const InspectRequest& request) {
  if (!scene.tessellation.enabled)
    throw InputError("inspect: the scene does not tessellate (tessellation.enabled is false)");
  check_request(request);
  InspectResult r;
  r.patch = request.patch;
  r.tessellator = scene.tessellation.tessellator;
  const Parallel serial(1);  // one patch: nothing to split, and the taps need one thread

  // ---- Vertex stage, over the mesh as the draw runs it --------------------------------------
  std::vector<StageVertex> shaded;
  std::span<const std::uint32_t> indices = mesh.indices;
  SceneProgram scene_program;
  const BuiltinFragmentProgram builtin_fs = builtin_fragment_program(scene);
  std::optional<BuiltinProgram> builtin;
  const DrawProgram* program = nullptr;
  std::vector<VertexAttribute> attributes;
  std::vector<shader::ShaderSource> sources;
  glm::vec4 default_outer(1.0f);
  glm::vec2 default_inner(1.0f);
  if (scene.shaders.program == ShaderProgram::Builtin) {
    std::vector<VertexTags> tags;
    if (scene.tessellation.scheme == SurfaceScheme::ScalarTaggedPN) tags = load_vertex_tags(scene.tessellation, mesh);
    builtin.emplace(scene_vertex_shader(scene), scene.tessellation, glm::vec2(float(scene.width), float(scene.height)),
                    builtin_fs.get(), std::move(tags));
    program = &*builtin;
    attributes = mesh_attributes(mesh);
    shaded.resize(mesh.vertex_count());
    const SurfaceScheme scheme = builtin->tess_programs().scheme;
    r.builtin_pn = scheme == SurfaceScheme::PN;
    r.builtin_quadratic = scheme == SurfaceScheme::Phong || scheme == SurfaceScheme::NLSA || scheme == SurfaceScheme::Nagata;
    r.program = scheme == SurfaceScheme::Flat
                    ? std::string("builtin flat")
                    : std::string("builtin ") + to_string(scheme) + " (" + to_string(scene.tessellation.normal_mode) + " normals)";
  } else {
    scene_program = build_scene_program(scene);
    program = scene_program.program.get();
    const DrawCall call = scene_draw_call(scene, mesh);
    r.patch_vertices = call.patch_vertices;
    default_outer = call.default_outer;
    default_inner = call.default_inner;
    shaded.resize(call.vertex_count);
    attributes = scene_attributes(scene, *scene_program.program, mesh);
    if (request.trace) sources = scene_sources(scene);
    r.program = scene.shaders.program == ShaderProgram::Twins ? "glsl twins (executor)" : "glsl custom (executor)";
  }
  try {
    program->run_vertices(attributes, 0, shaded.size(), 0, shaded.data(), serial);
  } catch (const glsl::StageError& e) {
    throw InputError(scene.source + ": " + e.what());
  }
  const auto tcs = program->control(r.patch_vertices, default_outer, default_inner);
  const auto tes = program->evaluation();

  const TessDrawInput input{shaded, indices, r.patch_vertices};
  r.patch_count = input.patch_count();
  if (request.patch >= r.patch_count)
    throw InputError("--patch: " + std::to_string(request.patch) + " is past the draw, which has " +
                     std::to_string(r.patch_count) + " patches (0.." + std::to_string(r.patch_count - 1) + ")");
  r.vertex_name = "mesh vertex";
  for (int k = 0; k < r.patch_vertices; ++k) {
    InspectCorner c;
    const std::size_t at = request.patch * std::size_t(r.patch_vertices) + std::size_t(k);
    c.vertex = indices.empty() ? std::uint32_t(at) : indices[at];
    if (c.vertex < mesh.vertex_count()) {
      c.in_position = mesh.positions[c.vertex];
      c.in_normal = mesh.normals[c.vertex];
    }
    if (c.vertex < shaded.size()) c.vs_out = shaded[c.vertex];
    if (builtin && c.vertex < shaded.size()) {  // shown on its own line, not among the TCS's inputs
      c.gl_position = shaded[c.vertex].attr[kAttrClipPosition];
      c.vs_out.attr[kAttrClipPosition] = glm::vec4(0.0f);
    }
    r.corners.push_back(c);
  }
  const PatchStages stages{scene.source, input, request.patch, *tcs, *tes,
                           scene.tessellation.tessellator, sources, [&](std::size_t k) {
                             StageVertex out;
                             program->run_vertices(attributes, r.corners[k].vertex, 1, 0, &out, serial);
                           }};
  inspect_stages(stages, request, r);
  if (request.trace && builtin) {
    Scene twins = scene;
    twins.shaders.program = ShaderProgram::Twins;
    r.traces = inspect_patch(twins, mesh, request).traces;
    r.traced_twins = true;
  }
  return r;
}

InspectResult inspect_draw_patch(const Scene& scene, const InspectRequest& request) {
  check_request(request);
  const std::size_t draw = request.draw.value_or(0);
  if (draw >= scene.draws.size())
    throw InputError("--draw: " + std::to_string(draw) + " is past the scene's " + std::to_string(scene.draws.size()) +
                     " draws (0.." + std::to_string(scene.draws.size() - 1) + ")");
  const DrawSetting& d = scene.draws[draw];
  if (d.mode != DrawMode::Patches)
    throw InputError("--draw: " + d.key + " draws untessellated primitives, not GL_PATCHES: --patch asks about a patch");
  const Parallel serial(1);
  SceneDraws draws(scene);
  InspectResult r;
  r.patch = request.patch;
  r.vertex_name = "gl_VertexID";
  const ShaderSettings& shaders = d.shaders ? *d.shaders : scene.shaders;
  r.program = shaders.program == ShaderProgram::Twins ? "glsl twins (executor)" : "glsl custom (executor)";
  bool found = false;
  draws.for_each_call(draw + 1, [&](const PreparedCall& p) {
    if (p.draw != draw) return;
    const DrawCall& call = p.call;
    const std::size_t per_instance = call.indices.size() / std::size_t(call.patch_vertices);
    const std::size_t here = per_instance * std::size_t(call.instances);
    if (found || request.patch >= r.patch_count + here) {
      r.patch_count += here;
      return;
    }
    found = true;
    const std::size_t local = request.patch - r.patch_count;
    r.patch_count += here;
    const int instance = int(local / per_instance);
    const std::size_t primitive = local % per_instance;
    r.draw = InspectDrawPatch{draw, p.call_index, instance, primitive,
                              call.first_patch_id + std::uint32_t(std::size_t(instance) * per_instance + primitive)};
    r.patch_vertices = call.patch_vertices;
    std::vector<glsl::VertexAttribute> attributes = p.attributes;
    if (call.instance_attributes) call.instance_attributes(instance, attributes);

    // The vertex shader at the patch's corners only: the stages after it read no other vertex.
    std::vector<StageVertex> shaded(call.vertex_count);
    std::vector<std::size_t> at(std::size_t(call.patch_vertices));  // corner k: position in the fetched vertices
    const auto run_corner = [&](std::size_t k, StageVertex& out) {
      p.program.run_vertices(attributes, at[k], 1, instance, &out, serial, call.vertex_ids.data() + at[k]);
    };
    for (std::size_t k = 0; k < at.size(); ++k) {
      at[k] = call.indices[primitive * at.size() + k];
      InspectCorner c;
      c.vertex = call.vertex_ids[at[k]];
      for (const glsl::VertexAttribute& a : attributes) {
        const std::size_t element = a.constant ? 0 : at[k];
        const std::size_t words = std::size_t(a.components);
        InspectInput in{a.location, a.scalar, {}};
        if ((element + 1) * words <= a.words.size())
          in.words.assign(a.words.begin() + std::ptrdiff_t(element * words), a.words.begin() + std::ptrdiff_t((element + 1) * words));
        c.inputs.push_back(std::move(in));
      }
      run_corner(k, shaded[at[k]]);
      c.vs_out = shaded[at[k]];
      r.corners.push_back(std::move(c));
    }
    const TessDrawInput input{shaded, call.indices, call.patch_vertices};
    const auto tcs = p.program.control(call.patch_vertices, call.default_outer, call.default_inner);
    const auto tes = p.program.evaluation();
    const std::vector<shader::ShaderSource> sources = request.trace ? draws.sources(draw) : std::vector<shader::ShaderSource>{};
    const PatchStages stages{scene.source, input, primitive, *tcs, *tes, TessOptions{}.tessellator, sources,
                             [&](std::size_t k) {
                               StageVertex out;
                               run_corner(k, out);
                             }};
    inspect_stages(stages, request, r);
  });
  if (!found)
    throw InputError("--patch: " + std::to_string(request.patch) + " is past " + d.key + ", which has " +
                     std::to_string(r.patch_count) + " patches" +
                     (r.patch_count ? " (0.." + std::to_string(r.patch_count - 1) + ", over its calls and instances)" : ""));
  return r;
}
}  // namespace tessref
