// `tessref verify` campaigns' bad input and `--merge`, without a GL driver: reports written by
// hand stand in for a campaign's (the campaigns themselves run in tests/glref/campaign_test.cpp).
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../pipeline/test_util.h"
#include "campaign_test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using test::TempDir;

class CampaignCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(test::kBinary)) GTEST_SKIP() << test::kBinary << " not built";
  }
};

TEST_F(CampaignCli, ShardSyntaxErrorsAreClear) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "scenes");
  dir.write("scenes/a.json", "{}");
  const std::string base = "verify " + (dir.path() / "scenes").string() + " --ref " + dir.path().string() +
                           "/caps --out " + dir.path().string() + "/reports --shard ";
  for (const std::string bad : {"0/0", "3/2", "2/2", "x", "1", "-1/2", "1/x", "auto/0"}) {
    const test::CliRun r = test::run_cli(base + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("--shard '" + bad + "': expected I/N with 0 <= I < N")) << bad;
  }
}

TEST_F(CampaignCli, ShardAutoNamesWhatIsMissing) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "scenes");
  dir.write("scenes/a.json", "{}");
  const std::string cmd = "cd " + dir.path().string() + " && env -u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX ";
  const std::string args = " verify scenes --ref caps --out reports --shard auto 2>&1";
  std::string out;
  FILE* p = popen((cmd + test::kBinary + args).c_str(), "r");
  for (int c; (c = std::fgetc(p)) != EOF;) out += char(c);
  EXPECT_EQ(WEXITSTATUS(pclose(p)), 2) << out;
  EXPECT_THAT(out, HasSubstr("neither SLURM_ARRAY_TASK_ID"));
  out.clear();
  p = popen((cmd + "JOB_COMPLETION_INDEX=1 " + test::kBinary + args).c_str(), "r");
  for (int c; (c = std::fgetc(p)) != EOF;) out += char(c);
  EXPECT_EQ(WEXITSTATUS(pclose(p)), 2) << out;
  EXPECT_THAT(out, HasSubstr("the shard count is unknown"));
}

TEST_F(CampaignCli, MissingCaptureIsNamed) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "scenes");
  std::filesystem::create_directories(dir.path() / "caps" / "a");
  dir.write("scenes/a.json", "{}");
  dir.write("scenes/b.json", "{}");
  const test::CliRun r = test::run_cli("verify " + (dir.path() / "scenes").string() + " --ref " +
                                       (dir.path() / "caps").string() + " --out " + (dir.path() / "r").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("scene 'b'"));
  EXPECT_THAT(r.output, HasSubstr("has no capture"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "r" / "a.json")) << "nothing runs before every capture is there";
}

TEST_F(CampaignCli, MergeRefusesMalformedAndDuplicateReports) {
  TempDir dir;
  test::write_fake_report(dir.path() / "one", "a", true, 0.1);
  test::write_fake_report(dir.path() / "two", "a", true, 0.1);
  test::CliRun r = test::run_cli("verify --merge " + (dir.path() / "one").string() + " " +
                                 (dir.path() / "two").string() + " --json " + (dir.path() / "m.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("scene 'a' is reported twice"));

  dir.write("one/broken.json", "{\"scene\": \"x\", \"pass\": ");
  r = test::run_cli("verify --merge " + (dir.path() / "one").string() + " --json " + (dir.path() / "m.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("broken.json: not a verify report: the JSON does not parse"));

  dir.write("one/broken.json", "{\"scene\": \"x\", \"pass\": \"yes\"}");
  r = test::run_cli("verify --merge " + (dir.path() / "one").string() + " --json " + (dir.path() / "m.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("broken.json: not a verify report: no \"pass\" true/false"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "m.json"));
}

TEST_F(CampaignCli, MergeIsTheSameWhateverTheSharding) {
  TempDir dir;
  for (const char* s : {"a", "b", "c"}) test::write_fake_report(dir.path() / "all", s, s[0] != 'b', 0.5);
  test::write_fake_report(dir.path() / "s0", "a", true, 0.5);
  test::write_fake_report(dir.path() / "s0", "c", true, 0.5);
  test::write_fake_report(dir.path() / "s1", "b", false, 0.5);
  const test::CliRun one = test::run_cli("verify --merge " + (dir.path() / "all").string() + " --json " +
                                         (dir.path() / "one.json").string());
  const test::CliRun two = test::run_cli("verify --merge " + (dir.path() / "s1").string() + " " +
                                         (dir.path() / "s0").string() + " --json " + (dir.path() / "two.json").string());
  EXPECT_EQ(one.exit_code, 1) << one.output;  // b failed
  EXPECT_EQ(two.exit_code, 1) << two.output;
  EXPECT_EQ(test::read_file(dir.path() / "one.json"), test::read_file(dir.path() / "two.json"));
  const nlohmann::json m = nlohmann::json::parse(test::read_file(dir.path() / "one.json"));
  EXPECT_EQ(m["summary"]["scenes"], 3);
  EXPECT_EQ(m["summary"]["failed"], 1);
  EXPECT_EQ(m["summary"]["worst_scene"], "b");
  EXPECT_EQ(m["scenes"][1]["name"], "b");
}

TEST_F(CampaignCli, MergeOptionsThatDoNotApplyAreNamed) {
  TempDir dir;
  test::write_fake_report(dir.path() / "r", "a", true, 0.1);
  const test::CliRun r = test::run_cli("verify --merge " + (dir.path() / "r").string() + " --ref x --json m.json");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--ref does not apply with --merge"));
}

}  // namespace
}  // namespace tessref
