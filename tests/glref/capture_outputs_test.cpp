// Issue 24, defects 5 and 6: what capture and verify leave behind when they stop: a capture cut
// short by a full file system names the file it was writing (not its hidden temporary) and the
// full file system, and removes the folder it made; a verify stopped by bad input removes the
// --html and --images folders it made.
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../pipeline/test_util.h"
#include "gl_fixture.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(CaptureOutputs, AFullFileSystemNamesTheFileAndLeavesNoFolder) {
  TESSREF_REQUIRE_GL(ctx);
  if (!test::can_mount_small_file_systems())
    GTEST_SKIP() << "unprivileged user namespaces are off here: no small file system to mount";
  const test::TempDir dir;
  const std::filesystem::path mnt = dir.path() / "small";
  std::filesystem::create_directories(mnt);
  const std::string m = mnt.string();
  const test::CliRun r = test::run_on_small_file_system(
      mnt, "100k", test::kBinary + " capture --out " + m + "/cap; echo \"status $?\"; ls -A " + m + " | wc -l");
  EXPECT_THAT(r.output, HasSubstr("tessref: error: " + m + "/cap/color.png: the file system holding it is full"));
  EXPECT_THAT(r.output, HasSubstr("status 2\n0\n"));  // exit 2, and no cap folder left
  EXPECT_THAT(r.output, Not(HasSubstr(".tessref-")));
  EXPECT_THAT(r.output, Not(HasSubstr("libpng")));
}

TEST(CaptureOutputs, VerifyStoppedByBadInputLeavesNoReportFolder) {
  const test::TempDir dir;
  const std::filesystem::path html = dir.path() / "report", images = dir.path() / "images" / "deeper";
  const test::CliRun r = test::run_cli("verify --ref " + (dir.path() / "no-such-capture").string() + " --html " +
                                       html.string() + " --images " + images.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("no such capture folder"));
  EXPECT_FALSE(std::filesystem::exists(html));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "images"));  // the outermost folder it made
  // A folder that was there before is left as it was.
  std::filesystem::create_directories(html);
  const test::CliRun again = test::run_cli("verify --ref " + (dir.path() / "no-such-capture").string() + " --html " +
                                           html.string());
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_TRUE(std::filesystem::is_directory(html));
}

}  // namespace
}  // namespace tessref
