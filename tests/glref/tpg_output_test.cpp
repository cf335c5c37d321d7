// Output formats, level files and the tessref-glref executable end to end.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "common/error.h"
#include "gl_fixture.h"
#include "glref/levels_file.h"
#include "glref/tess_capture.h"
#include "glref/tpg_output.h"

namespace tessref::glref {
namespace {

TEST(TpgOutput, TextAndHex) {
  const std::vector<glm::vec3> v = {{0.0f, 1.0f, 0.0f}, {48060.0f / 65536.0f, 0.5f, -0.0f}};
  EXPECT_EQ(format_stream(TessDomain::Triangles, v, CoordFormat::Text), "0 1 0\n0.733337402 0.5 -0\n");
  EXPECT_EQ(format_stream(TessDomain::Quads, v, CoordFormat::Text), "0 1\n0.733337402 0.5\n");
  EXPECT_EQ(format_stream(TessDomain::Triangles, v, CoordFormat::Hex),
            "00000000 3f800000 00000000\n3f3bbc00 3f000000 80000000\n");
  EXPECT_EQ(format_stream(TessDomain::Isolines, {}, CoordFormat::Hex), "");
  EXPECT_EQ(format_sweep_line(TessDomain::Isolines, 7, v), "7 2 00000000 3f800000 3f3bbc00 3f000000\n");
  EXPECT_EQ(format_sweep_line(TessDomain::Triangles, 3, {}), "3 0\n");
}

TEST(LevelsFile, ParsesSpecialsAndSkipsComments) {
  std::istringstream in("# header\n\n1 2 3 4 5 6\n  nan inf -inf -1 0.5 0x1.000002p+0\nNaN INF 1e40 1 1 1\n");
  const auto l = read_levels(in, "mem");
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[0].outer, (std::array<float, 4>{1, 2, 3, 4}));
  EXPECT_EQ(l[0].inner, (std::array<float, 2>{5, 6}));
  EXPECT_TRUE(std::isnan(l[1].outer[0]));
  EXPECT_EQ(l[1].outer[1], std::numeric_limits<float>::infinity());
  EXPECT_EQ(l[1].outer[2], -std::numeric_limits<float>::infinity());
  EXPECT_EQ(l[1].inner[1], 1.0f + 0x1p-23f);
  EXPECT_TRUE(std::isnan(l[2].outer[0]));
  EXPECT_EQ(l[2].outer[2], std::numeric_limits<float>::infinity());  // overflow rounds to inf
}

TEST(LevelsFile, RejectsMalformedLinesWithTheirLocation) {
  std::istringstream short_line("1 1 1 1 1 1\n1 2 3\n");
  try {
    read_levels(short_line, "f.txt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.txt:2"), std::string::npos) << e.what();
  }
  std::istringstream junk("1 1 1 1 1 1x\n");
  EXPECT_THROW(read_levels(junk, "j"), InputError);
  EXPECT_THROW(read_levels_file("/nonexistent/levels.txt"), InputError);
}

const std::string kExe = std::string(TESSREF_BINARY_DIR) + "/glref/tessref-glref";

// The executable is a separate target: building test_glref alone does not build it.
#define TESSREF_REQUIRE_EXE()                                                                 \
  if (!std::filesystem::exists(kExe)) {                                                       \
    GTEST_SKIP() << kExe << " is not built (cmake --build ... --target tessref-glref)";       \
  }

std::string run(const std::string& args, int* status = nullptr) {
  const std::string cmd = kExe + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return "popen failed";
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  const int rc = pclose(p);
  if (status) *status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  return out;
}

TEST(Cli, TpgMatchesTheLibrary) {
  TESSREF_REQUIRE_EXE();
  TESSREF_REQUIRE_GL(ctx);
  TessLayout layout;
  layout.spacing = TessSpacing::FractionalEven;
  TessLevels l;
  l.outer = {3.5f, 2.0f, 7.25f, 1.0f};
  l.inner = {5.0f, 1.0f};
  const auto coords = capture_tess_coords(*ctx, layout, {l});
  const std::string common = "tpg --domain triangles --spacing fractional_even --winding ccw --outer 3.5,2,7.25 --inner 5";
  int rc = -1;
  EXPECT_EQ(run(common + " --format hex", &rc), format_stream(layout.domain, coords[0], CoordFormat::Hex));
  EXPECT_EQ(rc, 0);
  EXPECT_EQ(run(common), format_stream(layout.domain, coords[0], CoordFormat::Text));
  EXPECT_EQ(run("tpg --outer nan,1,1 --inner 3", &rc), "");  // discarded: nothing
  EXPECT_EQ(rc, 0);
}

TEST(Cli, TpgSweepWritesOneLinePerPatch) {
  TESSREF_REQUIRE_EXE();
  TESSREF_REQUIRE_GL(ctx);
  const std::string path = ::testing::TempDir() + "/glref_sweep_levels.txt";
  {
    std::ofstream f(path);
    f << "1 1 1 1 1 1\nnan 1 1 1 1 1\n4 4 4 4 4 4\n";
  }
  TessLayout layout;
  layout.domain = TessDomain::Quads;
  layout.spacing = TessSpacing::FractionalOdd;
  layout.winding = TessWinding::Cw;
  std::ifstream in(path);
  const auto levels = read_levels(in, path);
  const auto coords = capture_tess_coords(*ctx, layout, levels);
  std::string expected;
  for (std::size_t i = 0; i < coords.size(); ++i) expected += format_sweep_line(layout.domain, i, coords[i]);
  int rc = -1;
  EXPECT_EQ(run("tpg-sweep --domain quads --spacing fractional_odd --winding cw --levels " + path, &rc), expected);
  EXPECT_EQ(rc, 0);
}

TEST(Cli, BadInputIsAnErrorNotACrash) {
  TESSREF_REQUIRE_EXE();
  int rc = -1;
  EXPECT_NE(run("tpg --domain hexagons --outer 1,1,1", &rc).find("unknown domain"), std::string::npos);
  EXPECT_EQ(rc, 2);
  EXPECT_NE(run("tpg --outer 1,2,3,4,5", &rc).find("--outer"), std::string::npos);
  EXPECT_EQ(rc, 2);
  EXPECT_NE(run("tpg-sweep --levels /nonexistent", &rc).find("cannot open"), std::string::npos);
  EXPECT_EQ(rc, 2);
  run("--platform wayland info", &rc);
  EXPECT_EQ(rc, 2);
}

}  // namespace
}  // namespace tessref::glref
