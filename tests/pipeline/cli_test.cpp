// The built `tessref render` binary: exit codes and messages for good and bad input.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include "io/image_output.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using test::TempDir;

using test::CliRun;
using test::kBinary;
CliRun run(const std::string& args) { return test::run_cli(args); }

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kBinary)) GTEST_SKIP() << kBinary << " not built";
  }
};

TEST_F(Cli, RendersTheDefaultScene) {
  TempDir dir;
  const auto out = dir.path() / "x.png";
  const CliRun r = run("render -o " + out.string() + " --threads 2 --set image.width=200 --set image.height=100 "
                    "--depth " + (dir.path() / "d.exr").string() + " --normals " + (dir.path() / "n.exr").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("tessref render: <default scene> with --set image.width, image.height -> " + out.string() +
                                  ", " + (dir.path() / "d.exr").string() + " (depth), " +
                                  (dir.path() / "n.exr").string() + " (normals) (200x100, 2 threads): "
                                  "256 triangles in, "));
  EXPECT_THAT(r.output, HasSubstr("fragments shaded; mesh "));
  EXPECT_THAT(r.output, HasSubstr(", raster+fs "));
  const Rgb8Image img = read_rgb8_image(out);
  EXPECT_EQ(img.width, 200);
  EXPECT_EQ(img.height, 100);
  EXPECT_EQ(read_float_image(dir.path() / "d.exr").channels, 1);
  EXPECT_EQ(read_float_image(dir.path() / "n.exr").channels, 3);
}

TEST_F(Cli, RendersTessellated) {
  TempDir dir;
  const CliRun r = run("render -o " + (dir.path() / "x.png").string() +
                    " --set tessellation.enabled=true --set image.width=64 --set image.height=64");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("256 triangles in, "));
  EXPECT_THAT(r.output, HasSubstr(" after tessellation, "));
}

TEST_F(Cli, RendersTheRepositoryDefaultScene) {
  TempDir dir;
  const CliRun r = run("render " + std::string(TESSREF_SOURCE_DIR) + "/scenes/default.json -o " +
                    (dir.path() / "x.png").string() + " --set image.width=64 --set image.height=64");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("scenes/default.json with --set image.width, image.height -> "));
}

TEST_F(Cli, RepeatPrintsStageTimesAndWritesTheSameImage) {
  TempDir dir;
  const std::string scene = " --threads 2 --set tessellation.enabled=true --set image.width=96 --set image.height=64";
  const auto once = dir.path() / "once.png", plain = dir.path() / "plain.png", thrice = dir.path() / "thrice.png";
  const CliRun r1 = run("render -o " + once.string() + scene + " --repeat 1");
  const CliRun r0 = run("render -o " + plain.string() + scene);
  const CliRun r3 = run("render -o " + thrice.string() + scene + " --repeat 3");
  ASSERT_EQ(r1.exit_code, 0) << r1.output;
  ASSERT_EQ(r0.exit_code, 0) << r0.output;
  ASSERT_EQ(r3.exit_code, 0) << r3.output;
  // The usual summary line, then one line of medians (min .. max) over the frames.
  const std::string num = "[0-9]+\\.[0-9]", ms = num + " ms";
  const auto stage = [&](const std::string& name) {
    return name + " " + ms + " \\(" + num + " \\.\\. " + ms + "\\)";
  };
  const std::string medians = ", median \\(min \\.\\. max\\): " + stage("vertex") + ", " +
                              stage("tessellation") + ", " + stage("raster\\+fs") + ", " + stage("frame") + "\n";
  EXPECT_THAT(r3.output, ::testing::MatchesRegex("tessref render: <default scene> with --set [^\n]*, write " + ms +
                                                 "\ntessref render: 3 frames" + medians));
  EXPECT_THAT(r1.output, ::testing::MatchesRegex("[^\n]*\ntessref render: 1 frame" + medians));
  EXPECT_THAT(r0.output, ::testing::Not(HasSubstr(" median ")));
  // The same counts, and the same image bytes, whatever the number of frames.
  const auto counts = [](const std::string& out) {
    const std::size_t begin = out.find(" threads): ");
    return out.substr(begin, out.find("; mesh") - begin);
  };
  EXPECT_EQ(counts(r3.output), counts(r1.output));
  EXPECT_EQ(counts(r0.output), counts(r1.output));
  const std::string bytes = test::read_file(once);
  EXPECT_FALSE(bytes.empty());
  EXPECT_EQ(test::read_file(plain), bytes);
  EXPECT_EQ(test::read_file(thrice), bytes);
}

TEST_F(Cli, BadRepeat) {
  TempDir dir;
  const auto out = dir.path() / "x.png";
  for (const std::string n : {"0", "-1", "abc", "1.5", "2x", "99999999999", "\"\""}) {
    SCOPED_TRACE(n);
    const CliRun r = run("render -o " + out.string() + " --repeat " + n);
    EXPECT_GE(r.exit_code, 100) << r.output;  // a malformed command line
    EXPECT_THAT(r.output, HasSubstr("--repeat: expected the number of frames, an integer from 1 to "));
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(Cli, BadInput) {
  TempDir dir;
  const std::string out = " -o " + (dir.path() / "x.png").string();
  struct Case {
    std::string args, message;
  };
  const auto bad_scene = dir.write("bad.json", "{\n  \"camera\": {\"eye\": [1, 2, 3]},\n  \"image\": {\"width\": 0}\n}\n");
  const auto broken = dir.write("broken.json", "{\n  \"camera\": {\"eye\": [1, 2, 3]\n}\n");
  const Case cases[] = {
      {"render /nonexistent.json" + out, "tessref: error: /nonexistent.json: no such scene file"},
      {"render " + bad_scene.string() + out,
       "tessref: error: " + bad_scene.string() + ": image.width: expected an integer in [1, 16384], got a number (0)"},
      {"render " + broken.string() + out, "tessref: error: " + broken.string() + ": line 4, column 1: JSON syntax error"},
      {"render --set camera.eye=nan,0,0" + out,
       "tessref: error: <default scene>: camera.eye: expected finite numbers, got nan at index 0 (from --set camera.eye)"},
      {"render --set camera.fov=30" + out, "tessref: error: <default scene>: camera.fov: unknown key"},
      {"render --set camera.eye" + out, "tessref: error: --set camera.eye: expected KEY=VALUE"},
      {"render --set mesh.type=file --set mesh.path=/usr/share/assimp/models/invalid/empty.obj" + out,
       "tessref: error: /usr/share/assimp/models/invalid/empty.obj: the file is empty"},
      {"render --set mesh.type=file --set mesh.path=/nonexistent.obj" + out,
       "tessref: error: /nonexistent.obj: no such file"},
      {"render -o " + (dir.path() / "x.unknownformat").string(), "x.unknownformat: this build's OpenImageIO cannot write color images as .unknownformat: OpenImageIO has no writer"},
      {"render -o /nonexistent/dir/x.png", "tessref: error: /nonexistent/dir/x.png: "},
      {"render --depth " + (dir.path() / "d.png").string() + out, "d.png: this build's OpenImageIO cannot write depth images (1 float channel) as .png"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const CliRun r = run(c.args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.message));
    EXPECT_THAT(r.output, ::testing::Not(HasSubstr("internal error")));
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.png"));
}

// Files in a folder, hidden ones (the temporaries) included.
std::vector<std::string> files_in(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST_F(Cli, TwoOutputsOnOneFileAreRefused) {
  TempDir dir;
  const std::string d = dir.path().string();
  CliRun r = run("render --set image.width=32 --set image.height=32 -o " + d + "/o.exr --depth " + d + "/o.exr");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("o.exr: --depth and -o name the same file"));
  r = run("render --set image.width=32 --set image.height=32 -o " + d + "/o.png --dump-tess " + d + "/./o.png");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--dump-tess and -o name the same file"));
  EXPECT_TRUE(files_in(dir.path()).empty());
}

TEST_F(Cli, OutputPathsAreCheckedBeforeAnyWorkAndWrittenAllOrNone) {
  TempDir dir;
  const std::string d = dir.path().string();
  CliRun r = run("render -o " + d + "/nodir/x.png");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("nodir/x.png: -o: the folder " + d + "/nodir does not exist"));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("tessref render:")));  // nothing was rendered
  // A bad --depth path: the good -o is not written either.
  r = run("render -o " + d + "/ok.png --depth " + d + "/nodir/d.exr");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--depth: the folder"));
  r = run("render -o " + d);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("names a folder, not a file"));
  EXPECT_TRUE(files_in(dir.path()).empty());
  // Success leaves exactly the outputs, no temporaries.
  r = run("render --set image.width=32 --set image.height=32 -o " + d + "/a.png --depth " + d +
          "/a.exr --dump-tess " + d + "/a.tess");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(files_in(dir.path()), (std::vector<std::string>{"a.exr", "a.png", "a.tess"}));
}

// Under a file-size limit every format fails with status 2 and leaves no file: the 8-bit writers
// that do not report failed writes are caught by reading the file back, libjpeg's exit() by the
// exit handler, the others by their own errors.
TEST_F(Cli, AWriteThatFailsLeavesNoFileAndExitsTwo) {
  for (const char* ext : {".png", ".bmp", ".tga", ".jpg", ".exr", ".tif", ".hdr"}) {
    TempDir dir;
    const std::string out = (dir.path() / (std::string("x") + ext)).string();
    // 16 blocks of 1 KiB: far less than a 1024x1024 image. SIGXFSZ ignored: writes fail with EFBIG.
    CliRun r;
    FILE* pipe = popen(("sh -c 'ulimit -f 16; trap \"\" XFSZ; exec " + kBinary + " render -o " + out +
                        "' 2>&1").c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::array<char, 4096> buf;
    for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) r.output.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    EXPECT_EQ(r.exit_code, 2) << ext << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("x" + std::string(ext))) << ext;
    EXPECT_TRUE(files_in(dir.path()).empty()) << ext << ": left " << ::testing::PrintToString(files_in(dir.path()));
  }
}

TEST_F(Cli, AnInterruptedRenderLeavesNoPartialFile) {
  for (const auto& [signal, status] : {std::pair<const char*, const char*>{"INT", "130"}, {"TERM", "143"}}) {
    SCOPED_TRACE(signal);
    TempDir dir;
    const std::string d = dir.path().string();
    // About a minute of frames, interrupted after one second.
    const std::string cmd = kBinary + " render --set tessellation.inner=64 --set tessellation.outer=64 --repeat 1000 -o " +
                            d + "/x.png --dump-tess " + d + "/x.tess";
    FILE* pipe = popen(("sh -c '" + cmd + " & p=$!; sleep 1; kill -" + signal + " $p; wait $p; echo status=$?' 2>&1").c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    std::array<char, 4096> buf;
    for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) output.append(buf.data(), n);
    pclose(pipe);
    EXPECT_THAT(output, HasSubstr("interrupted; unfinished output files removed"));
    EXPECT_THAT(output, HasSubstr(std::string("status=") + status));
    EXPECT_TRUE(files_in(dir.path()).empty()) << ::testing::PrintToString(files_in(dir.path()));
  }
}

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Every format is byte-stable across runs and clock changes (EXR and TIFF headers carry a DateTime
// that OpenImageIO would stamp with the current time). faketime comes from scripts/install-deps.sh.
TEST_F(Cli, OutputBytesDoNotDependOnTheClock) {
  if (std::system("command -v faketime > /dev/null 2>&1") != 0) GTEST_SKIP() << "faketime not installed";
  TempDir dir;
  const std::string d = dir.path().string();
  const std::string args = " render --set image.width=24 --set image.height=16";
  for (const char* ext : {".exr", ".tif", ".png", ".jpg", ".hdr", ".bmp", ".tga"}) {
    const std::string now = d + "/now" + ext, then = d + "/then" + ext;
    const std::string extras = " --depth %s_d.exr --normals %s_n.tif --dump-tess %s.tess";
    auto with = [&](const std::string& stem) {
      std::string e = extras;
      for (std::size_t at; (at = e.find("%s")) != std::string::npos;) e.replace(at, 2, d + "/" + stem);
      return e;
    };
    ASSERT_EQ(run(args.substr(1) + " -o " + now + with("now")).exit_code, 0);
    ASSERT_EQ(std::system(("faketime '2001-02-03 04:05:06' " + kBinary + args + " -o " + then + with("then") +
                           " > /dev/null").c_str()), 0);
    EXPECT_EQ(file_bytes(now), file_bytes(then)) << ext;
    EXPECT_FALSE(file_bytes(now).empty()) << ext;
    for (const char* suffix : {"_d.exr", "_n.tif", ".tess"})
      EXPECT_EQ(file_bytes(d + "/now" + suffix), file_bytes(d + "/then" + suffix)) << suffix;
  }
}

// Issue 11, defect 6: the formats the messages and --help list are the ones this build writes,
// and a format that cannot hold an output is refused before rendering, with the ones that can.
TEST_F(Cli, ImageFormatsAgreeWithWhatTheBuildWrites) {
  TempDir dir;
  // 32 pixels: OpenImageIO's JPEG 2000 writer leaves a file that does not read back below that
  // (the read-back check refuses it, exit 2).
  const std::string d = dir.path().string(), small = " --set image.width=32 --set image.height=32";
  const std::string color = writable_image_extensions(ImageKind::Color);
  const std::string depth = writable_image_extensions(ImageKind::Depth);
  EXPECT_THAT(color, HasSubstr(".png"));
  EXPECT_THAT(color, HasSubstr(".exr"));
  EXPECT_THAT(depth, HasSubstr(".exr"));
  EXPECT_THAT(depth, ::testing::Not(HasSubstr(".hdr")));  // RGB only
  EXPECT_THAT(depth, ::testing::Not(HasSubstr(".png")));  // integers only
  std::istringstream list(color);
  for (std::string ext; list >> ext;) {
    const CliRun r = run("render -o " + d + "/x" + ext + small);
    EXPECT_EQ(r.exit_code, 0) << ext << ": " << r.output;
  }
  std::istringstream depth_list(depth);
  for (std::string ext; depth_list >> ext;) {
    const CliRun r = run("render -o " + d + "/x.png --depth " + d + "/d" + ext + small);
    EXPECT_EQ(r.exit_code, 0) << ext << ": " << r.output;
    EXPECT_EQ(read_float_image(d + "/d" + ext).channels, 1) << ext;
  }
  std::filesystem::remove_all(dir.path());
  std::filesystem::create_directories(dir.path());
  CliRun r = run("render -o " + d + "/x.png --depth " + d + "/d.hdr" + small);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr(d + "/d.hdr: this build's OpenImageIO cannot write depth images (1 float channel) "
                                  "as .hdr: HDR can only support 3-channel images; it can as " + depth));
  r = run("render -o " + d + "/x.png --normals " + d + "/n.png" + small);
  EXPECT_THAT(r.output, HasSubstr("cannot write normal images (3 float channels) as .png: it stores 8 or 16-bit "
                                  "integers, not floats"));
  r = run("render -o " + d + "/x.xyz" + small);
  EXPECT_THAT(r.output, HasSubstr("cannot write color images as .xyz: OpenImageIO has no writer for this extension; "
                                  "it can as " + color));
  if (color.find(".pfm") == std::string::npos) {  // Debian 12's OpenImageIO lists .pfm, writes none
    r = run("render -o " + d + "/x.pfm" + small);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_THAT(r.output, HasSubstr("cannot write color images as .pfm"));
  }
  EXPECT_TRUE(files_in(dir.path()).empty()) << ::testing::PrintToString(files_in(dir.path()));
}

// Issue 11, defect 1: a link to a device cannot take a whole-file write and is refused before any
// work; a link to a file is followed, replacing the file and keeping the link.
TEST_F(Cli, OutputLinks) {
  TempDir dir;
  const std::filesystem::path full = dir.path() / "full.png", link = dir.path() / "link.png",
                              real = dir.path() / "real.png";
  std::filesystem::create_symlink("/dev/full", full);
  CliRun r = run("render -o " + full.string() + " --set image.width=16 --set image.height=16");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr(full.string() + ": -o: /dev/full is not a regular file (a device, pipe or socket)"));
  EXPECT_TRUE(std::filesystem::is_symlink(full));
  std::ofstream(real) << "old";
  std::filesystem::create_symlink(real, link);
  r = run("render -o " + link.string() + " --set image.width=16 --set image.height=16");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(read_rgb8_image(real).width, 16);
}

// Issue 11, defect 4: a dump's size is estimated before drawing where the levels are fixed, and
// checked while drawing where control shaders or adaptive levels choose them; either way a dump
// over --max-dump-bytes (or the free space) is refused with its size and leaves no file.
TEST_F(Cli, DumpSizeIsBoundedAndEstimated) {
  TempDir dir;
  const std::string d = dir.path().string(), small = " --set image.width=32 --set image.height=32";
  // The estimate is exact for binary dumps: 37632 records of 40 bytes and a 16-byte header.
  CliRun r = run("render -o " + d + "/x.png --dump-tess " + d + "/t.bin --max-dump-bytes 1505296" + small);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(std::filesystem::file_size(d + "/t.bin"), 1505296u);
  std::filesystem::remove_all(dir.path());
  std::filesystem::create_directories(dir.path());
  r = run("render -o " + d + "/x.png --dump-tess " + d + "/t.bin --max-dump-bytes 1505295" + small);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("t.bin: --dump-tess would write 1.5 MB (1505296 bytes) (37632 tessellated "
                                  "vertices), more than --max-dump-bytes 1505295"));
  // Adaptive levels: known only while drawing.
  r = run("render -o " + d + "/x.png --dump-tess " + d + "/t.txt --max-dump-bytes 100000 "
          "--set tessellation.adaptive.enabled=true --set tessellation.adaptive.pixels_per_segment=2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("t.txt: --dump-tess stopped after "));
  EXPECT_THAT(r.output, HasSubstr("more than --max-dump-bytes 100000; nothing was written"));
  // Far more than any disk: refused up front against the free space.
  r = run("render -o " + d + "/x.png --dump-tess " + d + "/t.bin --set tessellation.inner=64 "
          "--set tessellation.outer=64 --set mesh.torus.major_segments=4096 --set mesh.torus.minor_segments=4096");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("--dump-tess would write 4123.2 GB (4123168604176 bytes)"));
  EXPECT_THAT(r.output, HasSubstr(" free in "));
  EXPECT_TRUE(files_in(dir.path()).empty()) << ::testing::PrintToString(files_in(dir.path()));
}

// Issue 24, defect 5: room for the images is kept only on the file system they go to. A dump
// that fits a small file system alone is written there; with the colour image beside it, the
// refusal says how much room the image took (32x32: 16 bytes a pixel and 1 MiB). The small file
// system is a 2 MiB tmpfs mounted in a user namespace.
TEST_F(Cli, DumpOnASmallFileSystemKeepsRoomOnlyForTheImagesWrittenThere) {
  if (!test::can_mount_small_file_systems())
    GTEST_SKIP() << "unprivileged user namespaces are off here: no small file system to mount";
  TempDir dir;
  const std::filesystem::path mnt = dir.path() / "small";
  std::filesystem::create_directories(mnt);
  const std::string small = " --set image.width=32 --set image.height=32", m = mnt.string();
  CliRun r = test::run_on_small_file_system(
      mnt, "2m", kBinary + " render -o " + dir.path().string() + "/x.png --dump-tess " + m + "/t.bin" + small +
                     " && stat -c 'dump %s bytes' " + m + "/t.bin");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("dump 1505296 bytes"));
  r = test::run_on_small_file_system(mnt, "2m", kBinary + " render -o " + m + "/x.png --dump-tess " + m + "/t.bin" + small);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("more than the 1.0 MB (1032192 bytes) free in " + m +
                                  " (less 1.1 MB (1064960 bytes) for the 1 image written there)"));
}

// Issue 24, defect 6: a run killed with SIGKILL leaves its hidden temporary; the next run writing
// the same target removes it, and leaves alone one whose process is still running and files that
// only look alike.
TEST_F(Cli, TemporariesOfKilledRunsAreRemovedByTheNextRun) {
  TempDir dir;
  pid_t dead = fork();  // a process id that is certainly gone
  if (dead == 0) _exit(0);
  waitpid(dead, nullptr, 0);
  const std::string stale = ".x.tessref-" + std::to_string(dead) + "-0.png";
  const std::string live = ".x.tessref-" + std::to_string(getppid()) + "-0.png";  // the shell or ctest: running
  const std::string other = ".y.tessref-" + std::to_string(dead) + "-0.png";  // another target's
  for (const std::string& name : {stale, live, std::string(".x.tessref-notapid-0.png"), other})
    dir.write(name, "half an image");
  const CliRun r = run("render -o " + (dir.path() / "x.png").string() + " --set image.width=16 --set image.height=16");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / stale));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / live));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / ".x.tessref-notapid-0.png"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / other));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "x.png"));
}

// Issue 24, defects 5 and 6: a PNG cut short by a full file system is named as such, with the
// target's name (not its hidden temporary) and without libpng's own "IDAT: Read error" line, and
// nothing is left behind.
TEST_F(Cli, AFullFileSystemIsNamedAndLeavesNothing) {
  if (!test::can_mount_small_file_systems())
    GTEST_SKIP() << "unprivileged user namespaces are off here: no small file system to mount";
  TempDir dir;
  const std::filesystem::path mnt = dir.path() / "small";
  std::filesystem::create_directories(mnt);
  const std::string m = mnt.string();
  const CliRun r = test::run_on_small_file_system(
      mnt, "100k", kBinary + " render -o " + m + "/x.png; echo \"status $?\"; ls -A " + m + " | wc -l");
  EXPECT_THAT(r.output, HasSubstr("tessref: error: " + m + "/x.png: the file system holding it is full (0 bytes free)"));
  EXPECT_THAT(r.output, HasSubstr("status 2\n0\n"));  // exit 2, and no file left
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("libpng")));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr(".tessref-")));
}

// Issue 24, defect 8: on a terminal (script(1) gives the run one), a render that takes more than a
// second shows a progress line, redrawn at most five times a second and only when it changes,
// then clears it before the summary.
TEST_F(Cli, ProgressLineOnATerminal) {
  if (std::system("script --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "script(1) is not installed";
  TempDir dir;
  const auto t0 = std::chrono::steady_clock::now();
  const CliRun r = test::run_command("script -qec '" + kBinary + " render --repeat 30 --set shaders.program=twins -o " +
                                    (dir.path() / "x.png").string() + "' /dev/null");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  if (seconds < 1.5) GTEST_SKIP() << "the render took " << seconds << " s: too fast for a progress line";
  std::size_t lines = 0;
  for (std::size_t at = r.output.find("rendering ["); at != std::string::npos; at = r.output.find("rendering [", at + 1))
    ++lines;
  EXPECT_GE(lines, 1u) << r.output;
  EXPECT_LE(double(lines), 5.0 * seconds + 1.0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("%  "));  // the share, then the time so far
  // Cleared (overwritten with blanks) before the summary, and not drawn again after it.
  const std::size_t summary = r.output.find("tessref render: ");
  ASSERT_NE(summary, std::string::npos) << r.output;
  EXPECT_EQ(r.output.rfind("\r", summary), summary - 1) << r.output;
  EXPECT_EQ(r.output.find("rendering [", summary), std::string::npos) << r.output;
}

// Issue 11, defect 11: what a new user looks for.
TEST_F(Cli, VersionAndHelp) {
  CliRun r = run("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, "tessref 0.1.0\n");
  r = run("render --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("Image formats this build writes (-o): " + writable_image_extensions(ImageKind::Color)));
  EXPECT_THAT(r.output, HasSubstr("  depth (--depth): " + writable_image_extensions(ImageKind::Depth)));
  // The keys as the loader reads them, with what they allow and their defaults.
  auto key_line = [&](const std::string& key) {
    const std::size_t at = r.output.find("\n  " + key + " ");
    if (at == std::string::npos) return std::string("(missing)");
    const std::size_t end = r.output.find('\n', at + 1);
    const std::string line = r.output.substr(at + 3 + key.size(), end - at - 3 - key.size());
    return line.substr(line.find_first_not_of(' '));
  };
  EXPECT_EQ(key_line("camera.fit"), "true or false; default false");
  EXPECT_EQ(key_line("tessellation.spacing"), "one of equal, fractional_odd, fractional_even; default \"fractional_odd\"");
  EXPECT_EQ(key_line("lights[].position"), "[x, y, z]; default [-2.0,5.0,-10.0]");
  EXPECT_EQ(key_line("camera.far"), "a number greater than camera.near; default 50.0");
  EXPECT_EQ(run("scene --keys").output.substr(0, 12), "Scene keys (");
}

TEST_F(Cli, ScenePrintsTheMergedCheckedScene) {
  CliRun r = run("scene " + std::string(TESSREF_SOURCE_DIR) + "/scenes/spider.json --set material.ka=0.25");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["material"]["ka"], 0.25);                       // --set
  EXPECT_EQ(j["camera"]["fov_y_deg"], 11.0);                  // the file
  EXPECT_EQ(j["material"]["shininess"], 150.0);               // the default scene
  EXPECT_EQ(j["mesh"]["path"], "/usr/share/assimp/models/OBJ/spider.obj");
  // The printed scene reads back as the same scene.
  TempDir dir;
  const CliRun again = run("scene " + dir.write("s.json", r.output).string());
  EXPECT_EQ(nlohmann::json::parse(again.output), j);
  r = run("scene --set camera.near=60");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("camera.far: must be greater than camera.near (60)"));
}

TEST_F(Cli, DiffComparesTwoImages) {
  TempDir dir;
  const std::string d = dir.path().string(), small = " --set image.width=48 --set image.height=32";
  ASSERT_EQ(run("render -o " + d + "/a.png" + small).exit_code, 0);
  ASSERT_EQ(run("render -o " + d + "/b.png --set material.ka=0.41" + small).exit_code, 0);
  ASSERT_EQ(run("render -o " + d + "/big.png").exit_code, 0);
  CliRun r = run("diff " + d + "/a.png " + d + "/a.png");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("(48x32, 3 channels): 0 pixels (0%) differ by more than the tolerance 0"));
  r = run("diff " + d + "/a.png " + d + "/b.png --diff " + d + "/d.png");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("largest difference 0.0117648 (3.0/255)"));
  EXPECT_EQ(read_rgb8_image(d + "/d.png").width, 48);
  r = run("diff " + d + "/a.png " + d + "/b.png --tolerance 3/255 --json");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["pixels_above_tolerance"], 0);
  EXPECT_GT(j["pixels_above_1_255"].get<int>(), 0);
  EXPECT_NEAR(j["max_difference"].get<double>(), 3.0 / 255.0, 1e-6);
  r = run("diff " + d + "/a.png " + d + "/big.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("a.png is 48x32, " + d + "/big.png is 1024x1024: nothing to compare"));
  r = run("diff " + d + "/a.png " + d + "/none.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("none.png: cannot read image"));
  r = run("diff " + d + "/a.png " + d + "/b.png --tolerance -1");
  EXPECT_THAT(r.output, HasSubstr("--tolerance: expected a number >= 0 or N/255, got '-1'"));
}

// Issue 11, defect 11: the summary names the scene as drawn (with the keys --set changed) and
// every file written.
TEST_F(Cli, SummaryNamesTheSceneAndEveryFileWritten) {
  TempDir dir;
  const std::string d = dir.path().string();
  const CliRun r = run("render --set image.width=32 --set image.height=24 -o " + d + "/x.png --depth " + d +
                       "/d.exr --normals " + d + "/n.exr --dump-tess " + d + "/t.bin");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("tessref render: <default scene> with --set image.width, image.height -> " + d +
                                  "/x.png, " + d + "/d.exr (depth), " + d + "/n.exr (normals), " + d +
                                  "/t.bin (37632 tessellated vertices) (32x24, "));
}

// Issue 11, defect 9: an image of the background alone says why.
TEST_F(Cli, NothingDrawnIsAWarning) {
  TempDir dir;
  const std::string out = " -o " + (dir.path() / "x.png").string() + " --set image.width=32 --set image.height=32";
  CliRun r = run("render --set camera.target=0,50,0" + out);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("tessref: warning: nothing was drawn (0 fragments shaded): of 64768 triangles, "
                                  "64768 lie outside the view volume"));
  r = run("render --set tessellation.outer=0" + out);
  EXPECT_THAT(r.output, HasSubstr("256 patches were discarded by their levels"));
  // From inside a sphere every face is seen from behind.
  r = run("render --set mesh.type=icosphere --set camera.eye=0,0,0.01 --set camera.target=0,0,1 "
          "--set camera.near=0.001" + out);
  EXPECT_THAT(r.output, ::testing::ContainsRegex("outside the view volume, [1-9][0-9]* were culled \\(back-facing"));
  // Issue 24: every depth rounds to the cleared 1 and fails GL_LESS: the depth test is named, not the camera.
  r = run("render --set camera.near=1e-30 --set camera.far=1e30" + out);
  EXPECT_THAT(r.output, ::testing::ContainsRegex("nothing was drawn \\(0 fragments shaded\\): [1-9][0-9]* fragments "
                                                 "covered pixels but failed the depth test. Check camera.near"));
  r = run("render" + out);
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("warning")));
}

TEST_F(Cli, CameraFitFromTheCommandLine) {
  TempDir dir;
  const std::string out = (dir.path() / "x.png").string();
  const CliRun r = run("render -o " + out + " --set camera.fit=true --set camera.eye=0,0,500 --set image.width=64 "
                       "--set image.height=64");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("warning")));
  const Rgb8Image img = read_rgb8_image(out);
  std::size_t lit = 0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 3) lit += img.pixels[i] != img.pixels[0];
  EXPECT_GT(lit, 64u * 64u / 4);  // the torus fills the frame from 500 units away
}

TEST_F(Cli, DumpOptionErrors) {
  TempDir dir;
  const std::string d = dir.path().string();
  CliRun r = run("render -o " + d + "/x.png --dump-tess " + d + "/t.bin --set tessellation.enabled=false");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("--dump-tess: the scene does not tessellate"));
  for (const char* bad : {"0", "abc", "-5"}) {
    r = run("render -o " + d + "/x.png --dump-tess " + d + "/t.bin --max-dump-bytes " + bad);
    EXPECT_GE(r.exit_code, 100) << bad << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("--max-dump-bytes")) << bad;
  }
  EXPECT_TRUE(files_in(dir.path()).empty()) << ::testing::PrintToString(files_in(dir.path()));
}

// Issue 11, defect 10: an empty or malformed level is said to be one.
TEST_F(Cli, TpgLevelLists) {
  CliRun r = run("tpg --outer \"\"");
  EXPECT_GE(r.exit_code, 100);
  EXPECT_THAT(r.output, HasSubstr("--outer: expected a level (a number, nan or inf), got an empty value"));
  r = run("tpg --outer 1,x,1 --inner 1");
  EXPECT_THAT(r.output, HasSubstr("--outer: expected a level (a number, nan or inf), got 'x'"));
  r = run("tpg --outer 1,1,1 --inner nan");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(Cli, BadOptions) {
  for (const std::string args : {"render --threads -1", "render --frobnicate", "render a.json b.json"}) {
    SCOPED_TRACE(args);
    const CliRun r = run(args);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.exit_code, 3) << r.output;  // not an internal error
  }
  // A word where a number goes is said to be no number, not "out of range" (issue 11, defect 10).
  for (const std::string args : {"render --threads abc", "shader-test --threads abc x.shader_test",
                                 "shader-test --batch-lanes two x.shader_test", "tpg --outer 1,1,1 --max-level x"}) {
    SCOPED_TRACE(args);
    const CliRun r = run(args);
    EXPECT_GE(r.exit_code, 100) << r.output;  // a malformed command line
    EXPECT_THAT(r.output, HasSubstr("expected an integer, got '")) << r.output;
    EXPECT_THAT(r.output, ::testing::Not(HasSubstr("not in range"))) << r.output;
  }
}

}  // namespace
}  // namespace tessref
