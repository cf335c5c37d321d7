#pragma once
// One capture of the default scene at 128 x 128 for a whole test suite, made once in
// SetUpTestSuite (TempDir names itself after a test, which does not run yet then). A suite
// derives from DefaultCapture<Suite> and names itself in Suite::kName: each has its own folder.
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "../pipeline/test_util.h"
#include "gl_fixture.h"

namespace tessref::test {

inline const std::string kCaptureSize = " --set image.width=128 --set image.height=128";

template <class Suite>
class DefaultCapture : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::filesystem::temp_directory_path() / ("tessref_" + std::string(Suite::kName) + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    capture_ = run_cli("capture --out " + ref() + kCaptureSize);
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  void SetUp() override {
    TESSREF_REQUIRE_GL(ctx);
    ASSERT_EQ(capture_.exit_code, 0) << capture_.output;
  }
  static std::string ref() { return (dir_ / "ref").string(); }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }

  static inline std::filesystem::path dir_;
  static inline CliRun capture_;
};

}  // namespace tessref::test
