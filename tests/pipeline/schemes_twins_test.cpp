// The quadratic schemes' GLSL twins (phong.tesc, nlsa.tesc, nagata.tesc, quadratic_patch.tese) on
// tessref's executor against the C++ programs they mirror (shaders.program = twins against
// builtin): the same coverage, colours within 1/255, and the same gl_TessCoord, positions and
// normals bit for bit, in every normal mode, with the schemes' parameters set off default and
// with tessellation.displacement on top.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "twins_test_util.h"

namespace tessref {
namespace {

void expect_twins_match(const std::vector<std::string>& sets, const std::string& what) {
  const test::Frame cpp = test::render(sets);
  const test::Frame twins = test::render(test::with(sets, "shaders.program=twins"));
  test::expect_equivalent(cpp, twins, what);
  test::expect_same_dump(cpp, twins, what);
}

TEST(SchemeTwins, MatchTheCppProgramsInEveryNormalMode) {
  for (const char* scheme : {"phong", "nlsa", "nagata"})
    for (const char* mode : {"linear", "quadratic", "quadratic_corrected", "analytic"}) {
      const std::vector<std::string> sets = {std::string("tessellation.scheme=") + scheme,
                                             std::string("tessellation.normal_mode=") + mode};
      expect_twins_match(sets, std::string(scheme) + " " + mode);
    }
}

TEST(SchemeTwins, MatchWithTheirParametersAndOtherLayouts) {
  const std::vector<std::vector<std::string>> cases = {
      {"tessellation.scheme=phong", "tessellation.phong_alpha=0.3"},
      {"tessellation.scheme=phong", "tessellation.phong_alpha=1.4", "tessellation.spacing=equal",
       "tessellation.winding=cw", "cull_back_faces=false"},
      {"tessellation.scheme=nagata", "tessellation.nagata_eps=0"},
      // 0.04 (seed 004's head model) straightens the torus's 22.5-degree edges: the cut taken.
      {"tessellation.scheme=nagata", "tessellation.nagata_eps=0.04", "tessellation.adaptive.enabled=true"},
      {"tessellation.scheme=nlsa", "mesh.type=icosphere", "tessellation.spacing=fractional_even",
       "tessellation.inner=5.5", "tessellation.outer=3.2", "shading=normals"},
      {"tessellation.scheme=nagata", "mesh.type=cube", "tessellation.normal_mode=analytic"},
      // quadratic_patch.tese carries the displacement block of the other evaluation twins.
      {"tessellation.scheme=phong", R"(tessellation.displacement={"amplitude": 0.03, "frequency": 30})"},
  };
  for (const auto& sets : cases) {
    std::string what;
    for (const std::string& s : sets) what += s + " ";
    expect_twins_match(sets, what);
  }
}

}  // namespace
}  // namespace tessref
