// `tessref compare-tessellators`: the report does not depend on --threads, level 1 is an exact
// match, images come per level, and bad input is an error naming the option or scene key (exit 2).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_util.h"

namespace tessref {
namespace {

using test::run_cli;

const std::string kSmall = " --set image.width=96 --set image.height=96 ";

TEST(CompareTessellators, ReportIsTheSameForAnyThreadCount) {
  test::TempDir dir;
  const auto a = dir.path() / "a.json", b = dir.path() / "b.json";
  const test::CliRun ra = run_cli("compare-tessellators" + kSmall + "--levels 1,3,4.5 --threads 1 --json " + a.string());
  ASSERT_EQ(ra.exit_code, 0) << ra.output;
  const test::CliRun rb = run_cli("compare-tessellators" + kSmall + "--levels 1,3,4.5 --threads 3 --json " + b.string());
  ASSERT_EQ(rb.exit_code, 0) << rb.output;
  EXPECT_EQ(test::read_file(a), test::read_file(b));
  const nlohmann::json j = nlohmann::json::parse(test::read_file(a));
  ASSERT_EQ(j["levels"].size(), 3u);
  EXPECT_EQ(j["levels"][0]["hausdorff_of_diagonal"], 0.0);
  EXPECT_EQ(j["levels"][0]["coverage"]["differs"], 0);
  EXPECT_EQ(j["levels"][0]["colour_differs"], 0);
  EXPECT_EQ(j["levels"][1]["triangles_per_patch"]["uniform"], 9);
  EXPECT_EQ(j["levels"][1]["triangles_per_patch"]["primitive_generator"], 13);
  EXPECT_EQ(j["levels"][2]["uniform_n"], 5);
  EXPECT_GT(j["levels"][2]["hausdorff_of_diagonal"].get<double>(), 0.0);
}

TEST(CompareTessellators, WritesThreeImagesPerLevel) {
  test::TempDir dir;
  const test::CliRun r = run_cli("compare-tessellators" + kSmall + "--levels 2,5 --images " + (dir.path() / "img").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* name : {"tpg-2.png", "uniform-2.png", "coverage-2.png", "tpg-5.png", "uniform-5.png", "coverage-5.png"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.path() / "img" / name)) << name;
}

TEST(CompareTessellators, BadInputNamesTheOptionOrKey) {
  const struct {
    std::string args, message;
  } cases[] = {
      {"--levels 0.5", "--levels: expected numbers from 1 to 64 separated by commas, got '0.5'"},
      {"--levels 2,x", "--levels: expected numbers from 1 to 64 separated by commas, got 'x'"},
      {"--levels 65", "got '65'"},
      {"--levels ''", "--levels: expected at least one level"},
      {"--set tessellation.enabled=false", "tessellation.enabled: compare-tessellators needs tessellation"},
      {"--set tessellation.adaptive.enabled=true", "tessellation.adaptive.enabled: compare-tessellators needs fixed levels"},
      {"--set shaders.program=twins", "shaders.program: compare-tessellators runs the built-in programs only"},
  };
  for (const auto& c : cases) {
    const test::CliRun r = run_cli("compare-tessellators" + kSmall + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << ": " << r.output;
  }
}

}  // namespace
}  // namespace tessref
