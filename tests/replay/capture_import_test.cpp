// tessref import of tests/replay/replay_app.c's frame, captured here on the system's GL driver
// (llvmpipe) with apitrace and with RenderDoc: the imported frame renders the application's own
// glReadPixels image, the two importers give the same scene, and every capture the importer must
// refuse exits 2 with its reason and leaves no folder.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "../pipeline/test_util.h"

namespace tessref::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kApp = TESSREF_REPLAY_APP;
const std::string kLyingBlob = std::string(TESSREF_SOURCE_DIR) + "/tests/replay/lying_blob.py";
const std::string kSameScene = std::string(TESSREF_SOURCE_DIR) + "/tests/replay/same_scene.py";

bool have(const char* tool) { return std::system((std::string("command -v ") + tool + " >/dev/null 2>&1").c_str()) == 0; }

// One trace per application variant, captured once per test program into a shared folder.
class ApitraceImport : public ::testing::Test {
 protected:
  static fs::path folder() {
    static const fs::path dir = [] {
      const fs::path d = fs::temp_directory_path() / ("tessref_replay_" + std::to_string(::getpid()));
      fs::create_directories(d);
      return d;
    }();
    return dir;
  }
  static void TearDownTestSuite() { fs::remove_all(folder()); }

  // The trace of `replay_app FLAGS OUT.ppm` (apitrace trace --api egl), made on first use.
  static fs::path trace(const std::string& name, const std::string& flags = "") {
    const fs::path t = folder() / (name + ".trace");
    if (!fs::exists(t)) {
      const CliRun r = run_command("apitrace trace --api egl -o '" + t.string() + "' '" + kApp + "' " + flags + " '" +
                                   (folder() / (name + ".ppm")).string() + "'");
      EXPECT_EQ(r.exit_code, 0) << r.output;
    }
    return t;
  }
  static fs::path app_image(const std::string& name) { return folder() / (name + ".ppm"); }

  void SetUp() override {
    if (!have("apitrace") || !have("eglretrace")) GTEST_SKIP() << "apitrace is not installed (Debian package apitrace)";
  }

  // An import that must fail: exit 2, the reason on stderr, and no output folder (nor a staging one).
  void expect_refused(const fs::path& capture, const std::string& extra, const std::string& reason) {
    const fs::path parent = folder() / "refused";
    fs::create_directories(parent);
    const fs::path out = parent / "imported";
    const CliRun r = run_cli("import '" + capture.string() + "' --out '" + out.string() + "' " + extra);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr(reason));
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(fs::is_empty(parent)) << "a staging folder was left behind";
  }
};

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

// Pixels of two 8-bit images more than 1/255 apart, by `tessref diff --json`.
long long pixels_over_one_step(const fs::path& a, const fs::path& b) {
  const CliRun r = run_cli("diff --json --tolerance 1/255 '" + a.string() + "' '" + b.string() + "'");
  EXPECT_LE(r.exit_code, 1) << r.output;
  const auto j = nlohmann::json::parse(r.output.substr(r.output.find('{')));
  return j.at("pixels_above_1_255").get<long long>();
}

TEST_F(ApitraceImport, TheImportedFrameRendersTheApplicationsImage) {
  const fs::path t = trace("frame");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  const CliRun import = run_cli("import --quiet '" + t.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(import.exit_code, 0) << import.output;
  EXPECT_THAT(import.output, HasSubstr("scene.json (3 draws), gpu.png"));
  const CliRun render = run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "tessref.png").string() + "'");
  ASSERT_EQ(render.exit_code, 0) << render.output;
  // Measured: identical to the application's own read-back (0 of 65,536 pixels differ at all).
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "tessref.png", app_image("frame")), 0);
  // The driver's image from retracing is the application's.
  EXPECT_EQ(pixels_over_one_step(out / "gpu.png", app_image("frame")), 0);
}

TEST_F(ApitraceImport, TheSceneSaysWhatTheApplicationSaid) {
  const fs::path t = trace("frame");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  ASSERT_EQ(run_cli("import --quiet '" + t.string() + "' --out '" + out.string() + "'").exit_code, 0);
  const nlohmann::json scene = read_json(out / "scene.json");
  ASSERT_EQ(scene.at("draws").size(), 3u);
  EXPECT_EQ(scene.at("shaders").at("scene_uniforms"), false);
  EXPECT_EQ(scene.at("framebuffer").at("color").at(0).at("internalformat"), "GL_RGBA8");
  EXPECT_EQ(scene.at("framebuffer").at("depth").at("internalformat"), "GL_DEPTH_COMPONENT24");
  const nlohmann::json& plane = scene.at("draws").at(0);
  EXPECT_EQ(plane.at("mode"), "GL_TRIANGLE_STRIP");
  EXPECT_EQ(plane.at("clear").at("depth"), 1.0);
  EXPECT_EQ(plane.at("clear").at("color").at(0).get<double>(), double(0.05f));
  const nlohmann::json& gems = scene.at("draws").at(1);
  EXPECT_EQ(gems.at("mode"), "GL_PATCHES");
  EXPECT_EQ(gems.at("instancecount"), 3);
  EXPECT_EQ(gems.at("basevertex"), 3);
  EXPECT_EQ(gems.at("elements").at("offset"), 10);
  EXPECT_EQ(gems.at("elements").at("type"), "GL_UNSIGNED_SHORT");
  const nlohmann::json& arrays = gems.at("vertex_arrays");
  EXPECT_EQ(arrays.at("in_normal").at("type"), "GL_SHORT");
  EXPECT_EQ(arrays.at("in_normal").at("normalized"), true);
  EXPECT_EQ(arrays.at("in_normal").at("offset"), 12);
  EXPECT_EQ(arrays.at("in_color").at("stride"), 24);
  EXPECT_EQ(arrays.at("in_offset").at("divisor"), 1);
  // The per-instance offsets were written through glMapBufferRange: the bytes are the memcpy's.
  const std::string instance_file = scene.at("buffers").at(arrays.at("in_offset").at("buffer").get<std::string>()).at("file");
  std::ifstream in(out / instance_file, std::ios::binary);
  float offsets[9] = {};
  in.read(reinterpret_cast<char*>(offsets), sizeof offsets);
  EXPECT_EQ(offsets[0], -0.85f);
  EXPECT_EQ(offsets[4], 0.25f);
  const nlohmann::json block = gems.at("uniform_buffers").at(0);
  EXPECT_EQ(block.at("binding"), 1);
  EXPECT_EQ(block.at("offset"), 256);
  EXPECT_EQ(block.at("size"), 128);
  const nlohmann::json& texture = gems.at("shaders").at("textures").at("u_albedo");
  EXPECT_EQ(texture.at("generate_mipmap"), true);
  EXPECT_EQ(texture.at("min_filter"), "linear_mipmap_linear");
  EXPECT_EQ(texture.at("wrap_t"), "mirrored_repeat");
  EXPECT_EQ(gems.at("shaders").at("uniforms").count("u_albedo"), 0u) << "a sampler's unit is not a uniform value";
  const nlohmann::json& bicubic = scene.at("draws").at(2);
  EXPECT_EQ(bicubic.at("patch_vertices"), 16);
  EXPECT_EQ(bicubic.at("count"), 16);
  EXPECT_EQ(bicubic.at("shaders").at("uniforms").at("u_level").at(0), 8.0);
  const std::string report = [&] {
    std::ifstream r(out / "report.txt");
    return std::string(std::istreambuf_iterator<char>(r), {});
  }();
  EXPECT_THAT(report, HasSubstr("everything the draws read was carried"));
}

TEST_F(ApitraceImport, AnEventPicksAnEarlierDrawAndItsImage) {
  const fs::path t = trace("frame");
  const CliRun dump = run_command("apitrace dump '" + t.string() + "' | grep glDrawElementsInstancedBaseVertex");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(dump.output, m, std::regex("^(\\d+) glDrawElementsInstancedBaseVertex"))) << dump.output;
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  const CliRun import = run_cli("import --quiet '" + t.string() + "' --out '" + out.string() + "' --event " + m[1].str());
  ASSERT_EQ(import.exit_code, 0) << import.output;
  EXPECT_EQ(read_json(out / "scene.json").at("draws").size(), 2u);
  ASSERT_EQ(run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "t.png").string() + "'").exit_code, 0);
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "t.png", out / "gpu.png"), 0);
  // Not the whole frame's image: the bicubic patch comes after this draw.
  EXPECT_GT(pixels_over_one_step(out / "gpu.png", app_image("frame")), 1000);
}

TEST_F(ApitraceImport, BadCapturesExitTwoAndLeaveNothing) {
  const fs::path t = trace("frame");
  TempDir tmp;
  {  // the first 30,000 bytes of the trace
    std::ifstream in(t, std::ios::binary);
    std::string bytes(30000, '\0');
    in.read(bytes.data(), bytes.size());
    tmp.write("truncated.trace", bytes);
  }
  expect_refused(tmp.path() / "truncated.trace", "", "is truncated");
  expect_refused(app_image("frame"), "", "is neither a RenderDoc capture (.rdc) nor an apitrace trace");
  expect_refused(tmp.path() / "missing.trace", "", "is not a file");
  expect_refused(trace("untessellated", "--untessellated"), "", "has no GL_PATCHES draw");
  expect_refused(t, "--event 0", "call 0 is ");
  expect_refused(t, "--event 999999", "the trace has no call 999999");
  expect_refused(trace("gles", "--gles"), "", "OpenGL ES context");
  expect_refused(trace("label", "--label ../x"), "", "label '../x' names a path outside the output folder");
  const fs::path lying = tmp.path() / "lying.trace";
  const CliRun patch = run_command("python3 '" + kLyingBlob + "' '" + t.string() + "' '" + lying.string() + "'");
  ASSERT_EQ(patch.exit_code, 0) << patch.output;
  expect_refused(lying, "", "declares 400 bytes but the trace holds 384");
  // The instance offsets written by a compute shader: the trace holds the dispatch, not the bytes.
  expect_refused(trace("compute", "--compute"), "",
                 "input in_offset reads buffer 3, which was written by a compute shader (glDispatchCompute)");
}

// A region of the GPU's image altered where tessref draws a gem (draw 1): verify names the
// region's first pixel, the draw (and its capture call) and the patch, and the inspect commands;
// the named patch command opens the application's own source lines.
TEST_F(ApitraceImport, VerifyNamesWhereTheGpusImagePartsFromTessrefs) {
  const fs::path t = trace("frame");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  ASSERT_EQ(run_cli("import --quiet '" + t.string() + "' --out '" + out.string() + "'").exit_code, 0);
  const std::string scene = (out / "scene.json").string();
  const CliRun same = run_cli("verify '" + scene + "' --gpu '" + out.string() + "'");
  EXPECT_EQ(same.exit_code, 0) << same.output;
  EXPECT_THAT(same.output, HasSubstr("PASS: colour within 1/255 at all 65,536 pixels"));
  const fs::path altered = tmp.path() / "altered.png";
  const CliRun fill = run_command("oiiotool '" + (out / "gpu.png").string() + "' --fill:color=1,0,0 6x6+128+120 -o '" +
                                  altered.string() + "'");
  ASSERT_EQ(fill.exit_code, 0) << fill.output;
  const CliRun r = run_cli("verify '" + scene + "' --gpu '" + altered.string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("FAIL: 36 of 65,536 pixels differ by more than 1/255"));
  EXPECT_THAT(r.output, HasSubstr("within x 128..133, y 120..125"));
  EXPECT_THAT(r.output, HasSubstr("first differing pixel (128, 120)"));
  EXPECT_THAT(r.output, HasSubstr("draw 1 (capture call "));
  EXPECT_THAT(r.output, HasSubstr("glDrawElementsInstancedBaseVertex), patch 11,"));
  EXPECT_THAT(r.output, HasSubstr("--pixel 128,120 --trace"));
  EXPECT_THAT(r.output, HasSubstr("--draw 1 --patch 11 --trace"));
  // The command it names, run: the gem shaders' own lines, with the values they computed.
  const CliRun inspect = run_cli("inspect '" + scene + "' --draw 1 --patch 11 --trace");
  ASSERT_EQ(inspect.exit_code, 0) << inspect.output;
  EXPECT_THAT(inspect.output, HasSubstr("c_position = in_position * 0.45 + in_offset;"));
  EXPECT_THAT(inspect.output, HasSubstr("gl_TessLevelOuter[1] = u_level + 1.0;"));
  EXPECT_THAT(inspect.output, HasSubstr("gl_TessLevelOuter[1] = 6"));
}

// A campaign: a folder of captures imported into one folder per capture, then verified as a folder,
// whole and in shards; a capture that cannot be imported is named and fails the import.
TEST_F(ApitraceImport, AFolderOfCapturesIsImportedAndVerifiedInShards) {
  TempDir tmp;
  const fs::path captures = tmp.path() / "captures", imports = tmp.path() / "imports";
  fs::create_directories(captures);
  fs::copy_file(trace("frame"), captures / "a_frame.trace");
  fs::copy_file(trace("frame"), captures / "b_frame.trace");
  fs::copy_file(trace("untessellated", "--untessellated"), captures / "c_plane.trace");
  const CliRun import = run_cli("import '" + captures.string() + "' --out '" + imports.string() + "'");
  EXPECT_EQ(import.exit_code, 2) << import.output;
  EXPECT_THAT(import.output, HasSubstr("c_plane.trace not imported"));
  EXPECT_THAT(import.output, HasSubstr("2 of 3 captures imported"));
  EXPECT_TRUE(fs::exists(imports / "a_frame" / "scene.json"));
  EXPECT_FALSE(fs::exists(imports / "c_plane"));
  const CliRun all = run_cli("verify --gpu '" + imports.string() + "'");
  EXPECT_EQ(all.exit_code, 0) << all.output;
  EXPECT_THAT(all.output, HasSubstr("2 of 2 imported frames pass (shard 0/1 of 2)"));
  const CliRun second = run_cli("verify --gpu '" + imports.string() + "' --shard 1/2");
  EXPECT_EQ(second.exit_code, 0) << second.output;
  EXPECT_THAT(second.output, HasSubstr("b_frame/gpu.png"));
  EXPECT_THAT(second.output, ::testing::Not(HasSubstr("a_frame/gpu.png")));
}

// A last frame that does not begin with a clear starts from what the frame before left: the
// retrace's colour and depth before its first draw become the scene's framebuffer files.
TEST_F(ApitraceImport, AFrameWithoutAClearStartsFromTheEarlierFramesPixels) {
  const fs::path t = trace("two_frames", "--two-frames");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  const CliRun import = run_cli("import --quiet '" + t.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(import.exit_code, 0) << import.output;
  const nlohmann::json scene = read_json(out / "scene.json");
  EXPECT_EQ(scene.at("draws").size(), 2u) << "the plane was drawn in the earlier frame";
  EXPECT_EQ(scene.at("framebuffer").at("color").at(0).at("file"), "initial/color0.png");
  EXPECT_EQ(scene.at("framebuffer").at("depth").at("file"), "initial/depth.exr");
  ASSERT_EQ(run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "t.png").string() + "'").exit_code, 0);
  // Measured: identical (the plane's alpha of 0.75 in the colour read as stored, its depth occluding
  // the bicubic patch's middle).
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "t.png", app_image("two_frames")), 0);
}

// glDrawElementsIndirect reads its command from the tracked GL_DRAW_INDIRECT_BUFFER bytes (after 8
// unused ones), and glMultiDrawArrays of two commands becomes one draw with two calls.
TEST_F(ApitraceImport, IndirectAndMultiDrawsBecomeTheirCalls) {
  const fs::path t = trace("indirect", "--indirect");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  ASSERT_EQ(run_cli("import --quiet '" + t.string() + "' --out '" + out.string() + "'").exit_code, 0);
  const nlohmann::json scene = read_json(out / "scene.json");
  const nlohmann::json& gems = scene.at("draws").at(1);
  EXPECT_EQ(gems.at("elements").at("offset"), 10) << "firstIndex 5 of GL_UNSIGNED_SHORT";
  EXPECT_EQ(gems.at("count"), 24);
  EXPECT_EQ(gems.at("instancecount"), 3);
  EXPECT_EQ(gems.at("basevertex"), 3);
  EXPECT_EQ(scene.at("draws").at(2).at("calls").size(), 2u);
  ASSERT_EQ(run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "t.png").string() + "'").exit_code, 0);
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "t.png", app_image("indirect")), 0);
}

// A program with a geometry shader is carried (shaders/*.geom) and renders the application's image.
TEST_F(ApitraceImport, GeometryShadersAreCarried) {
  const fs::path t = trace("geometry", "--geometry");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  ASSERT_EQ(run_cli("import --quiet '" + t.string() + "' --out '" + out.string() + "'").exit_code, 0);
  const nlohmann::json scene = read_json(out / "scene.json");
  EXPECT_TRUE(scene.at("draws").at(2).at("shaders").contains("geometry")) << scene.at("draws").at(2).dump();
  ASSERT_EQ(run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "t.png").string() + "'").exit_code, 0);
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "t.png", app_image("geometry")), 0);
}

TEST_F(ApitraceImport, AnExistingFolderIsNotOverwritten) {
  const fs::path t = trace("frame");
  TempDir tmp;
  tmp.write("keep.txt", "mine");
  const CliRun r = run_cli("import '" + t.string() + "' --out '" + tmp.path().string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("already exists and is not an empty folder"));
  EXPECT_TRUE(fs::exists(tmp.path() / "keep.txt"));
}

// RenderDoc captures the application only through its in-app API (StartFrameCapture /
// EndFrameCapture), which replay_app calls when RenderDoc is loaded into it.
class RenderDocImport : public ApitraceImport {
 protected:
  static fs::path capture(const std::string& name, const std::string& flags = "") {
    const fs::path rdc = folder() / (name + "_capture.rdc");
    if (!fs::exists(rdc)) {
      const CliRun r = run_command("EGL_PLATFORM=surfaceless renderdoccmd capture -w -c '" + (folder() / name).string() +
                                   "' '" + kApp + "' " + flags + " '" + (folder() / (name + "_rdc.ppm")).string() + "'");
      EXPECT_EQ(r.exit_code, 0) << r.output;
      EXPECT_TRUE(fs::exists(rdc)) << r.output;
    }
    return rdc;
  }
  void SetUp() override {
    if (!have("renderdoccmd")) GTEST_SKIP() << "RenderDoc is not installed (Debian package renderdoc)";
    if (run_command("/usr/bin/python3 -c 'import renderdoc'").exit_code != 0)
      GTEST_SKIP() << "RenderDoc's python module is not installed (Debian package python3-renderdoc)";
  }
};

TEST_F(RenderDocImport, TheImportedFrameRendersTheApplicationsImage) {
  const fs::path rdc = capture("frame");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  const CliRun import = run_cli("import '" + rdc.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(import.exit_code, 0) << import.output;
  EXPECT_THAT(import.output, HasSubstr("(renderdoc), event "));
  EXPECT_THAT(import.output, HasSubstr("scene.json (3 draws), gpu.png"));
  EXPECT_TRUE(fs::exists(out / "gpu_depth.exr"));
  ASSERT_EQ(run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "t.png").string() + "'").exit_code, 0);
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "t.png", folder() / "frame_rdc.ppm"), 0);
  EXPECT_EQ(pixels_over_one_step(out / "gpu.png", folder() / "frame_rdc.ppm"), 0);
  const CliRun verify = run_cli("verify '" + (out / "scene.json").string() + "' --gpu '" + out.string() + "'");
  EXPECT_EQ(verify.exit_code, 0) << verify.output;
  // The evaluation shader's outputs RenderDoc recorded: the bicubic patch's 128 triangles in the
  // same order, each gl_Position within the bound (measured: 84 of 384 identical, the rest one
  // float step apart, where llvmpipe's arithmetic rounds differently from the executor's).
  EXPECT_THAT(verify.output, HasSubstr("evaluation outputs of draw 2 (gl_Position of each emitted triangle's corners): PASS: "));
  EXPECT_THAT(verify.output, HasSubstr(" of 384 identical"));
  // The depth the draws left: measured 56,949 of 65,536 pixels identical, at most 9 steps of 2^-24.
  EXPECT_THAT(verify.output, HasSubstr("depth (gpu_depth.exr): PASS: "));
  // A GPU that emitted one vertex fewer fails.
  fs::resize_file(out / "gpu_tes.bin", fs::file_size(out / "gpu_tes.bin") - 28);
  const CliRun short_tes = run_cli("verify --gpu '" + out.string() + "'");
  EXPECT_EQ(short_tes.exit_code, 1) << short_tes.output;
  EXPECT_THAT(short_tes.output, HasSubstr("FAIL: the GPU emitted 383 vertices, tessref 384"));
}

// What a trace cannot rebuild, a RenderDoc capture holds: the buffer a compute shader wrote.
TEST_F(RenderDocImport, ABufferTheGpuWroteIsCarried) {
  const fs::path rdc = capture("compute", "--compute");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  ASSERT_EQ(run_cli("import '" + rdc.string() + "' --out '" + out.string() + "'").exit_code, 0);
  ASSERT_EQ(run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "t.png").string() + "'").exit_code, 0);
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "t.png", folder() / "compute_rdc.ppm"), 0);
}

// RenderDoc gives a multi-draw's commands as child actions: each becomes a draw of the scene.
TEST_F(RenderDocImport, IndirectAndMultiDrawsAreCarried) {
  const fs::path rdc = capture("indirect", "--indirect");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  ASSERT_EQ(run_cli("import '" + rdc.string() + "' --out '" + out.string() + "'").exit_code, 0);
  EXPECT_EQ(read_json(out / "scene.json").at("draws").size(), 4u);
  ASSERT_EQ(run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "t.png").string() + "'").exit_code, 0);
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "t.png", folder() / "indirect_rdc.ppm"), 0);
}

TEST_F(RenderDocImport, GeometryShadersAreCarried) {
  const fs::path rdc = capture("geometry", "--geometry");
  TempDir tmp;
  const fs::path out = tmp.path() / "imported";
  ASSERT_EQ(run_cli("import '" + rdc.string() + "' --out '" + out.string() + "'").exit_code, 0);
  EXPECT_TRUE(read_json(out / "scene.json").at("draws").at(2).at("shaders").contains("geometry"));
  // RenderDoc's post-transform data is the geometry shader's then: no gpu_tes.bin to compare.
  EXPECT_FALSE(fs::exists(out / "gpu_tes.bin"));
  ASSERT_EQ(run_cli("render '" + (out / "scene.json").string() + "' -o '" + (tmp.path() / "t.png").string() + "'").exit_code, 0);
  EXPECT_EQ(pixels_over_one_step(tmp.path() / "t.png", folder() / "geometry_rdc.ppm"), 0);
}

TEST_F(RenderDocImport, BothImportersGiveTheSameScene) {
  if (!have("apitrace")) GTEST_SKIP() << "apitrace is not installed (Debian package apitrace)";
  TempDir tmp;
  const fs::path from_trace = tmp.path() / "apitrace", from_rdc = tmp.path() / "renderdoc";
  ASSERT_EQ(run_cli("import --quiet '" + trace("frame").string() + "' --out '" + from_trace.string() + "'").exit_code, 0);
  ASSERT_EQ(run_cli("import '" + capture("frame").string() + "' --out '" + from_rdc.string() + "'").exit_code, 0);
  const CliRun same = run_command("python3 '" + kSameScene + "' '" + (from_trace / "scene.json").string() + "' '" +
                                  (from_rdc / "scene.json").string() + "'");
  EXPECT_EQ(same.exit_code, 0) << same.output;
  EXPECT_THAT(same.output, HasSubstr("same scene"));
}

TEST_F(RenderDocImport, BadCapturesExitTwoAndLeaveNothing) {
  const fs::path rdc = capture("frame");
  TempDir tmp;
  {
    std::ifstream in(rdc, std::ios::binary);
    std::string bytes(3000, '\0');
    in.read(bytes.data(), bytes.size());
    tmp.write("truncated.rdc", bytes);
  }
  expect_refused(tmp.path() / "truncated.rdc", "", "RenderDoc cannot open");
  expect_refused(capture("untessellated", "--untessellated"), "", "has no GL_PATCHES draw");
  expect_refused(capture("label", "--label ../x"), "", "label '../x' names a path outside the output folder");
  // The event before the first draw's: a call of that draw's action, not a draw.
  const fs::path out = tmp.path() / "whole";
  ASSERT_EQ(run_cli("import '" + rdc.string() + "' --out '" + out.string() + "'").exit_code, 0);
  const int first_draw = read_json(out / "draws.json").at(0).at("event").get<int>();
  expect_refused(rdc, "--event " + std::to_string(first_draw - 1), "event " + std::to_string(first_draw - 1) + " is gl");
  expect_refused(rdc, "--event " + std::to_string(first_draw - 1), ", not a draw call");
  expect_refused(rdc, "--event 5000", "the capture has no event 5000");
}

}  // namespace
}  // namespace tessref::test
