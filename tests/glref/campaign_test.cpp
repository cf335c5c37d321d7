// A verify campaign on llvmpipe: `tessref capture SCENES_DIR` captures a folder of small scenes,
// `tessref verify SCENES_DIR` runs it in two shards and unsharded, and the two merged reports
// are the same bytes; a scene without a capture is named.
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../pipeline/test_util.h"
#include "gl_fixture.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;

// Small torus scenes that differ in levels, spacing and shading; every one self-contained.
const char* kScenes[][2] = {
    {"a_pn", R"({"image": {"width": 64, "height": 64}, "tessellation": {"inner": 3, "outer": 4}})"},
    {"b_flat", R"({"image": {"width": 64, "height": 64}, "tessellation": {"scheme": "flat", "inner": 2, "outer": 5}})"},
    {"c_even", R"({"image": {"width": 48, "height": 64},
                   "tessellation": {"inner": 5, "outer": 3, "spacing": "fractional_even"}})"},
};

class Campaign : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::filesystem::temp_directory_path() / ("tessref_Campaign_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "scenes");
    for (const auto& s : kScenes) std::ofstream(dir_ / "scenes" / (std::string(s[0]) + ".json")) << s[1];
    capture_ = test::run_cli("capture " + path("scenes") + " --out " + path("captures"));
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  void SetUp() override {
    TESSREF_REQUIRE_GL(ctx);
    ASSERT_EQ(capture_.exit_code, 0) << capture_.output;
  }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }

  static std::filesystem::path dir_;
  static test::CliRun capture_;
};
std::filesystem::path Campaign::dir_;
test::CliRun Campaign::capture_;

TEST_F(Campaign, CapturesEverySceneIntoItsFolder) {
  for (const auto& s : kScenes)
    EXPECT_TRUE(std::filesystem::exists(dir_ / "captures" / s[0] / "manifest.json")) << s[0];
  EXPECT_THAT(capture_.output, HasSubstr("[3/3] c_even"));
}

TEST_F(Campaign, ShardedMergeIsTheUnshardedMergeByteForByte) {
  const std::string scenes = path("scenes") + " --ref " + path("captures");
  const test::CliRun all = test::run_cli("verify " + scenes + " --out " + path("all") + " --threads 2");
  ASSERT_EQ(all.exit_code, 0) << all.output;
  EXPECT_THAT(all.output, HasSubstr("shard 0/1: 3 passed, 0 failed"));
  for (const char* shard : {"0/2", "1/2"}) {
    // Each shard with its own thread count: the reports do not depend on it.
    const test::CliRun r = test::run_cli("verify " + scenes + " --out " + path(std::string("shard") + shard[0]) +
                                         " --shard " + shard + " --threads 1");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  EXPECT_TRUE(std::filesystem::exists(dir_ / "shard0" / "a_pn.json"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "shard1" / "b_flat.json"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "shard0" / "c_even.json"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "shard0" / "c_even" / "heat.png"));

  ASSERT_EQ(test::run_cli("verify --merge " + path("all") + " --json " + path("one.json")).exit_code, 0);
  const test::CliRun m = test::run_cli("verify --merge " + path("shard1") + " " + path("shard0") + " --json " +
                                       path("two.json") + " --html " + path("site"));
  ASSERT_EQ(m.exit_code, 0) << m.output;
  const std::string one = test::read_file(path("one.json")), two = test::read_file(path("two.json"));
  EXPECT_EQ(one, two);
  const nlohmann::json j = nlohmann::json::parse(one);
  EXPECT_EQ(j["summary"]["scenes"], 3);
  EXPECT_EQ(j["summary"]["passed"], 3);
  EXPECT_EQ(j["scenes"][0]["name"], "a_pn");
  EXPECT_TRUE(std::filesystem::exists(path("site") + "/index.html"));
  EXPECT_THAT(test::read_file(path("site") + "/b_flat.html"), HasSubstr("data:image/png;base64,"));
}

TEST_F(Campaign, MissingCaptureIsNamed) {
  std::filesystem::create_directories(dir_ / "more");
  std::filesystem::copy(dir_ / "scenes", dir_ / "more", std::filesystem::copy_options::recursive |
                                                          std::filesystem::copy_options::skip_existing);
  std::ofstream(dir_ / "more" / "d_new.json") << kScenes[0][1];
  const test::CliRun r =
      test::run_cli("verify " + path("more") + " --ref " + path("captures") + " --out " + path("more_reports"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("scene 'd_new'"));
  EXPECT_THAT(r.output, HasSubstr("has no capture"));
}

TEST_F(Campaign, SingleSceneHtmlPage) {
  const test::CliRun r = test::run_cli("verify " + path("scenes/a_pn.json") + " --ref " + path("captures/a_pn") +
                                       " --html " + path("page"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string page = test::read_file(path("page") + "/index.html");
  EXPECT_THAT(page, HasSubstr("class=\"pass\">PASS"));
  EXPECT_THAT(page, HasSubstr("--patch "));
  EXPECT_TRUE(std::filesystem::exists(path("page") + "/heat.png"));
}

}  // namespace
}  // namespace tessref
