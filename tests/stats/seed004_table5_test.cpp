// Seed 004's Table 5, Gaussian curvature at the interior points of the 21-a-side grid of every
// patch. The paper prints 3-4 digits: each of its Sphere and Torus numbers is checked to one
// unit of its last printed digit (or 1e-4 relative, for 92.277), and tessref's own values are
// pinned to 6 digits (docs/stats.md has both side by side).
#include <cmath>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "stats/seed004_tables.h"

namespace tessref::stats {
namespace {

struct Row {
  const char* mesh;
  Interpolant scheme;
  const char* value[4];  // mean, std dev, min, max as printed
};
constexpr Row kPaper[] = {
    {"Sphere", Interpolant::Phong, {"2.032", "0.046", "1.847", "2.097"}},
    {"Sphere", Interpolant::Nagata, {"0.972", "0.010", "0.933", "0.985"}},
    {"Sphere", Interpolant::NLSA, {"0.930", "0.010", "0.887", "0.945"}},
    {"Sphere", Interpolant::PN, {"0.950", "0.029", "0.900", "1.047"}},
    {"Torus", Interpolant::Phong, {"-1.503", "3.310", "-9.476", "1.978"}},
    {"Torus", Interpolant::Nagata, {"-0.412", "3.483", "-4.027", "92.277"}},
    {"Torus", Interpolant::NLSA, {"-0.672", "1.544", "-3.901", "0.978"}},
    {"Torus", Interpolant::PN, {"-0.638", "1.610", "-5.612", "2.894"}},
};

// tessref's values (mean, std dev, min, max), as docs/stats.md prints them.
struct Pinned {
  const char* mesh;
  Interpolant scheme;
  double value[4];
};
constexpr Pinned kTessref[] = {
    {"Sphere", Interpolant::Phong, {2.03231, 0.0462072, 1.84729, 2.09669}},
    {"Sphere", Interpolant::Nagata, {0.971954, 0.0102163, 0.932543, 0.985251}},
    {"Sphere", Interpolant::NLSA, {0.930459, 0.0106365, 0.88717, 0.945488}},
    {"Sphere", Interpolant::PN, {0.950157, 0.0289704, 0.900258, 1.04714}},
    {"Torus", Interpolant::Phong, {-1.5034, 3.30985, -9.47647, 1.97772}},
    {"Torus", Interpolant::Nagata, {-0.412274, 3.48261, -4.02671, 92.2743}},
    {"Torus", Interpolant::NLSA, {-0.671821, 1.54423, -3.90136, 0.97779}},
    {"Torus", Interpolant::PN, {-0.637674, 1.60952, -5.61186, 2.89416}},
};

double values(const SchemeRow& r, int k) {
  return k == 0 ? r.value.mean : k == 1 ? r.value.std_dev : k == 2 ? r.value.min : r.value.max;
}

const SchemeRow& find(const std::vector<SchemeRow>& rows, const char* mesh, Interpolant s) {
  for (const SchemeRow& r : rows)
    if (r.mesh == mesh && r.scheme == s) return r;
  throw std::runtime_error(std::string("no row ") + mesh);
}

// One unit in the last digit printed: "0.010" -> 0.001.
double last_digit_unit(const char* printed) {
  const char* dot = std::strchr(printed, '.');
  return dot ? std::pow(10.0, -double(std::strlen(dot + 1))) : 1.0;
}

TEST(Seed004Table5, SphereAndTorusWithinThePapersDigits) {
  const std::vector<SchemeRow> rows = seed004_table5(Parallel(0));
  for (const Row& p : kPaper) {
    const SchemeRow& r = find(rows, p.mesh, p.scheme);
    for (int k = 0; k < 4; ++k) {
      const double paper = std::stod(p.value[k]);
      const double tolerance = std::max(last_digit_unit(p.value[k]), 1e-4 * std::abs(paper));
      EXPECT_NEAR(values(r, k), paper, tolerance) << p.mesh << " " << seed004_scheme_name(p.scheme) << " #" << k;
    }
  }
}

TEST(Seed004Table5, PinsTessrefsValues) {
  const std::vector<SchemeRow> rows = seed004_table5(Parallel(0));
  for (const Pinned& p : kTessref) {
    const SchemeRow& r = find(rows, p.mesh, p.scheme);
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(values(r, k), p.value[k], 1e-5 * std::abs(p.value[k]) + 1e-9)
          << p.mesh << " " << seed004_scheme_name(p.scheme) << " #" << k;
  }
}

TEST(Seed004Table5, InteriorPointsOnly) {
  const std::vector<SchemeRow> rows = seed004_table5(Parallel(0));
  EXPECT_EQ(find(rows, "Sphere", Interpolant::PN).value.count, 320u * 171u);
  EXPECT_EQ(find(rows, "Torus", Interpolant::PN).value.count, 200u * 171u);
}

TEST(Seed004Table5, SameBitsOnOneThreadAndMany) {
  const std::vector<SchemeRow> one = seed004_table5(Parallel(1)), many = seed004_table5(Parallel(3));
  ASSERT_EQ(one.size(), many.size());
  for (std::size_t r = 0; r < one.size(); ++r)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(values(one[r], k), values(many[r], k)) << one[r].mesh;
}

}  // namespace
}  // namespace tessref::stats
