// tessellation.displacement through the whole pipeline: the GLSL twins' displacement block on
// tessref's executor gives the C++ DisplacedTes's positions and normals bit for bit (PN in every
// normal mode, flat, Phong, Nagata, Scalar Tagged PN), the image moves where the surface does,
// and the output does not depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "twins_test_util.h"

namespace tessref {
namespace {

const std::string kDisplace = R"(tessellation.displacement={"amplitude": 0.03, "frequency": 30})";

using test::differing_records;
using test::Frame;

Frame render(std::vector<std::string> sets, int threads = 2) {
  sets.push_back("image.width=192");
  sets.push_back("image.height=192");
  return test::render_frame(sets, threads);
}

std::size_t coverage_mismatch(const Frame& a, const Frame& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.fb.depth.size(); ++i) n += (a.fb.depth[i] < 1.0f) != (b.fb.depth[i] < 1.0f);
  return n;
}

TEST(DisplacementTwins, ExecutorMatchesTheCppProgramsBitForBit) {
  const std::vector<std::vector<std::string>> configs = {
      {"tessellation.normal_mode=linear"},
      {"tessellation.normal_mode=quadratic"},
      {"tessellation.normal_mode=quadratic_corrected"},
      {"tessellation.normal_mode=analytic"},
      {"tessellation.scheme=flat"},
      {"tessellation.scheme=flat", "mesh.type=icosphere", "tessellation.inner=5", "tessellation.outer=5"},
      {"tessellation.scheme=phong"},
      {"tessellation.scheme=nagata", "tessellation.normal_mode=analytic"},
      {"tessellation.scheme=scalar_tagged_pn", "tessellation.tension=0.3"}};
  for (std::vector<std::string> sets : configs) {
    std::string what;
    for (const std::string& s : sets) what += s + " ";
    sets.push_back(kDisplace);
    const Frame cpp = render(sets);
    sets.push_back("shaders.program=twins");
    const Frame twins = render(sets);
    ASSERT_FALSE(cpp.dump.empty()) << what;
    EXPECT_EQ(differing_records(cpp, twins), 0u) << what;
    EXPECT_EQ(coverage_mismatch(cpp, twins), 0u) << what;
    std::size_t over = 0;
    for (std::size_t i = 0; i < cpp.fb.color.size(); ++i)
      for (int c = 0; c < 4; ++c) over += std::fabs(cpp.fb.color[i][c] - twins.fb.color[i][c]) > 1.0f / 255.0f;
    EXPECT_EQ(over, 0u) << what;
  }
}

TEST(DisplacementTwins, MovesTheSurfaceAndIsThreadIndependent) {
  const Frame plain = render({});
  const Frame displaced = render({kDisplace});
  const Frame one_thread = render({kDisplace}, 1);
  ASSERT_EQ(plain.dump.size(), displaced.dump.size());
  // Every record moved by |a sin(f |P|)| along its normal, which is at most a.
  std::size_t moved = 0;
  double largest = 0.0;
  for (std::size_t i = 0; i < plain.dump.size(); ++i) {
    const double d = glm::length(glm::dvec3(displaced.dump[i].position) - glm::dvec3(plain.dump[i].position));
    moved += d > 0.0;
    largest = std::max(largest, d);
  }
  EXPECT_GT(moved, plain.dump.size() * 9 / 10);
  EXPECT_LE(largest, 0.03 * 1.0001);
  EXPECT_GT(largest, 0.03 * 0.99);
  EXPECT_GT(coverage_mismatch(plain, displaced), 100u);
  EXPECT_EQ(differing_records(displaced, one_thread), 0u);
  EXPECT_EQ(std::memcmp(displaced.fb.color.data(), one_thread.fb.color.data(),
                        displaced.fb.color.size() * sizeof(displaced.fb.color[0])), 0);
}

}  // namespace
}  // namespace tessref
