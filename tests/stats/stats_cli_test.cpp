// The built `tessref stats` binary: the tables, a scene's mesh, JSON, errors.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../pipeline/test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

using test::CliRun;
using test::kBinary;

using test::run_cli;

using test::read_file;

class StatsCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kBinary)) GTEST_SKIP() << kBinary << " not built";
    dir_ = std::filesystem::temp_directory_path() / ("tessref_stats_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(StatsCli, Table3InThePapersLayout) {
  const CliRun r = run_cli("stats --table 3");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("Sphere  i = 0   Phong            0.0153197 ± 0.00940214"));
  EXPECT_THAT(r.output, HasSubstr("Torus   j = 19  Phong"));
  EXPECT_THAT(r.output, Not(HasSubstr("Table 4")));
}

TEST_F(StatsCli, Table4PrintsBothEdgeCountings) {
  const CliRun r = run_cli("stats --table 4");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("Sphere       162/480/320  0.98479 ± 0.00113564"));
  EXPECT_THAT(r.output, HasSubstr("480/0/0                      320/0/160"));
  EXPECT_THAT(r.output, HasSubstr("210/50/40                    135/25/140"));
}

TEST_F(StatsCli, JsonDoesNotDependOnThreads) {
  const auto one = dir_ / "one.json", three = dir_ / "three.json";
  ASSERT_EQ(run_cli("stats --table 6 --threads 1 --json " + one.string()).exit_code, 0);
  ASSERT_EQ(run_cli("stats --table 6 --threads 3 --json " + three.string()).exit_code, 0);
  EXPECT_EQ(read_file(one), read_file(three));
  const nlohmann::json j = nlohmann::json::parse(read_file(one));
  ASSERT_EQ(j["table6"].size(), 16u);
  EXPECT_EQ(j["table6"][8]["mesh"], "Sphere");
  EXPECT_EQ(j["table6"][8]["scheme"], "phong");
  EXPECT_EQ(j["table6"][8]["value"]["count"], 480 * 21);
}

TEST_F(StatsCli, MeasuresASceneMesh) {
  const auto out = dir_ / "vase.json";
  const CliRun r = run_cli("stats --set mesh.type=vase --nagata-eps 0.06 --json " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("mesh         241/700/460"));
  EXPECT_THAT(r.output, HasSubstr("mesh Nagata eps = 0.06"));
  // Issue 24, defect 8: the header names the --set keys, not a bare "<default scene>".
  EXPECT_THAT(r.output, HasSubstr("<default scene> with --set mesh.type (model space)"));
  const nlohmann::json j = nlohmann::json::parse(read_file(out));
  EXPECT_EQ(j["scene"], "<default scene> with --set mesh.type");
  EXPECT_EQ(j["mesh"]["triangles"], 460);
  EXPECT_EQ(j["mesh"]["boundary_edges"], 20);
  EXPECT_EQ(j["gaussian_curvature"].size(), 4u);
}

TEST_F(StatsCli, BadArguments) {
  EXPECT_NE(run_cli("stats --table 7").exit_code, 0);
  const CliRun r = run_cli("stats --table 3 --set mesh.type=vase");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("--table prints one of seed 004's tables"));
  const CliRun bad = run_cli("stats --set mesh.type=seed004_torus --set mesh.seed004_torus.grid=2");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.output, HasSubstr("mesh.seed004_torus.grid"));
}

}  // namespace
}  // namespace tessref
