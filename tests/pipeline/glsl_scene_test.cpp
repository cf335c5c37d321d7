// Scenes with the user's GLSL (shaders.program = custom): the example scene renders with exact
// counts, and bad settings and bad shaders are errors that name the key, file and line.
#include <gtest/gtest.h>

#include "common/error.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "test_util.h"

namespace tessref {
namespace {

const std::filesystem::path kExample = std::filesystem::path(TESSREF_SOURCE_DIR) / "scenes/displacement.json";

DrawStats render(const std::filesystem::path& file, std::vector<std::string> sets) {
  sets.push_back("image.width=128");
  sets.push_back("image.height=128");
  const Scene scene = load_scene(file, sets);
  std::vector<std::string> warnings;
  return render_scene(scene, build_mesh(scene.mesh, warnings), Parallel(2)).stats;
}

std::string error_of(const std::filesystem::path& file, const std::vector<std::string>& sets) {
  try {
    render(file, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(GlslScene, DisplacementExampleRenders) {
  const DrawStats s = render(kExample, {});
  // 256 torus patches at level 24, fractional_odd: 937 triangles each (tessref tpg).
  EXPECT_EQ(s.tess.patches_in, 256u);
  EXPECT_EQ(s.triangles_generated, 256u * 937u);
  EXPECT_GT(s.raster.fragments_shaded, 3000u);
  // The displacement moves the silhouette: the same scene without it covers other pixels.
  const DrawStats flat = render(kExample, {"shaders.uniforms.u_amplitude=0"});
  EXPECT_NE(flat.raster.fragments_shaded, s.raster.fragments_shaded);
}

TEST(GlslScene, BadUniformsNameTheKey) {
  EXPECT_NE(error_of(kExample, {"shaders.uniforms.u_amplitude=true"})
                .find("shaders.uniforms.u_amplitude: the uniform is a float, not a bool"),
            std::string::npos);
  EXPECT_NE(error_of(kExample, {"shaders.uniforms.u_amplitude=[1,2]"})
                .find("shaders.uniforms.u_amplitude: the uniform is a float, which takes 1 values, got 2"),
            std::string::npos);
  const std::string unknown = error_of(kExample, {"shaders.uniforms.u_nope=1"});
  EXPECT_NE(unknown.find("shaders.uniforms.u_nope: the program has no active uniform of that name"), std::string::npos)
      << unknown;
  EXPECT_NE(unknown.find("u_frequency"), std::string::npos) << unknown;
  EXPECT_NE(error_of(kExample, {"shaders.uniforms.u_num_lights=1.5"}).find("is not a 32-bit integer"),
            std::string::npos);
}

TEST(GlslScene, BadFilesAndShadersNameFileAndLine) {
  test::TempDir dir;
  EXPECT_NE(error_of(kExample, {"shaders.tess_evaluation=/nonexistent/x.tese"})
                .find("shaders.tess_evaluation: cannot read '/nonexistent/x.tese'"),
            std::string::npos);
  EXPECT_NE(error_of(kExample, {"shaders.vertex=twin:nope.vert"}).find("no built-in GLSL twin named 'nope.vert'"),
            std::string::npos);
  const auto bad = dir.write("bad.tese",
                             "#version 450\nlayout(triangles) in;\nvoid main() {\n  gl_Position = vec4(oops);\n}\n");
  const std::string e = error_of(kExample, {"shaders.tess_evaluation=" + bad.string()});
  EXPECT_NE(e.find(bad.string() + ":4: error:"), std::string::npos) << e;
  EXPECT_NE(e.find("oops"), std::string::npos) << e;
  EXPECT_NE(error_of(kExample, {"tessellation.enabled=false"}).find("tessellation.enabled is false"),
            std::string::npos);
}

TEST(GlslScene, RunawayShaderStopsAtTheBudget) {
  test::TempDir dir;
  const auto loop = dir.write("loop.tese",
                              "#version 450\nlayout(triangles) in;\nuniform int u_n;\n"
                              "layout(location = 0) out vec3 v_world_position;\n"
                              "layout(location = 1) out vec3 v_world_normal;\n"
                              "void main() {\n  float x = 0.0;\n  for (int i = 0; i != u_n; i += 2) x += 1.0;\n"
                              "  v_world_position = gl_TessCoord;\n  v_world_normal = vec3(x);\n"
                              "  gl_Position = vec4(gl_TessCoord, 1.0);\n}\n");
  const std::string e = error_of(kExample, {"shaders.tess_evaluation=" + loop.string(), "shaders.uniforms={\"u_n\": 1, \"u_amplitude\": null, \"u_frequency\": null}",
                                            "shaders.max_instructions=100000"});
  EXPECT_NE(e.find("tessellation evaluation shader, patch 0, invocation 0, line 8:"), std::string::npos) << e;
  EXPECT_NE(e.find("instruction budget of 100000 exceeded"), std::string::npos) << e;
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

RenderResult render_full(const std::filesystem::path& file, std::vector<std::string> sets) {
  sets.push_back("image.width=64");
  sets.push_back("image.height=64");
  const Scene scene = load_scene(file, sets);
  std::vector<std::string> warnings;
  return render_scene(scene, build_mesh(scene.mesh, warnings), Parallel(2));
}

TEST(GlslScene, TexturesFromImageFilesAndDiscard) {
  test::TempDir dir;
  // A 2 x 2 image, top row first in the file: (red, green / blue, white); GL's row 0 is the bottom.
  Rgb8Image img;
  img.width = img.height = 2;
  img.pixels = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  write_rgb8_image(img, dir.path() / "t.png");
  const auto fs = dir.write("tex.frag",
                            "#version 450\nuniform sampler2D u_tex;\nuniform vec2 u_at;\n"
                            "layout(location = 0) out vec4 color;\n"
                            "void main() {\n  if (gl_FragCoord.x < 32.0) discard;\n"
                            "  color = texture(u_tex, u_at);\n}\n");
  const std::vector<std::string> base = {
      "shaders.program=custom", "shaders.vertex=twin:transform.vert", "shaders.tess_control=twin:pn_triangles.tesc",
      "shaders.tess_evaluation=twin:pn_triangles.tese", "shaders.fragment=" + fs.string(),
      "shaders.textures={\"u_tex\": {\"path\": \"" + (dir.path() / "t.png").string() + "\", \"filter\": \"nearest\"}}"};
  auto with_at = [&](const char* at) {
    auto sets = base;
    sets.push_back(std::string("shaders.uniforms={\"u_at\": ") + at + "}");
    return sets;
  };
  const RenderResult bottom_left = render_full("", with_at("[0.25, 0.25]"));
  const RenderResult top_right = render_full("", with_at("[0.75, 0.75]"));
  const Framebuffer& fb = bottom_left.framebuffer;
  std::size_t left_drawn = 0, right_drawn = 0;
  for (int y = 0; y < fb.height; ++y)
    for (int x = 0; x < fb.width; ++x) {
      const std::size_t i = fb.index(x, y);
      if (fb.depth[i] == 1.0f) continue;
      (x < 32 ? left_drawn : right_drawn)++;
      // The image's bottom-left texel is blue, its top-right one green.
      EXPECT_EQ(fb.color[i], glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)) << x << "," << y;
      EXPECT_EQ(top_right.framebuffer.color[i], glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)) << x << "," << y;
    }
  // Discarded fragments write neither color nor depth.
  EXPECT_EQ(left_drawn, 0u);
  EXPECT_GT(right_drawn, 200u);
  const std::string e = error_of(kExample, {"shaders.textures={\"u_amplitude\": \"x.png\"}"});
  EXPECT_NE(e.find("shaders.textures.u_amplitude: the program has no active sampler uniform"), std::string::npos) << e;
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

// A uniform block's member set by name, an attribute fed by location, one-vertex patches.
TEST(GlslScene, UniformBlockMembersAttributeLocationsAndPatchVertices) {
  test::TempDir dir;
  const auto vs = dir.write("p.vert", "#version 450\nlayout(location = 3) in vec3 p;\n"
                                      "void main() { gl_Position = vec4(p, 1.0); }\n");
  // Each one-vertex patch becomes a small quad around its vertex, in the block's color.
  const auto tcs = dir.write("p.tesc", "#version 450\nlayout(vertices = 1) out;\nvoid main() {\n"
                                       "  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;\n"
                                       "  gl_TessLevelOuter = float[4](1.0, 1.0, 1.0, 1.0);\n"
                                       "  gl_TessLevelInner = float[2](1.0, 1.0);\n}\n");
  const auto tes = dir.write("p.tese", "#version 450\nlayout(quads) in;\nuniform mat4 u_view_projection;\n"
                                       "void main() {\n  vec4 c = u_view_projection * gl_in[0].gl_Position;\n"
                                       "  gl_Position = c + vec4((gl_TessCoord.xy - 0.5) * 0.2 * c.w, 0.0, 0.0);\n}\n");
  const auto fs = dir.write("p.frag", "#version 450\nlayout(std140) uniform Tint { vec4 tint; float unused; };\n"
                                      "layout(location = 0) out vec4 color;\nvoid main() { color = tint; }\n");
  const RenderResult r = render_full(
      "", {"shaders.program=custom", "shaders.vertex=" + vs.string(), "shaders.tess_control=" + tcs.string(),
           "shaders.tess_evaluation=" + tes.string(), "shaders.fragment=" + fs.string(), "shaders.patch_vertices=1",
           "shaders.attributes={\"3\": \"position\"}", "shaders.uniforms={\"Tint.tint\": [0, 1, 0, 1]}",
           "cull_back_faces=false"});
  // The torus's 256 triangles' 768 indices, one patch each.
  EXPECT_EQ(r.stats.tess.patches_in, 768u);
  std::size_t green = 0;
  for (const glm::vec4& c : r.framebuffer.color) green += c == glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
  EXPECT_GT(green, 100u);
}

}  // namespace
}  // namespace tessref
