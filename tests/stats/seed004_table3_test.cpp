// THE acceptance test of seed 004's reproduction: Table 3 (signed distances of the four
// interpolants to the unit sphere, i = 0..3, and the torus R = 1, r = 0.5, j = 5..19), every
// one of its 144 numbers within 1e-3 relative + 2e-7 absolute of the paper's. The paper's
// conventions that this needs are recovered in docs/stats.md.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "stats/seed004_tables.h"

namespace tessref::stats {
namespace {

// Seed 004, Table 3, typed in row by row: mean, "std dev", min, max (the min of 0 the paper
// prints is the interpolated vertices; tessref's float vertices sit up to 2 ulp off the sphere).
struct PaperRow {
  const char* surface;
  int step;
  Interpolant scheme;
  double mean, spread, min, max;
};
constexpr Interpolant Ph = Interpolant::Phong, Na = Interpolant::Nagata, NL = Interpolant::NLSA,
                      PN = Interpolant::PN;
constexpr PaperRow kTable3[] = {
    {"Sphere", 0, Ph, 0.0153196, 0.00940232, 0, 0.0269864},
    {"Sphere", 0, Na, 0.00287491, 0.00437559, -0.00290352, 0.0131106},
    {"Sphere", 0, NL, -0.0373717, 0.0231368, -0.0586981, 0},
    {"Sphere", 0, PN, -0.0318387, 0.0225525, -0.0586009, 0},
    {"Sphere", 1, Ph, 0.0157366, 0.00930732, 0, 0.0233265},
    {"Sphere", 1, Na, 0.000301524, 0.000336243, -7.21216e-5, 0.00125933},
    {"Sphere", 1, NL, -0.00329917, 0.00209737, -0.00633496, 0},
    {"Sphere", 1, PN, -0.0028053, 0.00203187, -0.00632477, 0},
    {"Sphere", 2, Ph, 0.00503575, 0.00300305, -5.96046e-8, 0.00815177},
    {"Sphere", 2, Na, 2.07119e-5, 2.18946e-5, -1.13249e-6, 8.9407e-5},
    {"Sphere", 2, NL, -0.000225536, 0.000143714, -0.000468373, 0},
    {"Sphere", 2, PN, -0.000191595, 0.000139045, -0.000467658, 0},
    {"Sphere", 3, Ph, 0.00133509, 0.000797624, -5.96046e-8, 0.00221264},
    {"Sphere", 3, Na, 1.29748e-6, 1.37613e-6, -1.78814e-7, 5.84126e-6},
    {"Sphere", 3, NL, -1.44418e-5, 9.19883e-6, -3.06964e-5, 0},
    {"Sphere", 3, PN, -1.22342e-5, 8.88072e-6, -3.05772e-5, 0},
    {"Torus", 5, Ph, -0.000754569, 0.0315128, -0.111965, 0.0630175},
    {"Torus", 5, Na, 0.000922857, 0.0386565, -0.112992, 0.0931029},
    {"Torus", 5, NL, -0.0252151, 0.0498816, -0.195886, 0.0383056},
    {"Torus", 5, PN, -0.0210668, 0.0457862, -0.195886, 0.0467965},
    {"Torus", 10, Ph, 0.00783327, 0.00929549, -0.00958499, 0.0287549},
    {"Torus", 10, Na, 9.40043e-5, 0.00211594, -0.00666818, 0.00601918},
    {"Torus", 10, NL, -0.00217635, 0.0041617, -0.0149165, 0.00385857},
    {"Torus", 10, PN, -0.00181822, 0.00374165, -0.0147308, 0.00398123},
    {"Torus", 15, Ph, 0.00440836, 0.00541819, -0.00492978, 0.0166597},
    {"Torus", 15, Na, 1.57127e-5, 0.000580865, -0.00252217, 0.00191915},
    {"Torus", 15, NL, -0.000451227, 0.000939187, -0.00340354, 0.00134289},
    {"Torus", 15, PN, -0.000376097, 0.000814623, -0.00340357, 0.00117016},
    {"Torus", 17, Ph, 0.00356666, 0.00441199, -0.00393245, 0.0138325},
    {"Torus", 17, Na, 2.97925e-5, 0.00039676, -0.00130969, 0.00172943},
    {"Torus", 17, NL, -0.000275727, 0.000596803, -0.00208876, 0.000976563},
    {"Torus", 17, PN, -0.000229708, 0.000509889, -0.00208879, 0.000768423},
    {"Torus", 19, Ph, 0.00293179, 0.00364289, -0.0032014, 0.0115674},
    {"Torus", 19, Na, 6.28688e-6, 0.000270014, -0.00122377, 0.000931621},
    {"Torus", 19, NL, -0.000177753, 0.0004006, -0.00135079, 0.000708401},
    {"Torus", 19, PN, -0.000148038, 0.000337174, -0.0013507, 0.000557363},
};

constexpr double kRelative = 1e-3, kAbsolute = 2e-7;

// How many tolerances apart: <= 1 passes.
double misfit(double ours, double paper) {
  return std::abs(ours - paper) / (kRelative * std::abs(paper) + kAbsolute);
}

TEST(Seed004Table3, AllNumbersWithinTolerance) {
  const std::vector<DistanceRow> rows = seed004_table3(Parallel(0));
  ASSERT_EQ(rows.size(), std::size(kTable3));
  double worst = 0.0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const PaperRow& p = kTable3[r];
    const DistanceRow& o = rows[r];
    ASSERT_EQ(o.surface, p.surface);
    ASSERT_EQ(o.step, p.step);
    ASSERT_EQ(o.scheme, p.scheme);
    const std::string where = std::string(p.surface) + " " + std::to_string(p.step) + " " +
                              seed004_scheme_name(p.scheme);
    const double ours[4] = {o.distance.mean, o.distance.seed004_table3_spread(), o.distance.min, o.distance.max};
    const double paper[4] = {p.mean, p.spread, p.min, p.max};
    const char* what[4] = {"mean", "std dev", "min", "max"};
    for (int k = 0; k < 4; ++k) {
      EXPECT_LE(misfit(ours[k], paper[k]), 1.0) << where << " " << what[k] << ": tessref " << ours[k]
                                                << ", paper " << paper[k];
      worst = std::max(worst, misfit(ours[k], paper[k]));
    }
    EXPECT_EQ(o.distance.count, (p.surface[0] == 'S' ? 20u << (2 * p.step) : 2u * p.step * p.step) * 231u) << where;
  }
  RecordProperty("worst_misfit", std::to_string(worst));
  std::printf("Table 3: worst number at %.3f of its tolerance\n", worst);
}

// The paper's "std dev" column is no plain standard deviation: on the sphere at i = 0 the
// sample standard deviation of the same distances misses Phong's by 40%.
TEST(Seed004Table3, StdDevColumnIsSpreadAboutHalfTheMean) {
  const std::vector<DistanceRow> rows = seed004_table3(Parallel(0));
  const Summary& phong = rows[0].distance;
  EXPECT_NEAR(phong.std_dev, 0.005452, 1e-5);
  EXPECT_LT(misfit(phong.seed004_table3_spread(), 0.00940232), 1.0);
  EXPECT_GT(misfit(phong.std_dev, 0.00940232), 100.0);
}

TEST(Seed004Table3, SameBitsOnOneThreadAndMany) {
  const std::vector<DistanceRow> one = seed004_table3(Parallel(1)), many = seed004_table3(Parallel(0));
  ASSERT_EQ(one.size(), many.size());
  for (std::size_t r = 0; r < one.size(); ++r) {
    EXPECT_EQ(one[r].distance.mean, many[r].distance.mean);
    EXPECT_EQ(one[r].distance.std_dev, many[r].distance.std_dev);
    EXPECT_EQ(one[r].distance.min, many[r].distance.min);
    EXPECT_EQ(one[r].distance.max, many[r].distance.max);
  }
}

}  // namespace
}  // namespace tessref::stats
