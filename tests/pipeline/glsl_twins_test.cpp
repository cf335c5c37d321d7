// The built-in programs' GLSL twins on tessref's executor against the C++ programs they mirror
// (shaders.program = twins against builtin): the same coverage, colors within 1/255, and the same
// gl_TessCoord, positions and normals bit for bit; and the executor's output does not depend on
// the thread count nor on its batch size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "twins_test_util.h"

namespace tessref {
namespace {

using test::expect_equivalent;
using test::expect_same_dump;
using test::Frame;
using test::render;
using test::with;

TEST(GlslTwins, DefaultSceneMatchesTheCppProgramsInEveryNormalMode) {
  for (const char* mode : {"linear", "quadratic", "quadratic_corrected", "analytic"}) {
    const std::vector<std::string> sets = {std::string("tessellation.normal_mode=") + mode};
    const Frame cpp = render(sets);
    const Frame twins = render(with(sets, "shaders.program=twins"));
    expect_equivalent(cpp, twins, mode);
    expect_same_dump(cpp, twins, mode);
  }
}

TEST(GlslTwins, FlatSchemeNormalsShadingAndNoTessellation) {
  const std::vector<std::vector<std::string>> cases = {
      {"tessellation.scheme=flat"},
      {"shading=normals", "tessellation.spacing=equal", "tessellation.winding=cw"},
      {"tessellation.enabled=false"},
      {"tessellation.adaptive.enabled=true"},
  };
  for (const auto& sets : cases) {
    const std::string what = sets[0];
    const Frame cpp = render(sets);
    const Frame twins = render(with(sets, "shaders.program=twins"));
    expect_equivalent(cpp, twins, what);
    if (!cpp.dump.empty()) expect_same_dump(cpp, twins, what);
  }
}

TEST(GlslTwins, ImagesAndDumpsDoNotDependOnThreadsOrBatchSize) {
  const std::vector<std::string> sets = {"shaders.program=twins"};
  const Frame base = render(with(sets, "shaders.batch_lanes=256"), 1);
  for (int threads : {1, 2, 8})
    for (int lanes : {1, 7, 64, 256}) {
      if (threads == 1 && lanes == 256) continue;
      const Frame f = render(with(sets, "shaders.batch_lanes=" + std::to_string(lanes)), threads);
      const std::string what = std::to_string(threads) + " threads, batch " + std::to_string(lanes);
      EXPECT_EQ(0, std::memcmp(base.fb.color.data(), f.fb.color.data(), base.fb.color.size() * sizeof(glm::vec4))) << what;
      EXPECT_EQ(0, std::memcmp(base.fb.depth.data(), f.fb.depth.data(), base.fb.depth.size() * sizeof(float))) << what;
      ASSERT_EQ(base.dump.size(), f.dump.size()) << what;
      EXPECT_EQ(0, std::memcmp(base.dump.data(), f.dump.data(), base.dump.size() * sizeof(TessDumpRecord))) << what;
    }
}

}  // namespace
}  // namespace tessref
