// Seed 004's Table 6, the Sphere (i = 2) and Torus (j = 10) rows: the cosine between the two
// patches' normals at 21 points along every shared edge. Means, minima and maxima to the paper's
// 6 digits (2.5e-6: its single-precision normals move the last digit), standard deviations to
// 2e-4 relative.
#include <gtest/gtest.h>

#include "stats/seed004_tables.h"

namespace tessref::stats {
namespace {

struct PaperRow {
  const char* mesh;
  Interpolant scheme;
  double mean, std_dev, min, max;
};
constexpr PaperRow kTable6[] = {
    {"Sphere", Interpolant::Phong, 0.997072, 0.000765733, 0.995723, 0.99874},
    {"Sphere", Interpolant::Nagata, 0.999996, 3.27602e-6, 0.999988, 1},
    {"Sphere", Interpolant::NLSA, 0.999979, 9.69038e-6, 0.999958, 1},
    {"Sphere", Interpolant::PN, 0.999991, 6.6563e-6, 0.999975, 1},
    {"Torus", Interpolant::Phong, 0.987918, 0.0157815, 0.915295, 0.999999},
    {"Torus", Interpolant::Nagata, 0.997556, 0.0086036, 0.938828, 1},
    {"Torus", Interpolant::NLSA, 0.994738, 0.0067909, 0.969450, 1},
    {"Torus", Interpolant::PN, 0.998873, 0.0018468, 0.989164, 1},
};

TEST(Seed004Table6, SphereAndTorusRows) {
  const std::vector<SchemeRow> rows = seed004_table6(Parallel(0));
  int matched = 0;
  for (const PaperRow& p : kTable6)
    for (const SchemeRow& r : rows) {
      if (r.mesh != p.mesh || r.scheme != p.scheme) continue;
      ++matched;
      const std::string where = r.mesh + " " + seed004_scheme_name(r.scheme);
      EXPECT_NEAR(r.value.mean, p.mean, 2.5e-6) << where;
      EXPECT_NEAR(r.value.std_dev, p.std_dev, 2e-4 * p.std_dev) << where;
      EXPECT_NEAR(r.value.min, p.min, 2.5e-6) << where;
      EXPECT_NEAR(r.value.max, p.max, 2.5e-6) << where;
    }
  EXPECT_EQ(matched, 8);
}

TEST(Seed004Table6, TwentyOnePointsOnEveryEdge) {
  const std::vector<SchemeRow> rows = seed004_table6(Parallel(0));
  for (const SchemeRow& r : rows) {
    // The edges each mesh's 21 samples are taken on (the Vase: 20 open-top edges skipped).
    const unsigned edges = r.mesh == "Sphere" ? 480u : r.mesh == "Torus" ? 300u : r.mesh == "RoundedCube" ? 84u
                         : r.mesh == "Vase" ? 680u : 0u;
    ASSERT_NE(edges, 0u) << "an unexpected mesh: " << r.mesh;
    EXPECT_EQ(r.value.count, edges * 21u) << r.mesh;
  }
}

}  // namespace
}  // namespace tessref::stats
