// PN triangles (quadratic normals, fractional_odd, levels 12 and 64) on a 320-triangle icosphere:
// tessellated vertices per second, tessref's executor against Mesa llvmpipe running the GLSL twins
// (transform.vert + pn_triangles.tesc/.tese), measured in the same process.
//
// "Vertices" are TES invocations, i.e. distinct domain points (tessref's TessStats::domain_points;
// llvmpipe evaluates each domain point of a patch once too). The same count is credited to both
// sides, position + normal computed for each.
//   tessref:  tessellate_chunks (PnTcs/PnTes; 256 patches per chunk like the pipeline, and 16),
//             all threads, consume = count triangles only.
//   llvmpipe: capture = PatchMesh::capture of position + normal by transform feedback (rasterizer
//             discard; includes reading the ~2 emitted vertices per point back);
//             discard = PatchMesh::draw with rasterizer discard and a GL_PRIMITIVES_GENERATED
//             query, nothing captured (llvmpipe still runs VS/TCS/TPG/TES on one thread);
//             the flat twins under the same conditions give llvmpipe's floor without PN's TES.
//   executor: the same GLSL twins (transform.vert + pn_triangles.tesc/.tese, normals.frag to make
//             a whole program) on tessref's SPIR-V executor, through tessellate_chunks exactly as
//             BM_TessrefPn (same control points, chunks and options), at batch_lanes 64 and 1
//             (one invocation at a time).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "common/parallel.h"
#include "mesh/procedural.h"
#include "shader/glsl_compile.h"
#include "stages/glsl/glsl_program.h"
#include "stages/glsl/twins.h"
#include "stages/programs/transform.h"
#include "stages/schemes/pn_triangles.h"
#include "stages/tess_stage.h"
#include "bench_common.h"
#ifdef TESSREF_HAVE_GLREF
#include <epoxy/gl.h>

#include "glref/gl_context.h"
#include "glref/patch_mesh.h"
#include "glref/pn_twins.h"
#include "glref/tess_capture.h"
#endif

namespace {

using namespace tessref;

constexpr int kRefinements = 2;  // 320 triangles
constexpr TessLayout kLayout{TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw, false};

// Patches per parallel task as the pipeline sizes them (draw.cpp: about 4,096 triangles a task),
// so that a 16-patch chunk at level 64 still spreads over the threads.
TessOptions task_options(float level) {
  TessOptions o;
  const std::size_t per_patch = std::max<std::size_t>(
      1, generate_tessellation(kLayout, TessLevelSettings::uniform(level, level).constant).primitive_count());
  o.patches_per_task = std::clamp<std::size_t>(4096 / per_patch, 1, 64);
  return o;
}

const Mesh& mesh() {
  static const Mesh m = make_icosphere(kRefinements);
  return m;
}

// Control points = the vertex shader's outputs with an identity model (the twins get the same).
const std::vector<StageVertex>& control_points() {
  static const std::vector<StageVertex> cp = [] {
    const auto vs = programs::TransformVertexShader::from(glm::mat4(1.0f), glm::mat4(1.0f));
    std::vector<StageVertex> out(mesh().positions.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      const programs::VertexOut v = vs.main(mesh().positions[i], mesh().normals[i]);
      out[i].attr[kAttrPosition] = glm::vec4(v.v_world_position, 1.0f);
      out[i].attr[kAttrNormal] = glm::vec4(v.v_world_normal, 0.0f);
    }
    return out;
  }();
  return cp;
}

const Parallel& parallel() {
  static const Parallel p(0);
  return p;
}

struct Tessref {
  PnTcs tcs;
  PnTes tes;
  std::size_t chunk;
  float level;
  Tessref(float level, std::size_t chunk_patches) : chunk(chunk_patches), level(level) {
    tcs.normal_mode = PnNormalMode::Quadratic;
    tcs.levels = TessLevelSettings::uniform(level, level);
    tes.normal_mode = PnNormalMode::Quadratic;
    tes.spacing = kLayout.spacing;
  }
  TessStats run(std::size_t& triangles) const {
    const TessDrawInput input{control_points(), mesh().indices, 3};
    return tessellate_chunks(input, chunk, tcs, tes, task_options(level), parallel(),
                             [&](const TriangleBatch& b) { triangles += b.triangle_count(); });
  }
};

// One draw of the whole mesh by tessref: its domain points are the count credited to both sides.
TessStats reference_stats(float level) {
  std::size_t triangles = 0;
  return Tessref(level, 16).run(triangles);
}

// Second argument: patches per chunk. 256 is the pipeline's default (DrawOptions); at level 64 a
// chunk's batch is then ~290 MB (256 x 5,953 triangles x 3 x 64-byte vertices) plus the tasks'
// buffers, allocated afresh by every tessellate_chunks call, so 16 is measured beside it.
// The benchmark loop over draws (TessStats draw(std::size_t& triangles)) and its rate counters.
template <class Draw>
void measure(benchmark::State& state, const Draw& draw) {
  std::uint64_t points = 0;
  std::size_t triangles = 0;
  TessStats last;
  for (auto _ : state) {
    last = draw(triangles);
    points += last.domain_points;
  }
  bench::set_work_counters(state, bench::work::pn_tessellation(last.domain_points, last.triangles_out));
  state.counters["vertices_per_s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
  state.counters["triangles_per_s"] = benchmark::Counter(double(triangles), benchmark::Counter::kIsRate);
  state.counters["threads"] = parallel().threads();
}

void BM_TessrefPn(benchmark::State& state) {
  const Tessref t(float(state.range(0)), std::size_t(state.range(1)));
  measure(state, [&](std::size_t& triangles) { return t.run(triangles); });
}
BENCHMARK(BM_TessrefPn)->ArgsProduct({{12, 64}, {256, 16}})->Unit(benchmark::kMillisecond)->UseRealTime();

// The GLSL twins compiled once (glslang + SPIR-V); each benchmark builds its GlslProgram from them.
const shader::CompiledProgram& twins_compiled() {
  static const shader::CompiledProgram p = [] {
    std::vector<shader::ShaderSource> sources;
    for (const auto& [stage, name] : {std::pair{shader::Stage::Vertex, "transform.vert"},
                                      std::pair{shader::Stage::TessControl, "pn_triangles.tesc"},
                                      std::pair{shader::Stage::TessEval, "pn_triangles.tese"},
                                      std::pair{shader::Stage::Fragment, "normals.frag"}})
      sources.push_back({stage, name, 1, glsl::twin_source(name)});
    return shader::compile_program(sources);
  }();
  return p;
}

glsl::UniformValue uniform_floats(const float* p, int columns, int rows) {
  glsl::UniformValue u;
  u.columns = columns;
  u.rows = rows;
  for (int i = 0; i < columns * rows; ++i) u.words.push_back(std::bit_cast<std::uint32_t>(p[i]));
  return u;
}
glsl::UniformValue uniform_int(int v, shader::Scalar s = shader::Scalar::I32) {
  glsl::UniformValue u;
  u.scalar = s;
  u.words.push_back(std::uint32_t(v));
  return u;
}

// The twins on the executor: the same draw as Tessref. Control points: the twins' vertex stage
// (transform.vert, identity matrices) run on the mesh, so world position and normal sit in I/O
// slots 1 and 2 (locations 0 and 1; slot 0 is gl_Position), where the twins' TCS reads them; they
// are checked bit for bit against Tessref's control points.
struct Executor {
  std::unique_ptr<glsl::GlslProgram> program;
  std::shared_ptr<const TessControlProgram> tcs;
  std::shared_ptr<const TessEvalProgram> tes;
  std::vector<StageVertex> cp;
  std::size_t chunk;
  float level;
  Executor(float level, std::size_t chunk_patches, int batch_lanes) : chunk(chunk_patches), level(level) {
    shader::ExecLimits limits;
    limits.batch_lanes = batch_lanes;
    program = std::make_unique<glsl::GlslProgram>(twins_compiled(), limits);
    program->override_tes_layout(kLayout);
    // The uniforms the twins declare, with the values Tessref gives PnTcs/PnTes (set_scene_uniforms
    // in render/glsl_scene.cpp names them all); the adaptive-level ones are unused (u_adaptive false).
    const std::vector<std::string> names = program->uniform_names();
    auto set = [&](const std::string& name, const glsl::UniformValue& v) {
      if (std::binary_search(names.begin(), names.end(), name)) program->set_uniform(name, v);
    };
    const auto vs = programs::TransformVertexShader::from(glm::mat4(1.0f), glm::mat4(1.0f));
    const PnTes reference;  // its view_proj, the matrix Tessref's PnTes uses
    const TessLevelSettings levels = TessLevelSettings::uniform(level, level);
    const AdaptiveLevelSettings screen;
    set("u_model", uniform_floats(&vs.u_model[0][0], 4, 4));
    set("u_view_projection", uniform_floats(&vs.u_view_projection[0][0], 4, 4));
    set("u_normal_matrix", uniform_floats(&vs.u_normal_matrix[0][0], 3, 3));
    set("u_view_proj", uniform_floats(&reference.view_proj[0][0], 4, 4));
    set("u_normal_mode", uniform_int(1));  // quadratic
    set("u_adaptive", uniform_int(0, shader::Scalar::Bool));
    set("u_outer", uniform_floats(levels.constant.outer.data(), 1, 4));
    set("u_inner", uniform_floats(levels.constant.inner.data(), 1, 2));
    set("u_viewport", uniform_floats(&screen.viewport_pixels[0], 1, 2));
    set("u_pixels_per_segment", uniform_floats(&screen.pixels_per_segment, 1, 1));
    set("u_min_level", uniform_floats(&screen.min_level, 1, 1));
    set("u_max_level", uniform_floats(&screen.max_level, 1, 1));
    set("u_inner_rule", uniform_int(screen.inner_rule == InnerLevelRule::Max ? 0 : 1));
    tcs = program->control(3, glm::vec4(level), glm::vec2(level));
    tes = program->evaluation();

    std::vector<glsl::VertexAttribute> attributes;
    for (const auto& [input, data] : {std::pair{"in_position", &mesh().positions}, std::pair{"in_normal", &mesh().normals}}) {
      glsl::VertexAttribute a;
      a.location = program->attribute_location(input).value();
      a.components = 3;
      for (const glm::vec3& v : *data)
        for (int c = 0; c < 3; ++c) a.words.push_back(std::bit_cast<std::uint32_t>(v[c]));
      attributes.push_back(std::move(a));
    }
    cp.resize(mesh().positions.size());
    program->run_vertices(attributes, 0, cp.size(), 0, cp.data(), parallel());
  }
  // Whether the executor's control points are Tessref's (xyz of position and normal, bit for bit).
  bool same_control_points() const {
    const std::vector<StageVertex>& ref = control_points();
    for (std::size_t i = 0; i < cp.size(); ++i)
      if (std::memcmp(&cp[i].attr[1], &ref[i].attr[kAttrPosition], 12) != 0 ||
          std::memcmp(&cp[i].attr[2], &ref[i].attr[kAttrNormal], 12) != 0)
        return false;
    return true;
  }
  TessStats run(std::size_t& triangles) const {
    const TessDrawInput input{cp, mesh().indices, 3};
    return tessellate_chunks(input, chunk, *tcs, *tes, task_options(level), parallel(),
                             [&](const TriangleBatch& b) { triangles += b.triangle_count(); });
  }
};

// Arguments: level, patches per chunk, batch_lanes (64: the executor's batch; 1: one invocation
// at a time). One untimed draw first checks the control points and that the domain-point and
// triangle counts are those of the C++ programs (the label gives them).
void BM_ExecutorPn(benchmark::State& state) {
  const float level = float(state.range(0));
  const Executor e(level, std::size_t(state.range(1)), int(state.range(2)));
  if (!e.same_control_points()) return state.SkipWithError("the twins' vertex stage gave other control points");
  const TessStats expected = reference_stats(level);
  std::size_t check_triangles = 0;
  const TessStats check = e.run(check_triangles);
  if (check.domain_points != expected.domain_points || check.triangles_out != expected.triangles_out ||
      check_triangles != expected.triangles_out)
    return state.SkipWithError(("executor: " + std::to_string(check.domain_points) + " points, " +
                                std::to_string(check.triangles_out) + " triangles; C++ programs: " +
                                std::to_string(expected.domain_points) + ", " +
                                std::to_string(expected.triangles_out))
                                   .c_str());
  state.SetLabel(std::to_string(check.domain_points) + " points, " + std::to_string(check.triangles_out) +
                 " triangles per draw (= C++ programs)");
  measure(state, [&](std::size_t& triangles) { return e.run(triangles); });
  state.counters["points_per_draw"] = double(check.domain_points);
  state.counters["triangles_per_draw"] = double(check.triangles_out);
  state.counters["batch_lanes"] = double(state.range(2));
}
BENCHMARK(BM_ExecutorPn)
    ->ArgsProduct({{12, 64}, {256, 16}, {256, 64, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

#ifdef TESSREF_HAVE_GLREF

struct Llvmpipe {
  std::unique_ptr<glref::PatchMesh> patch_mesh;
  glref::Program program;
  std::vector<std::size_t> bounds;
  Llvmpipe(glref::GlContext& ctx, float level, glref::TwinCapture capture, bool pn = true) {
    glref::PatchMeshData data;
    data.positions = mesh().positions;
    data.normals = mesh().normals;
    data.indices = mesh().indices;
    patch_mesh = std::make_unique<glref::PatchMesh>(ctx, data);
    glref::TwinSetup setup;
    setup.pn = pn;
    setup.normal_mode = PnNormalMode::Quadratic;
    setup.layout = kLayout;
    setup.levels = TessLevelSettings::uniform(level, level);
    program = glref::link_twin_program(setup, capture);
    glref::set_twin_uniforms(program, setup);
    bounds.assign(patch_mesh->patch_count(), glref::domain_point_bound(kLayout, setup.levels.constant));
  }
};

void BM_LlvmpipePnCapture(benchmark::State& state) {
  glref::GlContext* ctx = bench::gl_context();
  if (!ctx) return state.SkipWithError("no GL context");
  const float level = float(state.range(0));
  Llvmpipe gl(*ctx, level, glref::TwinCapture::PositionNormal);
  const TessStats expected = reference_stats(level);
  const std::uint64_t per_draw = expected.domain_points;
  bench::set_work_counters(state, bench::work::pn_tessellation(per_draw, expected.triangles_out));
  std::uint64_t points = 0, captured = 0;
  for (auto _ : state) {
    const std::vector<std::uint32_t> words = gl.patch_mesh->capture(gl.program, 6, GL_TRIANGLES, gl.bounds);
    benchmark::DoNotOptimize(words.data());
    points += per_draw;
    captured += words.size() / 6;
  }
  state.counters["vertices_per_s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
  state.counters["captured_per_s"] = benchmark::Counter(double(captured), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LlvmpipePnCapture)->Arg(12)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();

// Rasterizer discard: nothing is read back; the primitives-generated query both waits for the
// draws and checks the triangle count against tessref's. pn = false runs the flat twins on
// the same patches: the floor set by llvmpipe's VS/TCS/tessellator/assembly, without PN's TES.
void llvmpipe_discard(benchmark::State& state, bool pn) {
  glref::GlContext* ctx = bench::gl_context();
  if (!ctx) return state.SkipWithError("no GL context");
  const float level = float(state.range(0));
  Llvmpipe gl(*ctx, level, glref::TwinCapture::None, pn);
  const TessStats expected = reference_stats(level);
  const std::uint64_t per_draw = expected.domain_points;
  bench::set_work_counters(state, bench::work::pn_tessellation(per_draw, expected.triangles_out));
  unsigned query = 0;
  glGenQueries(1, &query);
  std::uint64_t points = 0, triangles = 0;
  for (auto _ : state) {
    ctx->bind_default_framebuffer();
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginQuery(GL_PRIMITIVES_GENERATED, query);
    gl.patch_mesh->draw(gl.program, gl.bounds);
    glEndQuery(GL_PRIMITIVES_GENERATED);
    GLuint64 generated = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &generated);  // waits for the draws
    glDisable(GL_RASTERIZER_DISCARD);
    if (generated != expected.triangles_out) {
      glDeleteQueries(1, &query);
      return state.SkipWithError("llvmpipe generated another triangle count than tessref");
    }
    points += per_draw;
    triangles += generated;
  }
  glDeleteQueries(1, &query);
  state.counters["vertices_per_s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
  state.counters["triangles_per_s"] = benchmark::Counter(double(triangles), benchmark::Counter::kIsRate);
}
void BM_LlvmpipePnDiscard(benchmark::State& state) { llvmpipe_discard(state, true); }
void BM_LlvmpipeFlatDiscard(benchmark::State& state) { llvmpipe_discard(state, false); }
BENCHMARK(BM_LlvmpipeFlatDiscard)->Arg(12)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LlvmpipePnDiscard)->Arg(12)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

// Collects vertices_per_s per (benchmark, level) to print the ratios at the end.
class RatioReporter : public bench::RateReporter {
 public:
  RatioReporter() : RateReporter("vertices_per_s") {}
  void print_ratios() const {
    std::printf("\nPN quadratic, fractional_odd, icosphere %zu triangles; Mvertices/s (TES invocations)\n",
                mesh().indices.size() / 3);
    std::printf("level  chunk  tessref  llvmpipe capture  ratio  llvmpipe discard  ratio\n");
    for (int level : {12, 64}) {
      const std::string l = "/" + std::to_string(level) + "/real_time";
      const double c = rate("BM_LlvmpipePnCapture" + l), d = rate("BM_LlvmpipePnDiscard" + l);
      for (int chunk : {256, 16}) {
        const double t = rate("BM_TessrefPn/" + std::to_string(level) + "/" + std::to_string(chunk) + "/real_time");
        if (t == 0.0) continue;
        std::printf("%5d  %5d  %7.2f", level, chunk, t / 1e6);
        for (double g : {c, d}) {
          if (g > 0.0) std::printf("  %16.2f  %4.1fx", g / 1e6, t / g);
          else std::printf("  %16s  %5s", "n/a", "n/a");
        }
        std::printf("\n");
      }
    }
    bool header = false;
    for (int level : {12, 64})
      for (int chunk : {256, 16}) {
        const std::string lc = std::to_string(level) + "/" + std::to_string(chunk);
        const double e64 = rate("BM_ExecutorPn/" + lc + "/64/real_time"), e1 = rate("BM_ExecutorPn/" + lc + "/1/real_time");
        if (e64 == 0.0 && e1 == 0.0) continue;
        if (!header) {
          std::printf("\nGLSL twins on the executor (Mvertices/s) and ratios of batch 64 to the others\n");
          std::printf("level  chunk  batch 64  batch 1  C++ programs  llvmpipe discard  /llvmpipe  /C++  /batch 1\n");
          header = true;
        }
        const double t = rate("BM_TessrefPn/" + lc + "/real_time");
        const double d = rate("BM_LlvmpipePnDiscard/" + std::to_string(level) + "/real_time");
        auto text = [](const char* f, double v) {
          char buf[32];
          std::snprintf(buf, sizeof buf, f, v);
          return std::string(buf);
        };
        auto mv = [&](double r) { return r > 0.0 ? text("%.2f", r / 1e6) : std::string("n/a"); };
        auto q = [&](double r) { return e64 > 0.0 && r > 0.0 ? text("%.2fx", e64 / r) : std::string("n/a"); };
        std::printf("%5d  %5d  %8s  %7s  %12s  %16s  %9s  %5s  %8s\n", level, chunk, mv(e64).c_str(), mv(e1).c_str(),
                    mv(t).c_str(), mv(d).c_str(), q(d).c_str(), q(t).c_str(), q(e1).c_str());
      }
    for (int level : {12, 64}) {
      const double f = rate("BM_LlvmpipeFlatDiscard/" + std::to_string(level) + "/real_time");
      if (f > 0.0) std::printf("level %d, llvmpipe flat twins, discard (no PN): %.2f Mvertices/s\n", level, f / 1e6);
    }
  }
};

}  // namespace

int main(int argc, char** argv) { return tessref::bench::run_benchmarks<RatioReporter>(argc, argv); }
