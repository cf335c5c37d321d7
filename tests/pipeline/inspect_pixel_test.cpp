// tessref inspect --pixel and render --dump-fragments: on a scene whose answer is known by
// construction (three stacked squares, drawn back, front, back), the pixel query names each
// layer's patch in arrival order with the depth test's verdicts; on the default torus drawn with
// both faces, the winner's colour is the PNG's pixel, losing fragments are listed, and the EXR dump
// agrees with the query; nothing drawn and bad --pixel values are reported.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/image_output.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using nlohmann::json;
using test::CliRun;
using test::run_cli;
using test::TempDir;

json pixel_json(const TempDir& dir, const std::string& args) {
  const auto path = dir.path() / "pixel.json";
  const CliRun r = run_cli("inspect " + args + " --json " + path.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return json::parse(test::read_file(path));
}

glm::vec3 vec3(const json& a) { return {a[0].get<float>(), a[1].get<float>(), a[2].get<float>()}; }

// The channel names of an OpenEXR file, in file order, read from its header (the "channels"
// attribute: a list of NUL-terminated names, each followed by 16 bytes, ended by a NUL).
std::vector<std::string> exr_channels(const std::string& bytes) {
  std::size_t at = 8;  // magic and version
  const auto cstr = [&] {
    const std::string s(bytes.c_str() + at);
    at += s.size() + 1;
    return s;
  };
  while (at < bytes.size()) {
    const std::string name = cstr();
    if (name.empty()) break;
    const std::string type = cstr();
    std::int32_t size = 0;
    std::memcpy(&size, bytes.data() + at, 4);
    at += 4;
    if (name == "channels") {
      std::vector<std::string> out;
      for (std::string c; !(c = cstr()).empty();) {
        out.push_back(c);
        at += 16;
      }
      return out;
    }
    at += std::size_t(size);
  }
  return {};
}

// Three 2x2 squares facing the camera, as two triangles each (patches 2k, 2k + 1): z = -1 first,
// then z = 0.5 (the nearest), then z = -2. Triangle 2k covers the half below the diagonal y = x.
constexpr const char* kLayersObj = R"(v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 0.5
v 1 -1 0.5
v 1 1 0.5
v -1 1 0.5
v -1 -1 -2
v 1 -1 -2
v 1 1 -2
v -1 1 -2
f 1 2 3
f 1 3 4
f 5 6 7
f 5 7 8
f 9 10 11
f 9 11 12
)";
constexpr const char* kLayersScene = R"({
  "mesh": { "type": "file", "path": "layers.obj" },
  "transform": { "translate": [0, 0, 0], "rotate_deg": [0, 0, 0], "scale": 1.0 },
  "camera": { "eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40, "near": 0.5, "far": 50 },
  "lights": [ { "position": [1, 2, 6], "intensity": [1, 1, 1] } ],
  "image": { "width": 64, "height": 64 },
  "cull_back_faces": false
})";

// The PNG's pixel (x, y from the top row) against a colour as the 8-bit writer stores it.
void expect_png_pixel(const Rgb8Image& png, int x, int y, const json& color) {
  for (int c = 0; c < 3; ++c) {
    const float v = color[c].get<float>();
    const int expected = int(std::lround(std::clamp(std::isnan(v) ? 0.0f : v, 0.0f, 1.0f) * 255.0f));
    EXPECT_EQ(int(png.pixels[(std::size_t(y) * png.width + x) * 3 + c]), expected) << "channel " << c;
  }
}

TEST(InspectPixel, NamesEachLayerInArrivalOrderWithTheDepthVerdicts) {
  TempDir dir;
  dir.write("layers.obj", kLayersObj);
  const std::string scene = dir.write("layers.json", kLayersScene).string();
  // Pixel (40, 36): right of and below the centre, so below every square's diagonal.
  const json j = pixel_json(dir, scene + " --pixel 40,36");
  EXPECT_EQ(j["pixel"]["window_y"], 64 - 1 - 36);
  const json& f = j["fragments"];
  ASSERT_EQ(f.size(), 3u) << j.dump(1);
  EXPECT_EQ(f[0]["patch"], 0);  // drawn first: passes the cleared depth, then hidden
  EXPECT_EQ(f[1]["patch"], 2);  // the nearest: the winner
  EXPECT_EQ(f[2]["patch"], 4);  // behind the winner: fails
  EXPECT_TRUE(f[0]["depth_test"]["passed"]);
  EXPECT_TRUE(f[0]["depth_test"]["stored_by"].is_null());
  EXPECT_EQ(f[0]["hidden_by"], 1);
  EXPECT_TRUE(f[1]["depth_test"]["passed"]);
  EXPECT_EQ(f[1]["depth_test"]["stored_by"], 0);
  EXPECT_FALSE(f[2]["depth_test"]["passed"]);
  EXPECT_EQ(f[2]["depth_test"]["stored_by"], 1);
  EXPECT_EQ(j["winner"], 1);
  EXPECT_NEAR(vec3(f[0]["world_position"]).z, -1.0f, 1e-5);
  EXPECT_NEAR(vec3(f[1]["world_position"]).z, 0.5f, 1e-5);
  EXPECT_NEAR(vec3(f[2]["world_position"]).z, -2.0f, 1e-5);

  // gl_TessCoord: on a flat patch the evaluation shader at that coordinate lands on the fragment.
  for (const json& frag : f) {
    const glm::vec3 tc = vec3(frag["gl_TessCoord"]);
    EXPECT_NEAR(tc.x + tc.y + tc.z, 1.0f, 1e-5);
    const json p = json::parse(test::read_file([&] {
      const auto path = dir.path() / "patch.json";
      char coord[96];
      std::snprintf(coord, sizeof coord, "%.9g,%.9g,%.9g", tc.x, tc.y, tc.z);
      EXPECT_EQ(run_cli("inspect " + scene + " --patch " + frag["patch"].dump() + " --coord " + coord +
                        " --json " + path.string()).exit_code, 0);
      return path;
    }()));
    const glm::vec3 at = vec3(p["evaluation_stage"]["points"][0]["world_position"]);
    const glm::vec3 got = vec3(frag["world_position"]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(at[c], got[c], 1e-5);
  }

  // The winner's colour is the rendered pixel's.
  const auto png = dir.path() / "layers.png";
  ASSERT_EQ(run_cli("render " + scene + " -o " + png.string()).exit_code, 0);
  expect_png_pixel(read_rgb8_image(png), 40, 36, f[1]["color"]);
}

TEST(InspectPixel, NothingDrawnAndTextOutput) {
  TempDir dir;
  dir.write("layers.obj", kLayersObj);
  const std::string scene = dir.write("layers.json", kLayersScene).string();
  const json j = pixel_json(dir, scene + " --pixel 0,0");
  EXPECT_TRUE(j["fragments"].empty());
  EXPECT_TRUE(j["winner"].is_null());
  const CliRun empty = run_cli("inspect " + scene + " --pixel 0,0");
  EXPECT_EQ(empty.exit_code, 0) << empty.output;
  EXPECT_THAT(empty.output, HasSubstr("nothing was drawn at this pixel"));
  const CliRun text = run_cli("inspect " + scene + " --pixel 40,36");
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("Y down from the top row"));
  EXPECT_THAT(text.output, HasSubstr("3 fragments at this pixel"));
  EXPECT_THAT(text.output, HasSubstr("fragment 2: patch 4"));
  EXPECT_THAT(text.output, HasSubstr("failed: "));
  EXPECT_THAT(text.output, HasSubstr("then hidden by fragment 1"));
}

TEST(InspectPixel, DefaultTorusBothFacesAgreesWithPngAndExrDump) {
  TempDir dir;
  const std::string sets = " --set cull_back_faces=false --set image.width=256 --set image.height=256";
  const auto png = dir.path() / "torus.png", exr = dir.path() / "frags.exr";
  const CliRun r = run_cli("render -o " + png.string() + " --dump-fragments " + exr.string() + sets);
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const std::vector<std::string> names = exr_channels(test::read_file(exr));
  EXPECT_THAT(names, ::testing::UnorderedElementsAre("P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "patch_id", "triangle",
                                                      "tess_coord.u", "tess_coord.v", "tess_coord.w", "depth"));
  const FloatImage dump = read_float_image(exr);
  ASSERT_EQ(dump.channels, 12);
  const std::vector<std::string> read_order = read_channel_names(exr);  // not the file's order
  EXPECT_THAT(read_order, ::testing::UnorderedElementsAreArray(names));
  const auto channel = [&](const std::string& name) {
    return int(std::find(read_order.begin(), read_order.end(), name) - read_order.begin());
  };
  const auto at = [&](int x, int y, const std::string& name) {
    return dump.pixels[(std::size_t(y) * dump.width + x) * dump.channels + std::size_t(channel(name))];
  };
  EXPECT_EQ(at(0, 0, "patch_id"), -1.0f);  // the corner: background
  EXPECT_TRUE(std::isnan(at(0, 0, "depth")));

  const Rgb8Image image = read_rgb8_image(png);
  int checked = 0;
  const std::pair<int, int> pixels[] = {{128, 100}, {70, 128}, {180, 150}, {128, 170}};
  for (const auto& [x, y] : pixels) {
    if (at(x, y, "patch_id") < 0) continue;
    const json j = pixel_json(dir, "--pixel " + std::to_string(x) + "," + std::to_string(y) + sets);
    const json& f = j["fragments"];
    ASSERT_GE(f.size(), 2u) << "a ray into a closed surface crosses it at least twice: " << x << "," << y;
    ASSERT_FALSE(j["winner"].is_null());
    const json& w = f[j["winner"].get<std::size_t>()];
    EXPECT_EQ(w["patch"].get<float>(), at(x, y, "patch_id"));
    EXPECT_EQ(w["triangle"].get<float>(), at(x, y, "triangle"));
    EXPECT_EQ(w["gl_TessCoord"][0].get<float>(), at(x, y, "tess_coord.u"));
    EXPECT_EQ(w["gl_FragCoord"][2].get<float>(), at(x, y, "depth"));
    EXPECT_EQ(w["world_position"][0].get<float>(), at(x, y, "P.X"));
    expect_png_pixel(image, x, y, w["color"]);
    bool back = false, lost = false;
    for (const json& frag : f) {
      back |= !frag["front_facing"].get<bool>();
      lost |= !frag["depth_test"]["passed"].get<bool>() || !frag["hidden_by"].is_null();
    }
    EXPECT_TRUE(back && lost) << j.dump(1);
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

TEST(InspectPixel, BadRequestsNameTheOptionAndTheImageSize) {
  const std::pair<std::string, std::string> cases[] = {
      {"--pixel 1024,0", "--pixel: (1024, 0) is off the 1024x1024 image (X 0..1023, Y 0..1023, from the top row)"},
      {"--pixel 5,-1", "--pixel: (5, -1) is off the 1024x1024 image"},
      {"--pixel 5", "--pixel: expected X,Y (two integers: X from the left, Y down from the top row) on the 1024x1024 image"},
      {"--pixel 1,x", "--pixel: expected X,Y"},
      {"--pixel 1,2 --patch 3", "--pixel: give it alone"},
      {"--pixel 1,2 --set tessellation.enabled=false", "--pixel: the scene does not tessellate"},
  };
  for (const auto& [args, message] : cases) {
    const CliRun r = run_cli("inspect " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr(message)) << args;
  }
  TempDir dir;
  const CliRun r = run_cli("render -o " + (dir.path() / "x.png").string() + " --dump-fragments " +
                           (dir.path() / "f.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--dump-fragments: "));
}

}  // namespace
}  // namespace tessref
