// The built `tessref stats --image`: files, JSON, and the option errors (exit 2).
#include <unistd.h>

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

using test::CliRun;
using test::kBinary;
const std::string kSmall = "--set image.width=48 --set image.height=48 --set camera.fit=true ";

using test::run_cli;

class StatsImagesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kBinary)) GTEST_SKIP() << kBinary << " not built";
    dir_ = std::filesystem::temp_directory_path() / ("tessref_stats_images_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(StatsImagesCli, CurvatureImageAndJson) {
  const CliRun r = run_cli("stats " + kSmall + "--set tessellation.scheme=phong --image gaussian_curvature -o " +
                       path("k.png") + " --json " + path("k.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("scheme phong"));
  EXPECT_THAT(r.output, HasSubstr("0 white"));
  EXPECT_TRUE(std::filesystem::file_size(path("k.png")) > 100);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(path("k.json")));
  EXPECT_EQ(j["scheme"], "phong");
  EXPECT_GT(j["covered"].get<int>(), 300);
  EXPECT_LT(j["max_position_deviation"].get<double>(), 0.01);
}

TEST_F(StatsImagesCli, NormalModeDifferencePrintsTheFigures) {
  const CliRun r = run_cli("stats " + kSmall + "--image normal_mode_difference -o " + path("d.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("normals: max angle"));
  EXPECT_THAT(r.output, HasSubstr("covered pixels differ"));
  EXPECT_TRUE(std::filesystem::exists(path("d.png")));
}

TEST_F(StatsImagesCli, OptionErrorsExitTwoAndWriteNothing) {
  const struct {
    std::string args, message;
  } cases[] = {
      {"--image gaussian_curvature", "--image: needs -o FILE"},
      {"-o " + path("x.png"), "-o: writes the image of --image"},
      {"--table 3 --image highlight_lines -o " + path("x.png"), "does not combine with --table"},
      {"--set shaders.program=twins --image highlight_lines -o " + path("x.png"), "shaders.program builtin"},
      {"--image gaussian_curvature --curvature-range -1 -o " + path("x.png"),
       "--curvature-range: must be a positive finite number"},
      {"--image highlight_lines --highlight-width 2 -o " + path("x.png"), "--highlight-width: must be in (0, 1]"},
      {"--image normal_mode_difference --difference-scale nan -o " + path("x.png"),
       "--difference-scale: must be a positive finite number"},
      {"--set tessellation.scheme=scalar_tagged_pn --image gaussian_curvature -o " + path("x.png"),
       "scalar_tagged_pn is not supported"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli("stats " + kSmall + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.args;
    EXPECT_FALSE(std::filesystem::exists(path("x.png"))) << c.args;
  }
}

}  // namespace
}  // namespace tessref
