// `tessref tpg` end to end: the printed stream, its formats, discarded patches and bad input; and,
// where the GL reference runner was built and a context starts, the same bytes as
// `tessref-glref tpg` capturing llvmpipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {

struct CmdResult {
  int status = -1;
  std::string out;
};

CmdResult run(const std::string& args) {
  const std::string cmd = args + " 2>&1";
  CmdResult r;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  if (!pipe) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe.get())) > 0) r.out.append(buf.data(), n);
  const int raw = pclose(pipe.release());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

const std::string kTessref = std::string(TESSREF_BINARY_DIR) + "/cli/tessref";
const std::string kGlref = std::string(TESSREF_BINARY_DIR) + "/glref/tessref-glref";

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST(TpgCli, PrintsOneLinePerEmittedVertex) {
  const CmdResult r = run(kTessref + " tpg --spacing fractional_odd --outer 4,4,4 --inner 4");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(lines(r.out), 111);  // 37 triangles
  EXPECT_NE(r.out.find("0.733337402"), std::string::npos);

  const CmdResult one = run(kTessref + " tpg --outer 1,1,1 --inner 1");
  EXPECT_EQ(one.out, "0 1 0\n0 0 1\n1 0 0\n");
  const CmdResult hex = run(kTessref + " tpg --outer 1,1,1 --inner 1 --format hex");
  EXPECT_EQ(hex.out, "00000000 3f800000 00000000\n00000000 00000000 3f800000\n"
                     "3f800000 00000000 00000000\n");
  const CmdResult quads = run(kTessref + " tpg --domain quads --outer 1,1,1,1 --inner 1,1");
  EXPECT_EQ(quads.out, "0 0\n1 0\n0 1\n1 0\n1 1\n0 1\n");
  const CmdResult points = run(kTessref + " tpg --domain isolines --outer 2,3 --point-mode");
  EXPECT_EQ(lines(points.out), 8);  // 2 lines x 4 points
}

TEST(TpgCli, DiscardedPatchPrintsNothing) {
  for (const char* outer : {"0,4,4", "nan,4,4", "-1,4,4"}) {
    const CmdResult r = run(kTessref + " tpg --outer " + outer + " --inner 4");
    EXPECT_EQ(r.status, 0) << outer;
    EXPECT_EQ(r.out, "") << outer;
  }
}

TEST(TpgCli, BadInputIsAClearError) {
  CmdResult r = run(kTessref + " tpg --outer 4,4 --inner 4");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--outer: triangles take 3 outer levels, got 2"), std::string::npos) << r.out;
  r = run(kTessref + " tpg --spacing odd --outer 4,4,4 --inner 4");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--spacing"), std::string::npos) << r.out;
  r = run(kTessref + " tpg --outer 4,x,4 --inner 4");
  EXPECT_NE(r.status, 0);
}

TEST(TpgCli, SameBytesAsTheGlReference) {
  if (!std::filesystem::exists(kGlref)) GTEST_SKIP() << "tessref-glref not built";
  if (run(kGlref + " info").status != 0) GTEST_SKIP() << "no GL context";
  const char* cases[] = {
      "--spacing fractional_odd --outer 4,4,4 --inner 4",
      "--spacing fractional_even --winding cw --outer 2.5,7.25,13 --inner 5.5 --format hex",
      "--domain quads --spacing fractional_odd --outer 3.3,1,7,2.2 --inner 5,1.5 --format hex",
      "--domain isolines --spacing equal --outer 3.5,6.1 --format hex",
      "--domain triangles --spacing equal --point-mode --outer 64,1,33 --inner 0.5 --format hex",
  };
  for (const char* c : cases) {
    const CmdResult ours = run(kTessref + " tpg " + c), gl = run(kGlref + " tpg " + c);
    ASSERT_EQ(gl.status, 0) << gl.out;
    EXPECT_EQ(ours.out, gl.out) << c;
  }
}

}  // namespace
