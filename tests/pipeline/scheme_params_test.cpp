// The quadratic schemes' scene keys (tessellation.scheme = phong | nlsa | nagata,
// tessellation.phong_alpha, tessellation.nagata_eps): defaults, and every bad value an error that
// names the key and the rule, from a scene file and from --set alike.
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "render/builtin_program.h"
#include "scene/scene_loader.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;

std::string scene_error(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse_scene(text, "scenes/x.json", ".", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SchemeParams, DefaultsAndNames) {
  const Scene s = load_scene("");
  EXPECT_EQ(s.tessellation.phong_alpha, 0.75f);
  EXPECT_EQ(s.tessellation.nagata_eps, 1e-4f);
  for (const char* name : {"flat", "pn", "phong", "nlsa", "nagata"}) {
    const Scene t = load_scene("", {std::string("tessellation.scheme=") + name});
    EXPECT_STREQ(to_string(t.tessellation.scheme), name);
  }
  const Scene t = parse_scene(R"({"tessellation": {"scheme": "nagata", "phong_alpha": 0.0, "nagata_eps": 0.5}})",
                              "x", ".");
  EXPECT_EQ(t.tessellation.scheme, SurfaceScheme::Nagata);
  EXPECT_EQ(t.tessellation.phong_alpha, 0.0f);
  EXPECT_EQ(t.tessellation.nagata_eps, 0.5f);
  EXPECT_THAT(scene_error(R"({"tessellation": {"scheme": "walton_meek"}})"),
              HasSubstr("scenes/x.json: tessellation.scheme: expected one of flat, pn, phong, nlsa, nagata"));
}

TEST(SchemeParams, NegativePhongAlpha) {
  const std::string rule =
      "must not be negative (0 is the flat triangle, 1 the full tangent-plane projection, 0.75 "
      "Boubekeur & Alexa's choice), got -0.5";
  EXPECT_EQ(scene_error(R"({"tessellation": {"phong_alpha": -0.5}})"),
            "scenes/x.json: tessellation.phong_alpha: " + rule);
  EXPECT_EQ(scene_error("{}", {"tessellation.phong_alpha=-0.5"}),
            "scenes/x.json: tessellation.phong_alpha: " + rule + " (from --set tessellation.phong_alpha)");
  EXPECT_EQ(scene_error("{}", {"tessellation.phong_alpha=nan"}),
            "scenes/x.json: tessellation.phong_alpha: expected a finite number, got nan (from --set "
            "tessellation.phong_alpha)");
  EXPECT_EQ(scene_error(R"({"tessellation": {"phong_alpha": "3/4"}})"),
            "scenes/x.json: tessellation.phong_alpha: expected a number, got a string (\"3/4\")");
  // Above 1 is allowed: the patch bulges further out (Boubekeur & Alexa's Figure 3 range).
  EXPECT_EQ(scene_error("{}", {"tessellation.phong_alpha=1.5"}), "");
}

TEST(SchemeParams, NagataEpsNaNNegativeOrAboveOneHalf) {
  const std::string rule =
      "must be in [0, 0.5] (an edge is left straight where (1 - n0.n1)/2 <= eps or (1 + n0.n1)/2 "
      "<= eps: 0 only for exactly parallel normals, 0.5 for every edge), got ";
  EXPECT_EQ(scene_error(R"({"tessellation": {"nagata_eps": -0.01}})"),
            "scenes/x.json: tessellation.nagata_eps: " + rule + "-0.01");
  EXPECT_EQ(scene_error("{}", {"tessellation.nagata_eps=-1e-6"}),
            "scenes/x.json: tessellation.nagata_eps: " + rule + "-1e-06 (from --set tessellation.nagata_eps)");
  EXPECT_EQ(scene_error("{}", {"tessellation.nagata_eps=0.6"}),
            "scenes/x.json: tessellation.nagata_eps: " + rule + "0.6 (from --set tessellation.nagata_eps)");
  EXPECT_EQ(scene_error("{}", {"tessellation.nagata_eps=nan"}),
            "scenes/x.json: tessellation.nagata_eps: expected a finite number, got nan (from --set "
            "tessellation.nagata_eps)");
  EXPECT_EQ(scene_error("{}", {"tessellation.nagata_eps=inf"}),
            "scenes/x.json: tessellation.nagata_eps: expected a finite number, got inf (from --set "
            "tessellation.nagata_eps)");
  EXPECT_EQ(scene_error("{}", {"tessellation.nagata_eps=0"}), "");
}

TEST(SchemeParams, BadValuesAreErrorsWhateverTheScheme) {
  // Checked where they enter, not when a scheme first reads them.
  EXPECT_THAT(scene_error("{}", {"tessellation.scheme=pn", "tessellation.phong_alpha=-1"}),
              HasSubstr("tessellation.phong_alpha: must not be negative"));
  EXPECT_THAT(scene_error("{}", {"tessellation.enabled=false", "tessellation.nagata_eps=-1"}),
              HasSubstr("tessellation.nagata_eps: must be in [0, 0.5]"));
}

TEST(SchemeParams, BuiltinProgramsTakeTheSchemeAndItsParameters) {
  const Scene s = load_scene("", {"tessellation.scheme=nagata", "tessellation.nagata_eps=0.02",
                                  "tessellation.phong_alpha=0.3", "tessellation.normal_mode=analytic"});
  const auto vs = scene_vertex_shader(s);
  const BuiltinTessPrograms p = builtin_tess_programs(s.tessellation, vs, glm::vec2(64.0f));
  EXPECT_EQ(&p.tcs(), &p.nagata_tcs);
  EXPECT_EQ(&p.scheme_tes(), &p.quadratic_tes);
  EXPECT_EQ(p.nagata_tcs.eps, 0.02f);
  EXPECT_EQ(p.phong_tcs.alpha, 0.3f);
  EXPECT_EQ(p.nagata_tcs.normal_mode, PnNormalMode::Analytic);
  EXPECT_EQ(p.quadratic_tes.normal_mode, PnNormalMode::Analytic);
  EXPECT_EQ(scheme_twins(SurfaceScheme::Phong).tess_control, std::string("phong.tesc"));
  EXPECT_EQ(scheme_twins(SurfaceScheme::NLSA).tess_evaluation, std::string("quadratic_patch.tese"));
}

}  // namespace
}  // namespace tessref
