// Hostile inputs through the built `tessref` binary: files and shaders made to crash it or exhaust
// its memory end with exit status 2 and a message naming the file, the key or the variable and the
// limit (docs/adversarial.md, "Limits against hostile input").
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using test::CliRun;
using test::kBinary;
using test::run_cli;
using test::TempDir;

const std::string kSource = TESSREF_SOURCE_DIR;
const std::string kDisplacement = kSource + "/scenes/displacement.json";

class HostileInput : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kBinary)) GTEST_SKIP() << kBinary << " not built";
  }
  // A small render into the test's folder; `args` are the scene and options.
  CliRun render(const std::string& args) {
    return run_cli("render " + args + " --set image.width=32 --set image.height=32 -o " +
                   (dir.path() / "x.png").string());
  }
  TempDir dir;
};

std::string repeat(const std::string& s, int n) {
  std::string out;
  out.reserve(s.size() * std::size_t(n));
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

// 150,000 nested arrays (300 KB) and 100,000 nested objects overflowed the stack in the JSON
// library's recursive copy (SIGSEGV, exit 139) in render, scene and verify.
TEST_F(HostileInput, DeeplyNestedJsonIsRefusedAtItsLineAndColumn) {
  const auto arrays = dir.write("arrays.json", repeat("[", 150000) + repeat("]", 150000));
  const auto objects = dir.write("objects.json", repeat("{\"a\":", 100000) + "1" + repeat("}", 100000));
  for (const std::string command : {"render", "scene", "verify"}) {
    const std::string ref = command == "verify" ? " --ref " + dir.path().string() : "";
    CliRun r = run_cli(command + " " + arrays.string() + ref);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("tessref: error: " + arrays.string() +
                                    ": line 1, column 257: arrays and objects nested deeper than 256 levels"))
        << command;
    r = run_cli(command + " " + objects.string() + ref);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.output;
    // Each level is 5 bytes: the 257th object opens at column 5 * 256 + 1.
    EXPECT_THAT(r.output, HasSubstr(objects.string() + ": line 1, column 1281: arrays and objects nested deeper "
                                    "than 256 levels"))
        << command;
  }
  // A --set value is JSON too.
  const CliRun set = run_cli("scene --set 'camera=" + repeat("[", 300) + repeat("]", 300) + "'");
  EXPECT_EQ(set.exit_code, 2) << set.output;
  EXPECT_THAT(set.output, HasSubstr("--set camera: line 1, column 257: arrays and objects nested deeper than 256"));
}

// `render /dev/zero` read forever; a file past 64 MiB is refused before it is parsed.
TEST_F(HostileInput, SceneFilesMustBeRegularAndAtMost64MiB) {
  CliRun r = render("/dev/zero");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("tessref: error: /dev/zero: is not a regular file (a device, pipe or socket), "
                                  "not a scene file"));
  const auto big = dir.path() / "big.json";
  std::ofstream(big) << "{}";
  std::filesystem::resize_file(big, (std::uintmax_t(64) << 20) + 1);  // sparse
  r = render(big.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(big.string() + ": the scene file is larger than 64 MiB"));
  r = render(dir.path().string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(dir.path().string() + ": is a directory, not a scene file"));
}

}  // namespace
}  // namespace tessref
