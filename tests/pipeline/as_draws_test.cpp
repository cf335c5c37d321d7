// tessref scene --as-draws: a mesh scene written as the GL draw render makes of it (buffers, one
// glDrawElements, the program's GLSL files) renders the same PNG bytes as the mesh scene with its
// GLSL twins, for schemes, shading and untessellated meshes; what the draw form cannot say the
// same way is refused with the key and the reason.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using test::CliRun;
using test::run_cli;
using test::TempDir;

void expect_same_image(const std::string& sets) {
  TempDir dir;
  const std::string d = (dir.path() / "draws").string();
  const CliRun w = run_cli("scene --as-draws " + d + sets);
  ASSERT_EQ(w.exit_code, 0) << w.output;
  const nlohmann::json scene = nlohmann::json::parse(test::read_file(dir.path() / "draws" / "scene.json"));
  EXPECT_FALSE(scene.contains("mesh"));
  ASSERT_EQ(scene["draws"].size(), 1u);
  const std::string small = " --set image.width=192 --set image.height=160";
  const auto mesh_png = dir.path() / "mesh.png", draws_png = dir.path() / "draws.png";
  ASSERT_EQ(run_cli("render -o " + mesh_png.string() + sets + small + " --set shaders.program=twins").exit_code, 0);
  const CliRun r = run_cli("render " + d + "/scene.json -o " + draws_png.string() + small);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::read_file(mesh_png), test::read_file(draws_png)) << sets;
}

TEST(AsDraws, DefaultSceneGivesTheTwinsBytes) { expect_same_image(""); }

TEST(AsDraws, OtherSchemesShadingAndNoTessellation) {
  expect_same_image(" --set tessellation.scheme=phong --set shading=normals");
  expect_same_image(" --set tessellation.enabled=false --set mesh.type=icosphere --set camera.fit=true");
  expect_same_image(" --set cull_back_faces=false --set polygon_mode=GL_LINE --set tessellation.inner=5");
}

TEST(AsDraws, WhatTheDrawFormCannotSayIsRefused) {
  TempDir dir;
  const std::string d = " --as-draws " + (dir.path() / "x").string();
  const CliRun flat = run_cli("scene" + d + " --set tessellation.scheme=flat");
  EXPECT_EQ(flat.exit_code, 2);
  EXPECT_THAT(flat.output, HasSubstr("tessellation.spacing, tessellation.winding: the twin evaluation shader's layout is"));
  const CliRun draws = run_cli("scene" + d + " " + std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/terrain.json");
  EXPECT_EQ(draws.exit_code, 2);
  EXPECT_THAT(draws.output, HasSubstr("draws: the scene already describes its draws"));
}

}  // namespace
}  // namespace tessref
