// Scenes with GL draws (README "Draws") on tessref alone: what is drawn, determinism across
// thread counts, and the errors a bad draw description gets.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/hash.h"
#include "render/draw_scene.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace tessref {
namespace {

const std::string kDraws = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/";

RenderResult render_file(const std::string& file, const std::vector<std::string>& sets = {}, int threads = 0) {
  const Scene scene = load_scene(kDraws + file, sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  return render_scene(scene, mesh, threads ? Parallel(threads) : Parallel());
}

std::string error_of(const std::string& file, const std::vector<std::string>& sets) {
  try {
    render_file(file, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DrawsScene, BicubicPatchesFromDrawArrays) {
  const RenderResult r = render_file("bicubic_arrays.json");
  EXPECT_EQ(r.stats.vertices_shaded, 32u);
  EXPECT_EQ(r.stats.tess.patches_in, 2u);
  EXPECT_EQ(r.stats.triangles_generated, 2u * 12u * 12u * 2u);  // quads at level 12: 288 triangles a patch
  EXPECT_GT(r.stats.raster.fragments_shaded, 10000u);
}

// Every scene of draws under tests/data/draws: the same bytes at 1 and 8 threads, in every draw buffer.
TEST(DrawsScene, SameBytesAtOneAndEightThreads) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kDraws)) {
    if (entry.path().extension() != ".json") continue;
    const std::string f = entry.path().filename().string();
    const RenderResult one = render_file(f, {}, 1);
    const RenderResult eight = render_file(f, {}, 8);
    ASSERT_EQ(one.framebuffer.draw_buffers(), eight.framebuffer.draw_buffers()) << f;
    for (int k = 0; k < one.framebuffer.draw_buffers(); ++k)
      EXPECT_EQ(*one.framebuffer.draw_buffer(k), *eight.framebuffer.draw_buffer(k)) << f << ", draw buffer " << k;
    EXPECT_EQ(one.framebuffer.depth, eight.framebuffer.depth) << f;
    ++scenes;
  }
  EXPECT_EQ(scenes, 26);
}

// Each draw with its own program: a flat-coloured strip, then the patches depth-tested against it.
TEST(DrawsScene, EachDrawUsesItsOwnProgram) {
  const RenderResult r = render_file("two_draws_depth.json");
  EXPECT_EQ(r.stats.vertices_shaded, 4u + 32u);
  EXPECT_EQ(r.stats.tess.patches_in, 2u);
  // The strip's colour (u_fill, draw 0's own uniform) where the plane hides the surface: the
  // image's centre bottom row of the plane, checked against the scene's value.
  std::size_t fill = 0;
  for (const glm::vec4& c : r.framebuffer.color)
    fill += c == glm::vec4(0.15f, 0.35f, 0.75f, 1.0f);
  EXPECT_GT(fill, 5000u);
  const RenderResult one = render_file("two_draws_depth.json", {}, 1);
  const RenderResult eight = render_file("two_draws_depth.json", {}, 8);
  EXPECT_EQ(one.framebuffer.color, eight.framebuffer.color);
}

TEST(DrawsScene, ADrawsOwnShadersAreCheckedByKey) {
  const std::string f = "two_draws_depth.json";
  EXPECT_NE(error_of(f, {"draws.0.shaders.patch_vertices=4"}).find("draws.0.shaders: a draw feeds its inputs through vertex_arrays and patch_vertices"),
            std::string::npos) << error_of(f, {"draws.0.shaders.patch_vertices=4"});
  EXPECT_NE(error_of(f, {"draws.1.shaders.program=\"twins\""}).find("a draw's own program is a custom one"), std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.shaders.uniforms.u_fill=[1, 0, 0]"}).find("draws.0.shaders.uniforms.u_fill"), std::string::npos)
      << error_of(f, {"draws.0.shaders.uniforms.u_fill=[1, 0, 0]"});
  EXPECT_NE(error_of(f, {"draws.1.shaders.vertex=\"missing.vert\""}).find("draws.1.shaders.vertex: cannot read"), std::string::npos)
      << error_of(f, {"draws.1.shaders.vertex=\"missing.vert\""});
  // Without shaders of its own a draw needs the scene's custom program.
  const std::string none = error_of("bicubic_arrays.json", {"shaders.program=\"builtin\""});
  EXPECT_NE(none.find("draws.0: has no shaders of its own"), std::string::npos) << none;
}

TEST(DrawsScene, AssemblesStripsFansAndRestartedRunsAsGlDoes) {
  const std::vector<std::vector<std::uint32_t>> runs{{0, 1, 2, 3, 4}, {5, 6, 7, 8}};
  EXPECT_EQ(assemble(DrawMode::TriangleStrip, 3, runs),
            (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 2, 3, 4, 5, 6, 7, 7, 6, 8}));
  EXPECT_EQ(assemble(DrawMode::TriangleFan, 3, runs),
            (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4, 5, 6, 7, 5, 7, 8}));
  // A partial last primitive of each run is dropped.
  EXPECT_EQ(assemble(DrawMode::Triangles, 3, runs), (std::vector<std::uint32_t>{0, 1, 2, 5, 6, 7}));
  EXPECT_EQ(assemble(DrawMode::Patches, 4, runs), (std::vector<std::uint32_t>{0, 1, 2, 3, 5, 6, 7, 8}));
}

TEST(DrawsScene, AssemblesLineStripsLoopsAndPointsAsGlDoes) {
  const std::vector<std::vector<std::uint32_t>> runs{{0, 1, 2, 3}, {4, 5, 6}, {7}};
  EXPECT_EQ(assemble(DrawMode::LineStrip, 3, runs), (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 4, 5, 5, 6}));
  EXPECT_EQ(assemble(DrawMode::LineLoop, 3, runs),
            (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 4}));
  EXPECT_EQ(assemble(DrawMode::Lines, 3, runs), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(assemble(DrawMode::Points, 3, runs), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  // With adjacency (GL 4.5, 10.1.11 to 10.1.14), for a geometry shader: lines take 4 vertices,
  // triangles 6, in the shader's order (vertex, adjacent, vertex, adjacent, vertex, adjacent).
  EXPECT_EQ(assemble(DrawMode::LineStripAdjacency, 3, {{0, 1, 2, 3, 4}}), (std::vector<std::uint32_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(assemble(DrawMode::LinesAdjacency, 3, {{0, 1, 2, 3, 4}}), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(assemble(DrawMode::TrianglesAdjacency, 3, {{0, 1, 2, 3, 4, 5, 6}}), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  // Table 10.1's strip of 12 vertices (4 triangles: first, odd, even, last odd) and of 6 (only).
  EXPECT_EQ(assemble(DrawMode::TriangleStripAdjacency, 3, {{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}}),
            (std::vector<std::uint32_t>{0, 1, 2, 6, 4, 3, 4, 0, 2, 5, 6, 8, 4, 2, 6, 10, 8, 7, 8, 4, 6, 9, 10, 11}));
  EXPECT_EQ(assemble(DrawMode::TriangleStripAdjacency, 3, {{0, 1, 2, 3, 4, 5}}), (std::vector<std::uint32_t>{0, 1, 2, 5, 4, 3}));
  EXPECT_EQ(primitive_corners(DrawMode::TriangleStripAdjacency), 6);
  EXPECT_EQ(primitive_corners(DrawMode::LineLoop), 2);
  EXPECT_EQ(primitive_corners(DrawMode::Points), 1);
  EXPECT_EQ(primitive_corners(DrawMode::TriangleFan), 3);
}

// Isolines and point mode reach the rasterizer: every blade segment and domain point is drawn.
TEST(DrawsScene, IsolinesAndPointModeAreDrawnAndDeterministic) {
  const RenderResult grass = render_file("grass_isolines.json");
  EXPECT_EQ(grass.stats.tess.lines_out, 480u);  // 2 patches x 40 blades x 6 segments
  EXPECT_EQ(grass.stats.raster.triangles_in, 480u + 4u + 4u);  // + the loop's 4 lines and 4 points
  EXPECT_GT(grass.stats.raster.fragments_shaded, 2000u);
  const RenderResult dome = render_file("dome_points.json");
  EXPECT_EQ(dome.stats.tess.points_out, dome.stats.tess.domain_points);
  EXPECT_GT(dome.stats.tess.points_out, 300u);
}

// Uniforms by GL name: struct members, arrays of structs, nested, non-square matrices, unsigned,
// boolean and double vectors, array elements from an index on. The colour is exact.
TEST(DrawsScene, UniformsOfEveryKindByTheirGlNames) {
  const RenderResult r = render_file("uniform_types.json");
  ASSERT_EQ(r.stats.raster.fragments_shaded, 256u);
  for (const glm::vec4& c : r.framebuffer.color) ASSERT_EQ(c, glm::vec4(0.25f, 0.5f, 0.5f, 0.625f));
  const std::string f = "uniform_types.json";
  const std::string is_struct = error_of(f, {"draws.0.shaders.uniforms.u_rig=1"});
  EXPECT_NE(is_struct.find("draws.0.shaders.uniforms.u_rig: the uniform is a struct Rig: give an object of its members (lights, m)"),
            std::string::npos) << is_struct;
  const std::string member = error_of(f, {"draws.0.shaders.uniforms.u_rig.lights.0.colour=[1, 1, 1]"});
  EXPECT_NE(member.find("u_rig.lights[0].colour: the program has no active uniform of that name"), std::string::npos) << member;
  const std::string past = error_of(f, {"draws.0.shaders.uniforms.u_i[1]=[1, 2, 3]"});
  EXPECT_NE(past.find("takes 1 values (this element) or 2 (the elements from it to the end of the array), got 3"),
            std::string::npos) << past;
}

// A height map sampled in the TES; a sampler of another target than the texture's is refused.
TEST(DrawsScene, TexturesAreBoundPerDrawAndCheckedAgainstTheSamplerTarget) {
  const RenderResult r = render_file("terrain.json");
  EXPECT_EQ(r.stats.tess.patches_in, 4u);
  EXPECT_GT(r.stats.raster.fragments_shaded, 20000u);
  // Flattened (the height map's texels all 0): another image.
  const RenderResult flat = render_file("terrain.json", {"draws.0.shaders.uniforms.u_scale=0"});
  EXPECT_NE(r.framebuffer.color, flat.framebuffer.color);
  const std::string wrong = error_of("uniform_types.json", {"draws.0.shaders.fragment=\"sampler3d.frag\"",
                                                            "draws.0.shaders.uniforms={\"u_rig\": null, \"u_u\": null, "
                                                            "\"u_b\": null, \"u_d\": null, \"u_m32\": null, \"u_i[1]\": null}",
                                                            "draws.0.shaders.textures={\"u_volume\": \"heightmap.pgm\"}"});
  // The texture is the image a plain file name gives, a GL_TEXTURE_2D: GL draws nothing from a
  // sampler3D on that unit, so tessref refuses the pairing by key.
  EXPECT_NE(wrong.find("draws.0.shaders.textures.u_volume.target: the uniform is a sampler3D, which reads a GL_TEXTURE_3D "
                       "texture, and this one is GL_TEXTURE_2D"),
            std::string::npos) << wrong;
}

// A std140 block from buffer bytes, bound at an offset: the errors name the key and GL's rule.
TEST(DrawsScene, UniformBuffersAreCheckedAgainstTheBlocks) {
  const std::string f = "instanced_blocks.json";
  const RenderResult r = render_file(f);
  EXPECT_EQ(r.stats.tess.patches_in, 6u);
  // The block read from byte 0 instead (64 floats of 9): another image.
  const RenderResult shifted = render_file(f, {"draws.0.uniform_buffers.0.offset=0"});
  EXPECT_NE(r.framebuffer.color, shifted.framebuffer.color);
  const std::string unaligned = error_of(f, {"draws.0.uniform_buffers.0.offset=128"});
  EXPECT_NE(unaligned.find("draws.0.uniform_buffers.0.offset: 128 is not a multiple of 256"), std::string::npos) << unaligned;
  const std::string unbound = error_of(f, {"draws.0.uniform_buffers.0.binding=3"});
  EXPECT_NE(unbound.find("draws.0.uniform_buffers.0.binding: the program has no uniform block at binding 3 (its blocks: Shading at 1"),
            std::string::npos) << unbound;
  const std::string short_range = error_of(f, {"draws.0.uniform_buffers.0.size=64"});
  EXPECT_NE(short_range.find("draws.0.uniform_buffers.0: uniform block 'Shading' (binding 1) reads 120 bytes; the bound range holds 64"),
            std::string::npos) << short_range;
  const std::string past_end = error_of(f, {"draws.0.uniform_buffers.0.size=1024"});
  EXPECT_NE(past_end.find("bytes [256, 1280) of buffer 'shading', which holds 376 bytes"), std::string::npos) << past_end;
}

TEST(DrawsScene, BadDrawsNameTheKeyAndTheRule) {
  const std::string f = "bicubic_arrays.json";
  EXPECT_NE(error_of(f, {"draws.0.count=33"}).find(
                "draws.0.vertex_arrays.in_position: gl_VertexID 32 reads bytes [384, 396) of buffer 'control_points', "
                "which holds 384 bytes"),
            std::string::npos)
      << error_of(f, {"draws.0.count=33"});
  EXPECT_NE(error_of(f, {"draws.0.patch_vertices=33"}).find("draws.0.patch_vertices: glPatchParameteri(GL_PATCH_VERTICES) takes 1..32"),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.vertex_arrays.in_position.normalized=true"}).find("normalized applies to integer types"),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.vertex_arrays.in_position.stride=4096"}).find("GL_MAX_VERTEX_ATTRIB_STRIDE"),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.vertex_arrays.in_position.type=\"GL_INT_2_10_10_10_REV\""}).find("needs size 4 or GL_BGRA"),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.vertex_arrays.in_position.buffer=\"nope\""}).find("no buffer named \"nope\" (buffers: control_points)"),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.mode=\"GL_TRIANGLES\""}).find("draws.0.mode: the patch parameters apply to GL_PATCHES only"),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.vertex_arrays={\"in_positon\": {\"buffer\": \"control_points\", \"size\": 3}}"})
                .find("no active input named \"in_positon\""),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.basevertex=1"}).find("glDrawArrays* takes no basevertex"), std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.polygon_mode=\"GL_WIRE\""}).find("draws.0.polygon_mode: expected one of GL_FILL, GL_LINE, GL_POINT, got a string"),
            std::string::npos);
  const std::string adjacency = error_of("two_draws_depth.json", {"draws.0.mode=\"GL_LINES_ADJACENCY\""});
  EXPECT_NE(adjacency.find("adjacency primitives need a geometry shader"), std::string::npos) << adjacency;
  EXPECT_NE(error_of(f, {"draws.0.viewport=[0, 0, -1, 8]"}).find("draws.0.viewport: glViewport refuses a negative width"),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.viewport=[0, 0, 8]"}).find("draws.0.viewport: expected [x, y, width, height] as 4 integers"),
            std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.viewport=[0, 0, 20000, 8]"}).find("at most 16384 (GL_MAX_VIEWPORT_DIMS)"), std::string::npos);
  EXPECT_NE(error_of(f, {"draws.0.depth_range=[0, \"far\"]"}).find("draws.0.depth_range: expected [near, far] as 2 numbers"),
            std::string::npos);
}

// Read-only shader storage blocks: a runtime array takes its length from the bound range, and
// what GL would refuse or tessref cannot run names the key and the rule.
TEST(DrawsScene, StorageBlocksAreSizedByTheirRangeAndCheckedAsGlChecks) {
  const RenderResult r = render_file("storage_blocks.json");
  EXPECT_EQ(r.stats.tess.patches_in, 2u);
  EXPECT_EQ(r.stats.vertices_shaded, 32u);
  const std::string f = "storage_blocks.json";
  const struct {
    std::vector<std::string> sets;
    std::string message;
  } cases[] = {
      {{"draws.0.shader_storage_buffers=[{\"binding\": 0, \"buffer\": \"control_points\"}]"},
       "shader storage block 'Lift' (binding 1) has a runtime-sized array; bind a buffer range there to size it"},
      {{"draws.0.shader_storage_buffers.2={\"binding\": 5, \"buffer\": \"lift\"}"},
       "draws.0.shader_storage_buffers.2.binding: the program has no shader storage block at binding 5 (its blocks: "},
      {{"draws.0.shader_storage_buffers.1.size=8"},
       "draws.0.shader_storage_buffers.1: shader storage block 'Lift' (binding 1) reads 16 bytes; the bound range holds 8"},
      {{"draws.0.shader_storage_buffers.1.offset=16"}, "GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT may be as large as 256"},
      {{"draws.0.shader_storage_buffers.1.binding=8"}, "draws.0.shader_storage_buffers.1.binding"},
  };
  for (const auto& c : cases) EXPECT_NE(error_of(f, c.sets).find(c.message), std::string::npos) << error_of(f, c.sets);
}

// A write into a block bound at an offset lands in the buffer at that offset through the std430
// layout (lift[0] is float 68: byte 256 + 16), and only there; later invocations read it back.
TEST(DrawsScene, StorageBlockWritesLandInTheBoundRange) {
  const auto lift_after = [](int threads) {
    const Scene scene = load_scene(kDraws + "storage_blocks.json", {"shaders.tess_evaluation=\"storage_write.tese\""});
    std::vector<std::string> warnings;
    Framebuffer fb;
    DrawnMemory memory;
    render_scene(scene, build_mesh(scene.mesh, warnings), Parallel(threads), fb, {}, nullptr, &memory);
    const std::vector<draw::Buffer>& buffers = memory.buffers;
    std::vector<float> lift(buffers.at(1).bytes.size() / 4);
    std::memcpy(lift.data(), buffers.at(1).bytes.data(), lift.size() * 4);
    return lift;
  };
  const std::vector<float> one = lift_after(1);
  ASSERT_EQ(one.size(), 72u);
  const float block[8] = {1.0f, 0.05f, 0.0f, 0.0f, 0.5f, -0.75f, 0.25f, 7.0f};  // as uploaded
  for (std::size_t i = 0; i < one.size(); ++i)
    if (i != 68) {
      EXPECT_EQ(one[i], i < 64 ? 9.0f : block[i - 64]) << i;
    }
  EXPECT_NE(one[68], 0.5f);  // the last evaluation's height
  EXPECT_TRUE(std::isfinite(one[68]));
  EXPECT_EQ(one, lift_after(2));
}

// glDepthRange clamps its arguments to [0, 1] (GL 4.5, 13.6.1); the draw keeps GL's doubles.
TEST(DrawsScene, DepthRangeIsClampedAsGlDoes) {
  const Scene s = load_scene(kDraws + "viewports.json", {"draws.1.depth_range=[-0.5, 1.5]"});
  EXPECT_EQ(s.draws[1].raster.depth_range_near, 0.0);
  EXPECT_EQ(s.draws[1].raster.depth_range_far, 1.0);
  EXPECT_EQ(s.draws[0].raster.depth_range_far, 0.5);
  ASSERT_TRUE(s.draws[2].raster.viewport);
  EXPECT_EQ(s.draws[2].raster.viewport->x, 170);
  EXPECT_FALSE(load_scene(kDraws + "terrain.json", {}).draws[0].raster.viewport);
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

// The framebuffer's keys: each bad value names its key and the rule.
TEST(DrawsScene, BadFramebuffersNameTheKeyAndTheRule) {
  const std::string f = "attachments.json";
  const auto expect_error = [&](const std::vector<std::string>& sets, const std::string& message) {
    const std::string e = error_of(f, sets);
    EXPECT_NE(e.find(message), std::string::npos) << sets[0] << ": " << e;
  };
  expect_error({"framebuffer.color.2.internalformat=\"GL_RGB8\""},
               "framebuffer.color.2.internalformat: expected GL_RGBA32F, GL_RGBA16F, GL_RGBA8 or GL_SRGB8_ALPHA8, got \"GL_RGB8\"");
  expect_error({"framebuffer.color=[\"a.png\", \"a.png\", \"a.png\", \"a.png\", \"a.png\", \"a.png\", \"a.png\", \"a.png\", \"a.png\"]"},
               "framebuffer.color: expected 1 to 8 attachments (GL_MAX_DRAW_BUFFERS), got 9");
  expect_error({"framebuffer.depth.internalformat=\"GL_DEPTH_COMPONENT16\""},
               "expected GL_DEPTH_COMPONENT32F or GL_DEPTH_COMPONENT24, got \"GL_DEPTH_COMPONENT16\"");
  expect_error({"framebuffer.color.0.file=\"heightmap.pgm\""}, "framebuffer.color.0: ");  // 32x32, the image 256x256
  expect_error({"framebuffer.color.0.file=\"heightmap.pgm\""}, "is 32x32, the image 256x256");
  expect_error({"framebuffer.color.0.file=\"missing.png\""}, "framebuffer.color.0: ");
  expect_error({"draws.1.clear={}"}, "draws.1.clear.color: give color, depth or both");
  expect_error({"draws.1.enable=[\"GL_FRAMEBUFFER_sRGB\"]"},
               "GL_TEXTURE_CUBE_MAP_SEAMLESS or GL_CLIP_DISTANCE0 to GL_CLIP_DISTANCE7, got a string (\"GL_FRAMEBUFFER_sRGB\")");
  expect_error({"draws.1.enable=[\"GL_CLIP_DISTANCE8\"]"}, "draws.1.enable: expected GL_DEPTH_TEST");
  const std::string mesh = error_of("../../../scenes/default.json", {"framebuffer={\"color\": \"x.png\"}"});
  EXPECT_NE(mesh.find("framebuffer: takes a scene of draws"), std::string::npos) << mesh;
}

}  // namespace
}  // namespace tessref
