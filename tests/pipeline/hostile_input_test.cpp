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

// layout(vertices = 33) reached the pipeline's internal check (exit 3).
TEST_F(HostileInput, OutputPatchPastGlMaxPatchVerticesIsACompileError) {
  std::string tesc;
  {
    std::ifstream in(kSource + "/stages/schemes/flat.tesc");
    tesc.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t at = tesc.find("layout(vertices = 3) out;");
  ASSERT_NE(at, std::string::npos);
  tesc.replace(at, 25, "layout(vertices = 33) out;");
  const auto file = dir.write("big.tesc", tesc);
  const CliRun r = render(kDisplacement + " --set shaders.tess_control=" + file.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(file.string() + ":4: error: layout(vertices = 33) is more than "
                                                  "GL_MAX_PATCH_VERTICES (32)"));
}

// A fragment shader with a local array of `n` floats, indexed by the fragment so it stays.
std::string fragment_with_array(const std::string& n) {
  return "#version 450\nlayout(location = 0) in vec3 v_world_position;\nlayout(location = 1) in vec3 v_world_normal;\n"
         "layout(location = 0) out vec4 out_color;\nlayout(location = 1) out vec4 out_normal;\n"
         "void main() {\n  float a[" + n + "];\n  a[int(gl_FragCoord.x)] = v_world_normal.x;\n"
         "  out_color = vec4(a[int(gl_FragCoord.y)]);\n  out_normal = vec4(v_world_normal, 1.0);\n}\n";
}

// float a[100000000] ended in std::bad_alloc (exit 3); float a[10000000] took 10.3 GB for a
// 32 x 32 image. Both are refused when the program is built, naming the stage and the variable.
TEST_F(HostileInput, LocalArraysPastTheExecutorsLimitsNameTheStageAndVariable) {
  const auto huge = dir.write("huge.frag", fragment_with_array("100000000"));
  CliRun r = render(kDisplacement + " --set shaders.fragment=" + huge.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("shaders: fragment shader: 'a' is 400000000 bytes: one variable holds at most 16 MiB"));
  const auto large = dir.write("large.frag", fragment_with_array("10000000"));
  r = render(kDisplacement + " --set shaders.fragment=" + large.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("fragment shader: 'a' is 40000000 bytes"));
  // Under the per-variable limit, over the per-invocation one (1 MiB).
  const auto mid = dir.write("mid.frag", fragment_with_array("1000000"));
  r = render(kDisplacement + " --set shaders.fragment=" + mid.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("fragment shader: 'a' takes 4000000 bytes per invocation"));
  EXPECT_THAT(r.output, HasSubstr("more than the executor's private memory limit of 1048576 bytes per invocation"));
  // A modest array draws.
  const auto small = dir.write("small.frag", fragment_with_array("64"));
  r = render(kDisplacement + " --set shaders.fragment=" + small.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// `while (true) {}` has no results, so dead-code removal dropped it: the draw finished with
// exit 0 and the outputs unwritten (issue 23). It now runs into the instruction budget in render,
// render --check and inspect alike.
TEST_F(HostileInput, AnEmptyEndlessLoopStopsAtTheBudget) {
  const auto frag = dir.write("endless.frag",
                              "#version 450\nlayout(location = 0) in vec3 v_world_position;\n"
                              "layout(location = 0) out vec4 out_color;\nvoid main() {\n  while (true) {}\n"
                              "  out_color = vec4(1.0);\n}\n");
  const std::string sets = kDisplacement + " --set shaders.fragment=" + frag.string() +
                           " --set shaders.max_instructions=100000";
  const std::string message = "fragment shader, fragment (";
  const std::string budget = "line 5: instruction budget of 100000 exceeded (an infinite loop?)";
  for (const std::string& args : {std::string(""), std::string(" --check")}) {
    const CliRun r = render(sets + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr(message)) << args;
    EXPECT_THAT(r.output, HasSubstr(budget)) << args;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.png")) << args;
  }
  const CliRun r = run_cli("inspect " + sets + " --set image.width=32 --set image.height=32 --patch 3");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(budget));
}

// --scale nan wrote a black image and --scale -5 printed DBL_MAX in 310 digits.
TEST_F(HostileInput, DiffScaleMustBeFiniteAndPositive) {
  const std::string image = kSource + "/tests/golden/default.png";
  for (const std::string scale : {"nan", "-5", "0", "inf", "1e999", "2x"}) {
    const CliRun r = run_cli("diff " + image + " " + image + " --diff " + (dir.path() / "d.png").string() +
                             " --scale " + scale);
    EXPECT_EQ(r.exit_code, 2) << scale << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("tessref: error: --scale: expected a finite number greater than 0, got '" +
                                    scale + "'"));
    EXPECT_LT(r.output.size(), 200u) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "d.png"));
  }
  const CliRun ok = run_cli("diff " + image + " " + image + " --diff " + (dir.path() / "d.png").string() +
                            " --scale 0.5");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

// The whole process has a memory budget (--max-memory, TESSREF_MAX_MEMORY; default 3/4 of the
// machine): a run that needs more stops with exit 2 and the budget named, wherever the
// allocation happened (here a 4096 x 4096 render: colour, depth and normals are 576 MiB of
// framebuffer; the run peaks at 864 MiB resident).
TEST_F(HostileInput, MemoryPastTheBudgetIsAnErrorNamingIt) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's shadow memory passes any budget: the budget is not set in its builds";
#endif
  const std::string out = (dir.path() / "big.png").string();
  const std::string big = " --set image.width=4096 --set image.height=4096 -o " + out;
  const std::string message =
      "tessref: error: out of memory: this run needed more than its memory budget of 320.0 MiB (--max-memory SIZE "
      "or TESSREF_MAX_MEMORY;";
  for (const std::string& command : {"--max-memory 320M render" + big, "render --max-memory 320M" + big,
                                    "render --max-memory 320MiB" + big}) {
    const CliRun r = run_cli(command);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr(message)) << command;
    EXPECT_FALSE(std::filesystem::exists(out)) << command;
  }
  CliRun r = test::run_command("TESSREF_MAX_MEMORY=320M " + kBinary + " render" + big);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(message));
  // The same render within a budget, and with none (0).
  r = run_cli("render --max-memory 2G" + big);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = test::run_command("TESSREF_MAX_MEMORY=0 " + kBinary + " render" + big);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // Under 256 MiB tessref's own libraries do not load (and x265, behind OpenImageIO's HEIF
  // writer, hung when it could not start a thread): refused.
  r = run_cli("render --max-memory 100M" + big);
  EXPECT_GE(r.exit_code, 100) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--max-memory: a budget under 256.0 MiB cannot load tessref's libraries"));
  // A size CLI11 cannot read is refused before anything runs.
  r = run_cli("render --max-memory lots" + big);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("--max-memory"));
  // --help gives the default for this machine.
  r = run_cli("--help");
  EXPECT_THAT(r.output, HasSubstr("Default: 3/4 of this machine's memory"));
}

}  // namespace
}  // namespace tessref
