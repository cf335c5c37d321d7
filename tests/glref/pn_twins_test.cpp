// The GLSL twins (transform.vert + flat / pn_triangles .tesc/.tese) run on the driver against the
// C++ programs run by tessref's executor: per TES invocation, the same patch, the same
// gl_TessCoord bits in the same order, and the same world position and normal up to rounding.
//
// Why positions and normals get a tolerance and tess coords do not: gl_TessCoord comes from the
// primitive generator, which tessref reproduces bit for bit (tpg_vs_llvmpipe_test). The shaders'
// arithmetic is compiled by LLVM, which may contract a * b + c into an FMA and evaluate matrix
// products in another association than glm, so the last bits of the VS/TCS/TES results differ.
// The tolerance is a few times the largest error measured over every case here (printed below).
#include <epoxy/gl.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "glref/patch_mesh.h"
#include "glref/pn_twins.h"
#include "glref/tess_capture.h"
#include "stages/programs/transform.h"
#include "stages/schemes/flat.h"
#include "stages/schemes/pn_triangles.h"
#include "stages/tess_stage.h"

namespace tessref::glref {
namespace {

// Max abs error allowed in world positions (|p| <= ~2.5 here) and unit normals, about 4x the
// largest measured over all 60 cases on llvmpipe (Mesa 22.3.6, LLVM 15): 3.6e-7 and 5.9e-7, a few
// ulps (the [ twins ] line this test prints). A wrong formula or term order is far above this.
constexpr float kPositionTolerance = 1.5e-6f;
constexpr float kNormalTolerance = 2.5e-6f;

// An octahedron split once (32 triangles) on an ellipsoid, with normals tilted off the surface
// normal so that the PN mid-edge terms and the quadratic/analytic fields all matter.
PatchMeshData test_mesh() {
  PatchMeshData d;
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                           {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  std::map<std::tuple<float, float, float>, std::uint32_t> index_of;
  const glm::vec3 radii(1.3f, 0.8f, 1.0f);
  auto vertex = [&](glm::vec3 dir) {
    dir = glm::normalize(dir);
    const auto key = std::make_tuple(dir.x, dir.y, dir.z);
    auto it = index_of.find(key);
    if (it != index_of.end()) return it->second;
    const glm::vec3 p = dir * radii;
    const glm::vec3 n = glm::normalize(p / (radii * radii) + 0.25f * glm::vec3(dir.y, dir.z, dir.x));
    d.positions.push_back(p);
    d.normals.push_back(n * (0.5f + 0.25f * float(d.positions.size() % 3)));  // not unit length
    return index_of[key] = static_cast<std::uint32_t>(d.positions.size() - 1);
  };
  for (const auto& f : faces) {
    const glm::vec3 a = axes[f[0]], b = axes[f[1]], c = axes[f[2]];
    const glm::vec3 ab = a + b, bc = b + c, ca = c + a;
    const std::uint32_t tri[4][3] = {{vertex(a), vertex(ab), vertex(ca)},
                                     {vertex(ab), vertex(b), vertex(bc)},
                                     {vertex(ca), vertex(bc), vertex(c)},
                                     {vertex(ab), vertex(bc), vertex(ca)}};
    for (const auto& t : tri) d.indices.insert(d.indices.end(), {t[0], t[1], t[2]});
  }
  return d;
}

enum class Levels { One, FiveHalf, Twelve, Adaptive };
const char* to_string(Levels l) {
  return l == Levels::One ? "1" : l == Levels::FiveHalf ? "5_5" : l == Levels::Twelve ? "12" : "adaptive";
}

// Scheme: -1 flat, else a PnNormalMode.
using Config = std::tuple<int, TessSpacing, Levels>;

TwinSetup setup_for(const Config& c) {
  const auto [scheme, spacing, levels] = c;
  TwinSetup s;
  s.pn = scheme >= 0;
  s.normal_mode = s.pn ? static_cast<PnNormalMode>(scheme) : PnNormalMode::Quadratic;
  s.layout = TessLayout{TessDomain::Triangles, spacing, TessWinding::Ccw, false};
  s.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, -0.2f, 0.1f)) *
            glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f))) *
            glm::scale(glm::mat4(1.0f), glm::vec3(1.1f, 0.9f, 1.4f));
  s.view_proj = glm::perspective(glm::radians(40.0f), 1.0f, 0.5f, 20.0f) *
                glm::lookAt(glm::vec3(1.0f, 2.0f, -6.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  const float level = levels == Levels::One ? 1.0f : levels == Levels::FiveHalf ? 5.5f : 12.0f;
  s.levels = TessLevelSettings::uniform(level, level);
  if (levels == Levels::Adaptive) {
    s.levels.adaptive = true;
    s.levels.screen.view_proj = s.view_proj;
    s.levels.screen.viewport_pixels = glm::vec2(300.0f, 300.0f);
    s.levels.screen.pixels_per_segment = 7.0f;  // 43..205 domain points per patch here
  }
  return s;
}

struct Reference {
  std::vector<TessDumpRecord> records;  // generation order
  TriangleBatch batch;                  // emission order
  TessStats stats;
  std::vector<std::size_t> point_bounds;
};

Reference run_tessref(const PatchMeshData& mesh, const TwinSetup& s) {
  const auto vs = programs::TransformVertexShader::from(s.model, s.view_proj);
  std::vector<StageVertex> cp(mesh.positions.size());
  for (std::size_t i = 0; i < cp.size(); ++i) {
    const programs::VertexOut v = vs.main(mesh.positions[i], mesh.normals[i]);
    cp[i].attr[kAttrPosition] = glm::vec4(v.v_world_position, 1.0f);
    cp[i].attr[kAttrNormal] = glm::vec4(v.v_world_normal, 0.0f);
  }
  PnTcs pn_tcs;
  pn_tcs.normal_mode = s.normal_mode;
  pn_tcs.levels = s.levels;
  PnTes pn_tes;
  pn_tes.normal_mode = s.normal_mode;
  pn_tes.spacing = s.layout.spacing;
  pn_tes.view_proj = s.view_proj;
  PassThroughTcs flat_tcs;
  flat_tcs.levels = s.levels;
  FlatTes flat_tes;
  flat_tes.tess_layout = s.layout;
  flat_tes.view_proj = s.view_proj;
  const TessControlProgram& tcs = s.pn ? static_cast<const TessControlProgram&>(pn_tcs) : flat_tcs;
  const TessEvalProgram& tes = s.pn ? static_cast<const TessEvalProgram&>(pn_tes) : flat_tes;

  Reference r;
  TessOptions options;
  options.dump = &r.records;
  const TessDrawInput input{cp, mesh.indices, 3};
  r.stats = tessellate(input, 0, input.patch_count(), tcs, tes, options, Parallel(1), r.batch);
  r.batch = expand_indices(r.batch);  // corners in emission order, as GL captures them
  // Bounds for splitting the GL draws, from the levels alone (not from tessref's output).
  for (std::size_t p = 0; p < input.patch_count(); ++p) {
    const glm::vec3 a(cp[mesh.indices[3 * p]].attr[0]), b(cp[mesh.indices[3 * p + 1]].attr[0]),
        c(cp[mesh.indices[3 * p + 2]].attr[0]);
    r.point_bounds.push_back(domain_point_bound(s.layout, triangle_levels(s.levels, a, b, c)));
  }
  return r;
}

struct GlVertex {
  glm::vec3 position, normal, coord;
  std::uint32_t patch;
};
std::vector<GlVertex> unpack(const std::vector<std::uint32_t>& words) {
  std::vector<GlVertex> out(words.size() / 10);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::uint32_t* w = &words[i * 10];
    std::memcpy(&out[i].position, w, 12);
    std::memcpy(&out[i].normal, w + 3, 12);
    std::memcpy(&out[i].coord, w + 6, 12);
    out[i].patch = w[9];
  }
  return out;
}

bool same_bits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }
float max_abs(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z});
}
glm::vec3 varying3(const ClipVertex& v, int at) { return {v.varyings[at], v.varyings[at + 1], v.varyings[at + 2]}; }

// Largest errors over every case, for the summary line.
float g_max_position_error = 0.0f, g_max_normal_error = 0.0f;

class PnTwins : public ::testing::TestWithParam<Config> {};

TEST_P(PnTwins, MatchTessrefsExecutor) {
  TESSREF_REQUIRE_GL(ctx);
  const PatchMeshData data = test_mesh();
  ASSERT_EQ(data.indices.size(), 32u * 3);
  PatchMesh mesh(*ctx, data);
  const TwinSetup setup = setup_for(GetParam());
  const Reference ref = run_tessref(data, setup);
  ASSERT_GT(ref.records.size(), 0u);
  ASSERT_EQ(ref.stats.domain_points, ref.records.size());
  if (std::get<2>(GetParam()) == Levels::Adaptive) {
    // The adaptive cases must really vary the levels from patch to patch.
    std::vector<std::size_t> per_patch(data.indices.size() / 3, 0);
    for (const TessDumpRecord& r : ref.records) ++per_patch[r.patch_id];
    const auto [lo, hi] = std::minmax_element(per_patch.begin(), per_patch.end());
    EXPECT_GE(*hi, 3 * *lo) << "domain points per patch " << *lo << ".." << *hi;
  }

  float pos_err = 0.0f, nrm_err = 0.0f;

  // Point mode: one TES invocation per record, in generation order, the sequence tessref dumps.
  {
    TwinSetup points = setup;
    points.layout.point_mode = true;
    Program program = link_twin_program(points, TwinCapture::Full);
    set_twin_uniforms(program, points);
    const std::vector<GlVertex> gl = unpack(mesh.capture(program, 10, GL_POINTS, ref.point_bounds));
    ASSERT_EQ(gl.size(), ref.records.size());
    for (std::size_t i = 0; i < gl.size(); ++i) {
      const TessDumpRecord& r = ref.records[i];
      ASSERT_EQ(gl[i].patch, r.patch_id) << "record " << i;
      ASSERT_TRUE(same_bits(gl[i].coord, r.tess_coord))
          << "record " << i << ": gl (" << gl[i].coord.x << ", " << gl[i].coord.y << ", " << gl[i].coord.z
          << ") tessref (" << r.tess_coord.x << ", " << r.tess_coord.y << ", " << r.tess_coord.z << ")";
      pos_err = std::max(pos_err, max_abs(gl[i].position, r.position));
      nrm_err = std::max(nrm_err, max_abs(gl[i].normal, r.normal));
    }
  }

  // Triangles, as drawn: the same emitted vertices in the same order as tessref's batch. Each GL
  // vertex's (patch, coord) must name one of tessref's records, and that record must be the one
  // tessref emitted at the same place (its varyings are copied bit for bit into the batch).
  {
    Program program = link_twin_program(setup, TwinCapture::Full);
    set_twin_uniforms(program, setup);
    const std::vector<GlVertex> gl = unpack(mesh.capture(program, 10, GL_TRIANGLES, ref.point_bounds));
    ASSERT_EQ(gl.size(), ref.batch.vertices.size());
    ASSERT_EQ(gl.size(), ref.stats.triangles_out * 3);
    std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>, std::size_t> by_coord;
    for (std::size_t i = 0; i < ref.records.size(); ++i) {
      const glm::vec3& c = ref.records[i].tess_coord;
      by_coord.emplace(std::make_tuple(ref.records[i].patch_id, std::bit_cast<std::uint32_t>(c.x),
                                       std::bit_cast<std::uint32_t>(c.y), std::bit_cast<std::uint32_t>(c.z)),
                       i);
    }
    for (std::size_t k = 0; k < gl.size(); ++k) {
      const auto it = by_coord.find(std::make_tuple(gl[k].patch, std::bit_cast<std::uint32_t>(gl[k].coord.x),
                                                    std::bit_cast<std::uint32_t>(gl[k].coord.y),
                                                    std::bit_cast<std::uint32_t>(gl[k].coord.z)));
      ASSERT_NE(it, by_coord.end()) << "emitted vertex " << k << " has a tess coord tessref never generated";
      const TessDumpRecord& r = ref.records[it->second];
      const ClipVertex& ours = ref.batch.vertices[k];
      ASSERT_TRUE(same_bits(varying3(ours, kVaryingPosition), r.position) &&
                  same_bits(varying3(ours, kVaryingNormal), r.normal))
          << "emitted vertex " << k << ": tessref emitted another domain point here";
      pos_err = std::max(pos_err, max_abs(gl[k].position, r.position));
      nrm_err = std::max(nrm_err, max_abs(gl[k].normal, r.normal));
    }
  }

  g_max_position_error = std::max(g_max_position_error, pos_err);
  g_max_normal_error = std::max(g_max_normal_error, nrm_err);
  RecordProperty("max_position_error", std::to_string(pos_err));
  RecordProperty("max_normal_error", std::to_string(nrm_err));
  EXPECT_LE(pos_err, kPositionTolerance);
  EXPECT_LE(nrm_err, kNormalTolerance);
}

// The tolerances separate right from wrong: the twins run with quadratic normals against tessref
// with quadratic_corrected (same positions, mid-edge normals scaled differently) are far outside.
TEST(PnTwinsControl, ToleranceCatchesAnotherNormalField) {
  TESSREF_REQUIRE_GL(ctx);
  const PatchMeshData data = test_mesh();
  PatchMesh mesh(*ctx, data);
  TwinSetup gl_setup = setup_for({int(PnNormalMode::Quadratic), TessSpacing::FractionalOdd, Levels::FiveHalf});
  gl_setup.layout.point_mode = true;
  TwinSetup ours = gl_setup;
  ours.normal_mode = PnNormalMode::QuadraticCorrected;
  const Reference ref = run_tessref(data, ours);
  Program program = link_twin_program(gl_setup, TwinCapture::Full);
  set_twin_uniforms(program, gl_setup);
  const std::vector<GlVertex> gl = unpack(mesh.capture(program, 10, GL_POINTS, ref.point_bounds));
  ASSERT_EQ(gl.size(), ref.records.size());
  float pos_err = 0.0f, nrm_err = 0.0f;
  for (std::size_t i = 0; i < gl.size(); ++i) {
    pos_err = std::max(pos_err, max_abs(gl[i].position, ref.records[i].position));
    nrm_err = std::max(nrm_err, max_abs(gl[i].normal, ref.records[i].normal));
  }
  EXPECT_LE(pos_err, kPositionTolerance);
  EXPECT_GT(nrm_err, 100.0f * kNormalTolerance);
  RecordProperty("normal_error_other_mode", std::to_string(nrm_err));
}

std::string config_name(const ::testing::TestParamInfo<Config>& info) {
  const auto [scheme, spacing, levels] = info.param;
  const std::string s = scheme < 0 ? "flat" : std::string("pn_") + to_string(static_cast<PnNormalMode>(scheme));
  return s + "_" + tessref::to_string(spacing) + "_" + to_string(levels);
}

INSTANTIATE_TEST_SUITE_P(
    FlatAndPn, PnTwins,
    ::testing::Combine(::testing::Values(-1, int(PnNormalMode::Linear), int(PnNormalMode::Quadratic),
                                         int(PnNormalMode::QuadraticCorrected), int(PnNormalMode::Analytic)),
                       ::testing::Values(TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven),
                       ::testing::Values(Levels::One, Levels::FiveHalf, Levels::Twelve, Levels::Adaptive)),
    config_name);

// Prints the largest errors seen, which is what the tolerances above were set from.
class ErrorSummary : public ::testing::Environment {
 public:
  void TearDown() override {
    if (g_max_position_error > 0.0f || g_max_normal_error > 0.0f)
      std::printf("[ twins ] max |position error| %.3g (tolerance %.3g), max |normal error| %.3g (tolerance %.3g)\n",
                  g_max_position_error, kPositionTolerance, g_max_normal_error, kNormalTolerance);
  }
};
const auto* const kSummary = ::testing::AddGlobalTestEnvironment(new ErrorSummary);

}  // namespace
}  // namespace tessref::glref
