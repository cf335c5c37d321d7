// Scene files: the default scene, every error case, --set overrides.
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using test::TempDir;

const std::string kSource = TESSREF_SOURCE_DIR;

// The InputError message parse_scene gives, or "" if it parses.
std::string scene_error(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse_scene(text, "scenes/x.json", ".", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, DefaultSceneIsFigure14) {
  const Scene s = load_scene("");
  EXPECT_EQ(s.source, "<default scene>");
  EXPECT_FLOAT_EQ(s.material.ka, 0.4f);
  EXPECT_FLOAT_EQ(s.material.kd, 0.5f);
  EXPECT_FLOAT_EQ(s.material.ks, 0.3f);
  EXPECT_FLOAT_EQ(s.material.shininess, 150.0f);
  EXPECT_EQ(s.material.color, glm::vec3(0.988f, 0.0f, 0.427f));
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].position, glm::vec3(-2.0f, 5.0f, -10.0f));
  EXPECT_EQ(s.lights[0].intensity, glm::vec3(1.0f));
  EXPECT_EQ(s.camera.eye, glm::vec3(2.0f, 5.0f, -10.0f));
  EXPECT_EQ(s.camera.target, glm::vec3(0.0f));
  EXPECT_EQ(s.shading, Shading::Phong);
  EXPECT_EQ(s.tessellation.scheme, SurfaceScheme::PN);
  EXPECT_EQ(s.tessellation.spacing, TessSpacing::FractionalOdd);
  EXPECT_EQ(s.tessellation.levels.inner[0], 12.0f);
  EXPECT_EQ(s.tessellation.levels.outer[2], 12.0f);
}

TEST(Scene, EmbeddedDefaultEqualsTheRepositoryFile) {
  EXPECT_EQ(default_scene_json(), test::read_file(kSource + "/scenes/default.json"));
}

TEST(Scene, EveryCommittedSceneLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(load_scene(entry.path()));
    ++count;
  }
  EXPECT_GE(count, 1);
}

TEST(Scene, FileValuesMergeOverTheDefault) {
  const Scene s = parse_scene(R"({"camera": {"fov_y_deg": 30}, "lights": []})", "x.json", ".");
  EXPECT_FLOAT_EQ(s.camera.fov_y_deg, 30.0f);
  EXPECT_EQ(s.camera.eye, glm::vec3(2.0f, 5.0f, -10.0f));  // from the default scene
  EXPECT_TRUE(s.lights.empty());                          // arrays replace
}

TEST(Scene, MissingFile) {
  try {
    load_scene("/nonexistent/scene.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/scene.json: no such scene file");
  }
}

TEST(Scene, SyntaxErrorNamesFileLineAndColumn) {
  TempDir dir;
  auto path = dir.write("bad.json", "{\n  \"camera\": {\n    \"eye\": [1, 2, 3],\n  }\n}\n");
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path.string() + ": line 4, column 3: JSON syntax error"));
  }
}

TEST(Scene, EmptyFileIsASyntaxError) {
  EXPECT_THAT(scene_error(""), HasSubstr("scenes/x.json: line 1, column 1: JSON syntax error"));
}

TEST(Scene, NumberOverflowInFile) {
  EXPECT_EQ(scene_error(R"({"camera": {"fov_y_deg": 1e999}})"),
            "scenes/x.json: line 1, column 26: invalid JSON: number overflow parsing '1e999'");
  // The number, not the same text in a string or a longer number before it.
  EXPECT_EQ(scene_error("{\"description\": \"1e999\",\n \"lights\": [{\"position\": [11e999, 0, 0]}],\n"
                        " \"camera\": {\"fov_y_deg\": 1e999}}"),
            "scenes/x.json: line 2, column 27: invalid JSON: number overflow parsing '11e999'");
  EXPECT_EQ(scene_error("{\"description\": \"1e999\", // 1e999\n \"camera\": {\"fov_y_deg\": -1e999}}"),
            "scenes/x.json: line 2, column 26: invalid JSON: number overflow parsing '-1e999'");
}

// nlohmann::json copies values recursively: a deep file overflowed the stack (SIGSEGV). 256
// levels are read (here the type check names the key), the 257th is refused where it opens.
TEST(Scene, NestingIsLimitedTo256Levels) {
  auto nested = [](int levels) { return std::string(std::size_t(levels), '[') + std::string(std::size_t(levels), ']'); };
  EXPECT_THAT(scene_error("{\"camera\": {\"eye\": " + nested(254) + "}}"),
              HasSubstr("scenes/x.json: camera.eye: expected an array of 3 numbers"));
  EXPECT_EQ(scene_error("{\"camera\": {\"eye\": " + nested(255) + "}}"),
            "scenes/x.json: line 1, column 274: arrays and objects nested deeper than 256 levels (tessref's limit "
            "for JSON input)");
  // Brackets inside strings and comments do not count.
  EXPECT_THAT(scene_error("{\"description\": \"" + nested(300) + "\", /* " + nested(300) + " */ \"colour\": 1}"),
              HasSubstr("colour: unknown key"));
  EXPECT_THAT(scene_error("{}", {"camera.eye=" + nested(257)}),
              HasSubstr("--set camera.eye: line 1, column 257: arrays and objects nested deeper than 256 levels"));
  EXPECT_THAT(scene_error("{}", {"camera.eye=" + nested(256)}), HasSubstr("camera.eye: expected an array of 3 numbers"));
}

TEST(Scene, UnknownKeys) {
  EXPECT_EQ(scene_error(R"({"camera": {"eyes": [1, 2, 3]}})"),
            "scenes/x.json: camera.eyes: unknown key (expected one of: eye, target, up, "
            "fov_y_deg, near, far, fit)");
  EXPECT_THAT(scene_error(R"({"colour": 1})"), HasSubstr("scenes/x.json: colour: unknown key"));
  EXPECT_THAT(scene_error(R"({"lights": [{"position": [0, 0, 0], "power": 2}]})"),
              HasSubstr("scenes/x.json: lights.0.power: unknown key"));
  EXPECT_THAT(scene_error(R"({"tessellation": {"adaptive": {"pixels": 2}}})"),
              HasSubstr("scenes/x.json: tessellation.adaptive.pixels: unknown key"));
}

TEST(Scene, WrongTypes) {
  EXPECT_EQ(scene_error(R"({"camera": {"eye": "abc"}})"),
            "scenes/x.json: camera.eye: expected an array of 3 numbers, got a string (\"abc\")");
  EXPECT_EQ(scene_error(R"({"camera": {"eye": [1, 2]}})"),
            "scenes/x.json: camera.eye: expected an array of 3 numbers, got an array of 2");
  EXPECT_EQ(scene_error(R"({"camera": {"eye": [1, "2", 3]}})"),
            "scenes/x.json: camera.eye: expected an array of 3 numbers, got a string (\"2\") at "
            "index 1");
  EXPECT_EQ(scene_error(R"({"cull_back_faces": 1})"),
            "scenes/x.json: cull_back_faces: expected true or false, got a number (1)");
  EXPECT_EQ(scene_error(R"({"camera": 5})"),
            "scenes/x.json: camera: expected an object, got a number (5)");
  EXPECT_EQ(scene_error(R"([1, 2])"), "scenes/x.json: expected an object, got an array of 2");
  EXPECT_EQ(scene_error(R"({"image": {"width": 10.5}})"),
            "scenes/x.json: image.width: expected an integer in [1, 16384], got a number (10.5)");
  EXPECT_EQ(scene_error(R"({"mesh": {"type": "teapot"}})"),
            "scenes/x.json: mesh.type: expected one of icosphere, torus, cube, file, seed004_torus, rounded_cube, vase, got \"teapot\"");
  EXPECT_EQ(scene_error(R"({"tessellation": {"spacing": "odd"}})"),
            "scenes/x.json: tessellation.spacing: expected one of equal, fractional_odd, "
            "fractional_even, got \"odd\"");
}

TEST(Scene, NonFiniteValuesFromOverrides) {
  EXPECT_EQ(scene_error("{}", {"camera.eye=nan,5,-10"}),
            "scenes/x.json: camera.eye: expected finite numbers, got nan at index 0 (from --set "
            "camera.eye)");
  EXPECT_EQ(scene_error("{}", {"camera.eye=2,1e999,-10"}),
            "scenes/x.json: camera.eye: expected finite numbers, got inf at index 1 (from --set "
            "camera.eye)");
  EXPECT_EQ(scene_error("{}", {"lights.0.intensity=1,-inf,1"}),
            "scenes/x.json: lights.0.intensity: expected finite numbers, got -inf at index 1 "
            "(from --set lights.0.intensity)");
  EXPECT_EQ(scene_error("{}", {"material.ka=nan"}),
            "scenes/x.json: material.ka: expected a finite number, got nan (from --set material.ka)");
  EXPECT_EQ(scene_error("{}", {"camera.fov_y_deg=1e999"}),
            "scenes/x.json: camera.fov_y_deg: expected a finite number, got inf (from --set "
            "camera.fov_y_deg)");
  // Finite in double, not in float: said as such, with the key (issue 11, defect 7).
  EXPECT_EQ(scene_error("{}", {"transform.translate=1e300,0,0"}),
            "scenes/x.json: transform.translate: 1e300 overflows single precision (the largest "
            "float is 3.4028235e38) at index 0 (from --set transform.translate)");
  EXPECT_EQ(scene_error(R"({"material": {"ka": 1e39}})"),
            "scenes/x.json: material.ka: 1e39 overflows single precision (the largest float is "
            "3.4028235e38)");
}

// Issue 11, defect 7: values that fit a float but overflow what is computed from them are blamed
// on themselves, as an overflow.
TEST(Scene, FloatOverflowNamesTheKey) {
  EXPECT_EQ(scene_error("{}", {"camera.eye=1e30,1e30,1e30"}),
            "scenes/x.json: camera.eye: the distance from camera.eye to camera.target overflows "
            "single precision when squared (keep it below 1e19) (from --set camera.eye)");
  EXPECT_THAT(scene_error("{}", {"camera.target=0,3e19,0"}),
              HasSubstr("camera.eye: the distance from camera.eye to camera.target overflows "
                        "single precision when squared (keep it below 1e19) (from --set camera.target)"));
  EXPECT_THAT(scene_error("{}", {"camera.up=0,1e20,0"}),
              HasSubstr("camera.up: its length overflows single precision"));
  // Large but representable: fine.
  EXPECT_EQ(scene_error("{}", {"camera.eye=1e18,1e18,1e18", "camera.far=1e19"}), "");
  EXPECT_EQ(scene_error("{}", {"mesh.icosphere.radius=1e38"}),
            "scenes/x.json: mesh.icosphere.radius: 1e38 is too large: the mesh's triangle areas "
            "(about its square) would overflow single precision; use at most 1e18 (from --set "
            "mesh.icosphere.radius)");
  EXPECT_THAT(scene_error("{}", {"mesh.cube.size=1e20"}), HasSubstr("mesh.cube.size: 1e20 is too large"));
}

// Issue 11, defect 10: messages echo values as typed and name the --set behind a rule that
// spans two keys; duplicate keys, hexadecimal numbers and --set objects behave as in files.
TEST(Scene, MessageDetails) {
  EXPECT_EQ(scene_error("{}", {"material.ka=-0.1"}),
            "scenes/x.json: material.ka: expected a number in [0, inf), got -0.1 (from --set "
            "material.ka)");
  EXPECT_EQ(scene_error("{}", {"camera.near=60"}),
            "scenes/x.json: camera.far: must be greater than camera.near (60), got 50 (from --set "
            "camera.near)");
  EXPECT_EQ(scene_error("{}", {"camera.near=60", "camera.far=0.5"}),
            "scenes/x.json: camera.far: must be greater than camera.near (60), got 0.5 (from --set "
            "camera.near, --set camera.far)");
  EXPECT_EQ(scene_error("{}", {"mesh.torus.major_radius=0.2"}),
            "scenes/x.json: mesh.torus.minor_radius: must be less than mesh.torus.major_radius "
            "(0.2), got 0.45 (from --set mesh.torus.major_radius)");
  EXPECT_EQ(scene_error(R"({"image": {"width": 64, "width": 32}})"),
            "scenes/x.json: image.width: the key is given twice in one object (JSON keeps only the "
            "last; remove one)");
  EXPECT_THAT(scene_error(R"({"lights": [{"position": [1, 2, 3], "position": [0, 0, 0]}]})"),
              HasSubstr("scenes/x.json: lights[].position: the key is given twice"));
  EXPECT_EQ(scene_error("{}", {"image.width=0x40"}),
            "scenes/x.json: image.width: expected an integer in [1, 16384], got a string "
            "(\"0x40\") (from --set image.width)");
  // An object given with --set merges key by key, as a scene file does over the default scene.
  const Scene s = parse_scene("{}", "x", ".", {R"(image={"width": 64})"});
  EXPECT_EQ(s.width, 64);
  EXPECT_EQ(s.height, 1024);
  // A null member removes a key, as in a JSON merge patch.
  const Scene u = parse_scene(R"({"shaders": {"uniforms": {"u_a": 1, "u_b": 2}}})", "x", ".",
                              {R"(shaders.uniforms={"u_a": null, "u_c": 3})"});
  ASSERT_EQ(u.shaders.uniforms.size(), 2u);
  EXPECT_EQ(u.shaders.uniforms[0].name, "u_b");
  EXPECT_EQ(u.shaders.uniforms[1].name, "u_c");
}

TEST(Scene, ImageSize) {
  EXPECT_EQ(scene_error(R"({"image": {"width": 0}})"),
            "scenes/x.json: image.width: expected an integer in [1, 16384], got a number (0)");
  EXPECT_THAT(scene_error(R"({"image": {"height": -4}})"), HasSubstr("image.height: expected an integer"));
  EXPECT_THAT(scene_error(R"({"image": {"width": 100000}})"), HasSubstr("image.width: expected an integer"));
  EXPECT_THAT(scene_error(R"({"image": {"width": 16384, "height": 16384}})"),
              HasSubstr("image.height: 16384 x 16384 pixels is more than the limit"));
  EXPECT_EQ(scene_error(R"({"image": {"width": 1, "height": 1}})"), "");
}

TEST(Scene, CameraAndMaterialChecks) {
  EXPECT_THAT(scene_error(R"({"camera": {"target": [2, 5, -10]}})"),
              HasSubstr("camera.target: must differ from camera.eye"));
  EXPECT_THAT(scene_error(R"({"camera": {"up": [2, 5, -10]}})"),
              HasSubstr("camera.up: must not be zero or parallel"));
  EXPECT_THAT(scene_error(R"({"camera": {"near": 0}})"), HasSubstr("camera.near: expected a number in (0"));
  EXPECT_THAT(scene_error(R"({"camera": {"near": 2, "far": 1}})"), HasSubstr("camera.far"));
  EXPECT_THAT(scene_error(R"({"camera": {"fov_y_deg": 180}})"), HasSubstr("camera.fov_y_deg"));
  EXPECT_THAT(scene_error(R"({"material": {"shininess": 0}})"), HasSubstr("material.shininess"));
  EXPECT_THAT(scene_error(R"({"material": {"kd": -1}})"), HasSubstr("material.kd"));
  EXPECT_THAT(scene_error(R"({"transform": {"scale": [1, 0, 1]}})"),
              HasSubstr("transform.scale: must not be zero"));
  EXPECT_THAT(scene_error(R"({"lights": [{"intensity": [1, 1, 1]}]})"),
              HasSubstr("lights.0.position: missing"));
  EXPECT_THAT(scene_error(R"({"lights": [{"position": [0, 0, 0]}, {"position": [0, 0, 0]},
      {"position": [0, 0, 0]}, {"position": [0, 0, 0]}, {"position": [0, 0, 0]},
      {"position": [0, 0, 0]}, {"position": [0, 0, 0]}, {"position": [0, 0, 0]},
      {"position": [0, 0, 0]}]})"),
              HasSubstr("lights: expected an array of at most 8 lights"));
  EXPECT_THAT(scene_error(R"({"mesh": {"type": "file"}})"),
              HasSubstr("mesh.path: required when mesh.type is \"file\""));
}

TEST(Scene, TessellationLevels) {
  Scene s = parse_scene(R"({"tessellation": {"inner": [3, 4], "outer": [1, 2, 3]}})", "x", ".");
  EXPECT_EQ(s.tessellation.levels.inner[0], 3.0f);
  EXPECT_EQ(s.tessellation.levels.inner[1], 4.0f);
  EXPECT_EQ(s.tessellation.levels.outer[0], 1.0f);
  EXPECT_EQ(s.tessellation.levels.outer[2], 3.0f);
  // Where the spec defines the behaviour: NaN and non-positive outer levels (discard), negative
  // and infinite inner levels (clamp).
  s = parse_scene(R"({"tessellation": {"inner": -2, "outer": ["nan", 0, "-inf"]}})", "x", ".");
  EXPECT_TRUE(std::isnan(s.tessellation.levels.outer[0]));
  EXPECT_EQ(s.tessellation.levels.outer[1], 0.0f);
  EXPECT_EQ(s.tessellation.levels.outer[2], -INFINITY);
  EXPECT_EQ(s.tessellation.levels.inner[0], -2.0f);
  s = parse_scene("{}", "x", ".", {"tessellation.outer=nan", "tessellation.inner=inf"});
  EXPECT_TRUE(std::isnan(s.tessellation.levels.outer[3]));
  EXPECT_EQ(s.tessellation.levels.inner[1], INFINITY);
  // NaN inner levels: one rule everywhere (scenes, tessref tpg, control shaders): they clamp to
  // the lower bound, as llvmpipe does (GL leaves them undefined; docs/tpg.md).
  s = parse_scene("{}", "x", ".", {"tessellation.inner=nan"});
  EXPECT_TRUE(std::isnan(s.tessellation.levels.inner[0]));
  EXPECT_THAT(scene_error(R"({"tessellation": {"outer": [1, 2]}})"),
              HasSubstr("tessellation.outer: expected a level or an array of 3 to 4 levels"));
  EXPECT_THAT(scene_error(R"({"tessellation": {"outer": "big"}})"),
              HasSubstr("tessellation.outer: expected a tessellation level"));
}

TEST(Scene, OverrideValues) {
  using nlohmann::json;
  EXPECT_EQ(parse_override_value("2,5,-10"), json::array({2.0, 5.0, -10.0}));
  EXPECT_EQ(parse_override_value("[2, 5, -10]"), json::array({2, 5, -10}));
  EXPECT_EQ(parse_override_value("8"), json(8));
  EXPECT_EQ(parse_override_value("true"), json(true));
  EXPECT_EQ(parse_override_value("torus"), json("torus"));
  EXPECT_EQ(parse_override_value("1,b,3"), json("1,b,3"));
  EXPECT_EQ(parse_override_value(""), json(""));
  EXPECT_TRUE(std::isnan(parse_override_value("nan").get<double>()));
  EXPECT_EQ(parse_override_value("1e999").get<double>(), INFINITY);
  EXPECT_EQ(parse_override_value("+2,-3"), json::array({2.0, -3.0}));
  EXPECT_EQ(parse_override_value("0x40"), json("0x40"));  // JSON has no hexadecimal either
  EXPECT_EQ(parse_override_value(" 1.5 "), json(1.5));
}

TEST(Scene, Overrides) {
  const Scene s = parse_scene("{}", "x", ".",
                              {"camera.eye=1,2,3", "tessellation.inner=8", "mesh.type=icosphere",
                               "lights.0.intensity=[0.5, 0.5, 0.5]", "lights.1.position=0,9,0",
                               "shading=normals", "image={\"width\": 64, \"height\": 32}"});
  EXPECT_EQ(s.camera.eye, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(s.tessellation.levels.inner[0], 8.0f);
  EXPECT_EQ(s.mesh.type, MeshType::Icosphere);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].intensity, glm::vec3(0.5f));
  EXPECT_EQ(s.lights[1].position, glm::vec3(0.0f, 9.0f, 0.0f));
  EXPECT_EQ(s.lights[1].intensity, glm::vec3(1.0f));
  EXPECT_EQ(s.shading, Shading::Normals);
  EXPECT_EQ(s.width, 64);
  EXPECT_EQ(s.height, 32);
}

TEST(Scene, OverrideErrors) {
  EXPECT_EQ(scene_error("{}", {"camera.eye"}), "--set camera.eye: expected KEY=VALUE (e.g. camera.eye=2,5,-10)");
  EXPECT_THAT(scene_error("{}", {"camera..eye=1"}), HasSubstr("empty key segment"));
  EXPECT_EQ(scene_error("{}", {"camera.eyes=1,2,3"}),
            "scenes/x.json: camera.eyes: unknown key (expected one of: eye, target, up, fov_y_deg, "
            "near, far, fit) (from --set camera.eyes)");
  EXPECT_EQ(scene_error("{}", {"camera.fov_y_deg.x=1"}),
            "--set camera.fov_y_deg.x: camera.fov_y_deg is a number (18), not an object");
  EXPECT_EQ(scene_error("{}", {"lights.5.position=1,2,3"}),
            "--set lights.5.position: lights has 1 elements: index 5 is past its end");
  EXPECT_EQ(scene_error("{}", {"camera.eye=up"}),
            "scenes/x.json: camera.eye: expected an array of 3 numbers, got a string (\"up\") "
            "(from --set camera.eye)");
}

TEST(Scene, ShaderSettingChecks) {
  EXPECT_THAT(scene_error("{}", {"shaders.patch_vertices=0"}), HasSubstr("shaders.patch_vertices: expected an integer in [1, 32], got a number (0)"));
  EXPECT_THAT(scene_error("{}", {"shaders.patch_vertices=33"}), HasSubstr("shaders.patch_vertices: expected an integer in [1, 32]"));
  EXPECT_THAT(scene_error("{}", {"shaders.batch_lanes=257"}), HasSubstr("shaders.batch_lanes: expected an integer in [1, 256]"));
  EXPECT_THAT(scene_error("{}", {"shaders.max_instructions=0"}), HasSubstr("shaders.max_instructions: expected an integer in [1, "));
  EXPECT_THAT(scene_error("{}", {"shaders.program=custom", "shaders.fragment=twin:phong.frag"}),
              HasSubstr("shaders.vertex: required when shaders.program is \"custom\""));
  EXPECT_THAT(scene_error("{}", {"shaders.program=mine"}),
              HasSubstr("shaders.program: expected one of builtin, twins, custom, got \"mine\""));
  EXPECT_THAT(scene_error("{}", {"shaders.attributes.in_position=uv"}),
              HasSubstr("shaders.attributes.in_position: expected \"position\" or \"normal\", got a string (\"uv\")"));
  EXPECT_THAT(scene_error(R"({"shaders": {"textures": {"u_tex": {"path": "a.png", "filter": "cubic"}}}})"),
              HasSubstr("shaders.textures.u_tex.filter: expected one of nearest, linear, got \"cubic\""));
  EXPECT_THAT(scene_error(R"({"shaders": {"textures": {"u_tex": {"path": "a.png", "wrap": "clamp"}}}})"),
              HasSubstr("shaders.textures.u_tex.wrap: expected one of repeat, mirrored_repeat, clamp_to_edge, clamp_to_border, mirror_clamp_to_edge"));
  EXPECT_THAT(scene_error(R"({"shaders": {"uniforms": {"u_k": "high"}}})"),
              HasSubstr("shaders.uniforms.u_k: expected numbers or booleans"));
}

// The key list that --help prints comes from the loader's own reads: every key of the default
// scene is in it, each with what it allows, and README's table names every one.
TEST(Scene, KeyListCoversTheDefaultSceneAndTheReadme) {
  const std::vector<SchemaKey> keys = scene_keys();
  ASSERT_GT(keys.size(), 40u);
  const std::string readme = test::read_file(kSource + "/README.md");
  for (const SchemaKey& k : keys) {
    SCOPED_TRACE(k.path);
    EXPECT_FALSE(k.allowed.empty());
    const std::string last = k.path.substr(k.path.rfind('.') + 1);
    const std::string short_path = k.path.find("[]") == std::string::npos ? k.path : "lights";
    EXPECT_TRUE(readme.find("`" + short_path + "`") != std::string::npos ||
                readme.find("`" + last + "`") != std::string::npos)
        << "README.md's scene key table does not name " << k.path;
    // A required key has a default, except inside buffers and draws: the default scene has
    // neither, and their own keys (a draw's mode and count, a buffer's type) must be given.
    if (!k.optional && k.path.rfind("buffers", 0) != 0 && k.path.rfind("draws", 0) != 0) {
      EXPECT_FALSE(scene_key_default(k.path).empty());
    }
  }
  // Every leaf of the default scene is a key the loader reads.
  std::function<void(const nlohmann::json&, const std::string&)> leaves = [&](const nlohmann::json& j,
                                                                              const std::string& path) {
    if (j.is_object() && !j.empty() && path != "shaders.attributes" && path != "shaders.uniforms") {
      for (const auto& [key, value] : j.items()) leaves(value, path.empty() ? key : path + "." + key);
      return;
    }
    std::string p = path;
    if (p.rfind("lights", 0) == 0) return;  // an array: lights[].position, lights[].intensity
    EXPECT_TRUE(std::any_of(keys.begin(), keys.end(), [&](const SchemaKey& k) { return k.path == p; })) << p;
  };
  leaves(nlohmann::json::parse(default_scene_json()), "");
}

TEST(Scene, MeshPathsResolve) {
  TempDir dir;
  auto scene = dir.write("s.json", R"({"mesh": {"type": "file", "path": "models/m.obj"}})");
  EXPECT_EQ(load_scene(scene).mesh.path, dir.path() / "models/m.obj");
  // From --set: against the current directory.
  EXPECT_EQ(load_scene(scene, {"mesh.path=other.obj"}).mesh.path,
            std::filesystem::current_path() / "other.obj");
  EXPECT_EQ(load_scene(scene, {"mesh.path=/abs/m.obj"}).mesh.path, "/abs/m.obj");
}

}  // namespace
}  // namespace tessref
