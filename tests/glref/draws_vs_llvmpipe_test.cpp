// Scenes that describe GL draws (buffers, vertex arrays, glDraw* calls) drawn by tessref and by
// the GL driver from the same scene file: the driver gets the same bytes through the same GL
// calls an application would make (glref/gl_draws.h). Figures are printed; on failure the diff
// and both images go to the build directory.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "common/fixed_point.h"
#include "glref/scene_renderer.h"
#include "io/image_compare.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace tessref::glref {
namespace {

struct DrawsOutcome {
  ImageComparison within1;  // tolerance 1/255
  DrawStats stats;
};

// `path` from the source folder; `file`, its name in messages and written images.
DrawsOutcome compare_scene(GlContext& ctx, const std::string& path, const std::string& file,
                           const std::vector<std::string>& sets = {}) {
  const Scene scene = load_scene(std::string(TESSREF_SOURCE_DIR) + "/" + path, sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  const RenderResult ours = render_scene(scene, mesh, Parallel());
  SceneRenderer renderer(ctx, scene, mesh);
  const Framebuffer gl = renderer.render();
  DrawsOutcome out{compare_framebuffers(ours.framebuffer, gl, 1, true), ours.stats};
  std::printf("[ figures  ] %s: %s; %llu fragments shaded\n", file.c_str(), out.within1.summary().c_str(),
              static_cast<unsigned long long>(ours.stats.raster.fragments_shaded));
  if (out.within1.within_tolerance != out.within1.pixels) {
    const std::string base = std::string(TESSREF_BINARY_DIR) + "/draws_vs_llvmpipe_" + file;
    write_rgb8_image(out.within1.diff, base + "_diff.png");
    write_color_image(ours.framebuffer, base + "_tessref.png");
    write_color_image(gl, base + "_gl.png");
    std::printf("[ figures  ] wrote %s_{diff,tessref,gl}.png\n", base.c_str());
  }
  return out;
}

DrawsOutcome compare_draws(GlContext& ctx, const std::string& file, const std::vector<std::string>& sets = {}) {
  return compare_scene(ctx, "tests/data/draws/" + file, file, sets);
}

// At most `coverage` pixels covered in one image only, and every other pixel within 1/255.
void expect_matches(const DrawsOutcome& o, std::size_t coverage = 4) {
  EXPECT_LE(o.within1.coverage_mismatch, coverage) << o.within1.summary();
  EXPECT_LE(o.within1.pixels - o.within1.within_tolerance, o.within1.coverage_mismatch) << o.within1.summary();
}

// Two 16-control-point bicubic patches from glDrawArrays(GL_PATCHES, 0, 32) with no index buffer.
TEST(DrawsVsLlvmpipe, BicubicPatchesFromDrawArrays) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "bicubic_arrays.json");
  EXPECT_GT(o.stats.raster.fragments_shaded, 10000u);
  EXPECT_EQ(o.stats.tess.patches_in, 2u);
  expect_matches(o);
}

// Derivatives at triangle edges (issue 20): a fragment quad's lanes that cover nothing run as
// helper invocations with inputs interpolated at their own pixels, as on llvmpipe. Before, they
// held an earlier fragment's inputs, and dFdx/dFdy/fwidth were wrong along every edge.
TEST(DrawsVsLlvmpipe, DerivativesAndHelperInvocationsAtTriangleEdges) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "derivatives.json");
  EXPECT_GT(o.stats.raster.fragments_shaded, 10000u);
  expect_matches(o);
}

// A frame of two draws with a program each: an untessellated triangle strip, then bicubic patches
// depth-tested against it. Where the surface crosses the plane the two depths are near-equal, so
// a pixel or two may resolve differently (GL_LESS on depths that differ in the last bits).
TEST(DrawsVsLlvmpipe, TessellatedDrawDepthTestedAgainstAnEarlierOne) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "two_draws_depth.json");
  EXPECT_EQ(o.stats.tess.patches_in, 2u);
  EXPECT_GT(o.stats.raster.fragments_shaded, 30000u);
  EXPECT_LE(o.within1.coverage_mismatch, 4u) << o.within1.summary();
  EXPECT_LE(o.within1.pixels - o.within1.within_tolerance, 2u) << o.within1.summary();
}

// Isolines: grass blades from 4-vertex ground patches, depth-tested, then a GL_LINE_LOOP and
// GL_POINTS. Lines between window positions computed by the same GLSL on both sides; llvmpipe's
// JIT may fuse a multiply-add in the projection, moving an end by an ulp, which changes a pixel
// only where a line end sits on a diamond-exit tie (measured: 0 pixels).
TEST(DrawsVsLlvmpipe, GrassIsolinesLineLoopAndPoints) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "grass_isolines.json");
  EXPECT_EQ(o.stats.tess.patches_in, 2u);
  EXPECT_EQ(o.stats.tess.lines_out, 2u * 40u * 6u);
  EXPECT_GT(o.stats.raster.fragments_shaded, 2000u);
  expect_matches(o);
}

// Point mode over a wireframe (glPolygonMode(GL_LINE)) and a GL_LINE_STRIP.
TEST(DrawsVsLlvmpipe, PointModeOverAWireframe) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "dome_points.json");
  EXPECT_EQ(o.stats.tess.patches_in, 2u);
  EXPECT_EQ(o.stats.tess.points_out, o.stats.tess.domain_points);
  EXPECT_GT(o.stats.raster.fragments_shaded, 1000u);
  expect_matches(o);
}

// Instanced and indexed, with interleaved normalized attributes, a uniform struct array and a
// std140 block bound at byte 256 of a buffer (its padding full of 77s a wrong stride would read).
TEST(DrawsVsLlvmpipe, InstancedIndexedWithAStructArrayAndAStd140Block) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "instanced_blocks.json");
  EXPECT_EQ(o.stats.tess.patches_in, 6u);  // 2 patches x 3 instances
  EXPECT_GT(o.stats.raster.fragments_shaded, 5000u);
  expect_matches(o);
}

// The same uniforms through glUniform* on the driver (struct members and elements by GL name,
// uvec, bvec, dvec, non-square matrices, glUniform1iv from an element on): the same colour.
TEST(DrawsVsLlvmpipe, UniformsOfEveryKindByTheirGlNames) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "uniform_types.json");
  EXPECT_EQ(o.within1.identical, o.within1.pixels) << o.within1.summary();
}

// Terrain: 4-vertex quad patches from glDrawArrays, displaced by a height map the TES samples with
// textureLod at level 0; the GL runner uploads the same texels (GL_RGBA32F) to the same unit.
TEST(DrawsVsLlvmpipe, TerrainFromAHeightMapSampledInTheTes) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "terrain.json");
  EXPECT_EQ(o.stats.tess.patches_in, 4u);
  EXPECT_GT(o.stats.raster.fragments_shaded, 20000u);
  expect_matches(o);
}

// scenes/terrain.json: distance-tessellated quad patches displaced by a mip-mapped GL_R16F height
// map (textureLod between levels 1 and 2 in the TES), coloured from a mip-mapped GL_RGB8 texture
// with implicit LOD, shadowed through a GL_DEPTH_COMPONENT24 map with a sampler2DShadow
// (GL_LEQUAL, GL_LINEAR). Identical coverage; one pixel of 196,608 beyond 1/255 (10/255 in blue,
// (426, 153) from the bottom): the evaluation shader's positions differ from llvmpipe's by up to
// 1024 float ulps (its normalize and mix are not tessref's to the bit), so a fragment on a
// shadow's edge can compare the other way. 61 pixels differ at all.
TEST(DrawsVsLlvmpipe, TerrainWithMipmapsAndAShadowMap) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_scene(*ctx, "scenes/terrain.json", "terrain_scene.json");
  EXPECT_EQ(o.stats.tess.patches_in, 16u);
  EXPECT_GT(o.stats.raster.fragments_shaded, 100000u);
  EXPECT_EQ(o.within1.coverage_mismatch, 0u) << o.within1.summary();
  EXPECT_LE(o.within1.pixels - o.within1.within_tolerance, 4u) << o.within1.summary();
}

// The terrain's shadow map is what tessref draws from scenes/terrain_light.json, bit for bit (the
// command that wrote it is in that scene's description).
TEST(DrawsVsLlvmpipe, TerrainShadowMapIsTheLightPassDepth) {
  const Scene scene = load_scene(std::string(TESSREF_SOURCE_DIR) + "/scenes/terrain_light.json");
  std::vector<std::string> warnings;
  const RenderResult light = render_scene(scene, build_mesh(scene.mesh, warnings), Parallel());
  const FloatImage stored = read_float_image(std::string(TESSREF_SOURCE_DIR) + "/scenes/terrain/shadow_depth.exr");
  ASSERT_EQ(stored.width, light.framebuffer.width);
  ASSERT_EQ(stored.height, light.framebuffer.height);
  std::size_t differ = 0;
  for (int y = 0; y < stored.height; ++y)
    for (int x = 0; x < stored.width; ++x)  // the file's top row first, the framebuffer's bottom row
      differ += stored.pixels[std::size_t((stored.height - 1 - y) * stored.width + x) * std::size_t(stored.channels)] !=
                light.framebuffer.depth[std::size_t(y * light.framebuffer.width + x)];
  EXPECT_EQ(differ, 0u);
}

// Fixed-function state: culling with clockwise front faces, blending (separate alpha factors, a
// constant colour, reverse subtract, GL_MAX), depth functions with depth writes off, a scissor
// box and a colour mask, over three draws.
TEST(DrawsVsLlvmpipe, FixedFunctionStateOverThreeDraws) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "fixed_function.json");
  EXPECT_GT(o.stats.raster.fragments_shaded, 30000u);
  EXPECT_EQ(o.stats.raster.triangles_culled, 0u);  // the patches face the camera clockwise: all front
  EXPECT_LE(o.within1.coverage_mismatch, 4u) << o.within1.summary();
  EXPECT_LE(o.within1.pixels - o.within1.within_tolerance, 4u) << o.within1.summary();
  // glCullFace(GL_FRONT) then removes every patch triangle, on both sides.
  const DrawsOutcome front = compare_draws(*ctx, "fixed_function.json", {"draws.0.cull_face=\"GL_FRONT\""});
  EXPECT_EQ(front.stats.raster.triangles_culled, 576u);
  EXPECT_EQ(front.within1.within_tolerance, front.within1.pixels) << front.within1.summary();
}

// Read-only shader storage blocks: control points pulled by gl_VertexID with no vertex arrays, and
// a per-patch value from a block at offset 256 whose runtime array the bound range sizes.
TEST(DrawsVsLlvmpipe, VertexPullingAndAPatchParameterFromStorageBlocks) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "storage_blocks.json");
  EXPECT_EQ(o.stats.tess.patches_in, 2u);
  EXPECT_GT(o.stats.raster.fragments_shaded, 10000u);
  expect_matches(o);
  // The range one float shorter: lift.length() is 2, so both patches sit scale.y = 0.05 lower.
  const DrawsOutcome shorter = compare_draws(*ctx, "storage_blocks.json", {"draws.0.shader_storage_buffers.1.size=24"});
  expect_matches(shorter);
  EXPECT_NE(shorter.stats.raster.fragments_shaded, o.stats.raster.fragments_shaded);
}

// A frame that starts from image files and clears per draw (within scissor boxes, through a colour
// mask): the driver gets the same images uploaded and the same glClear calls.
TEST(DrawsVsLlvmpipe, InitialImagesAndClearsPerDraw) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "clears.json");
  EXPECT_EQ(o.stats.tess.patches_in, 2u);
  EXPECT_GT(o.stats.raster.fragments_shaded, 10000u);
  expect_matches(o);
}

// Per draw buffer: how many pixels hold the same floats in both framebuffers, and the largest
// difference of a channel.
struct BufferAgreement {
  std::size_t identical = 0, pixels = 0;
  float max_difference = 0.0f;
};

BufferAgreement agreement(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  BufferAgreement out;
  out.pixels = a.size();
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    out.identical += a[i] == b[i];
    for (int c = 0; c < 4; ++c) out.max_difference = std::max(out.max_difference, std::abs(a[i][c] - b[i][c]));
  }
  return out;
}

// A G-buffer: GL_RGBA8, GL_SRGB8_ALPHA8 (GL_FRAMEBUFFER_SRGB on, alpha-blended), GL_RGBA16F and
// GL_RGBA32F draw buffers over a 24-bit depth buffer, initial images and a scissored clear. Each
// buffer is compared value for value. llvmpipe encodes sRGB with a polynomial approximation
// (lp_bld_format_srgb.c), tessref with GL's equation, so the sRGB buffer may differ by one step
// of 8 bits where the two round differently. Figures (Mesa 22.3.6): RGBA8 identical, sRGB 60,811
// of 65,536 identical and the rest one step apart, RGBA16F 65,496 identical, 24-bit depth 57,278
// identical and at most 3 steps apart.
TEST(DrawsVsLlvmpipe, FourDrawBuffersOfFourFormatsAndA24BitDepthBuffer) {
  TESSREF_REQUIRE_GL(ctx);
  const Scene scene = load_scene(std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/attachments.json");
  std::vector<std::string> warnings;
  const RenderResult ours = render_scene(scene, build_mesh(scene.mesh, warnings), Parallel());
  SceneRenderer renderer(*ctx, scene, build_mesh(scene.mesh, warnings));
  const Framebuffer gl = renderer.render();
  ASSERT_EQ(ours.framebuffer.draw_buffers(), 4);
  ASSERT_EQ(gl.draw_buffers(), 4);
  EXPECT_GT(ours.stats.raster.fragments_shaded, 10000u);
  std::size_t depth_equal = 0;
  std::int64_t depth_steps = 0;  // largest difference of the stored 24-bit integers
  for (std::size_t i = 0; i < gl.depth.size(); ++i) {
    depth_equal += ours.framebuffer.depth[i] == gl.depth[i];
    depth_steps = std::max(depth_steps, std::abs(std::int64_t(fixed::depth24_from_float(ours.framebuffer.depth[i])) -
                                                 std::int64_t(fixed::depth24_from_float(gl.depth[i]))));
  }
  std::printf("[ figures  ] attachments.json: depth (24-bit) identical %zu of %zu, largest difference %lld steps\n",
              depth_equal, gl.depth.size(), static_cast<long long>(depth_steps));
  // Every stored value is one the format holds, and the window z of a fragment differs from
  // llvmpipe's by a few float ulps (its plane equations are float, tessref's barycentrics double;
  // draw buffer 3 shows the same in gl_FragCoord.z), which 24 bits round to at most 3 steps apart.
  EXPECT_LE(depth_steps, 3);
  EXPECT_GT(depth_equal, gl.depth.size() * 8 / 10);
  for (int k = 0; k < 4; ++k) {
    const BufferAgreement a = agreement(*ours.framebuffer.draw_buffer(k), *gl.draw_buffer(k));
    std::printf("[ figures  ] attachments.json: draw buffer %d (%s): identical %zu of %zu, largest difference %g\n", k,
                gl_name(gl.color_format[std::size_t(k)]), a.identical, a.pixels, double(a.max_difference));
    switch (k) {
      case 0: EXPECT_EQ(a.identical, a.pixels); break;  // the normal's colour, rounded to 8 bits
      case 1: EXPECT_LE(a.max_difference, 1.0f / 255.0f + 1e-7f); break;  // sRGB encoding (above)
      // n * 333.3: a half's step there is 0.25; the GLSL normalize() on both sides differ in the
      // last float bit for a few pixels, which rounding toward zero can carry to the next half.
      case 2: EXPECT_LE(a.max_difference, 0.25f); EXPECT_GE(a.identical, a.pixels - a.pixels / 500); break;
      case 3: EXPECT_LE(a.max_difference, 2.5e-7f); break;  // gl_FragCoord.z, a few ulps (above)
    }
  }
}

// GL_DEPTH_CLAMP: the near and far planes cut through the patches; clipped in one viewport, kept
// with their window depth clamped to the depth range in the other (the colour's blue channel is
// gl_FragCoord.z).
TEST(DrawsVsLlvmpipe, DepthClampKeepsWhatTheNearAndFarPlanesWouldClip) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "depth_clamp.json");
  const DrawsOutcome clipped = compare_draws(*ctx, "depth_clamp.json", {"draws.1.enable=[\"GL_DEPTH_TEST\"]"});
  EXPECT_GT(o.stats.raster.fragments_shaded, clipped.stats.raster.fragments_shaded + 1000);
  expect_matches(o);
  expect_matches(clipped);
}

// glViewport and glDepthRange per draw: views past the image's edges (clipped at the viewport's
// sides, cut at the image's) and a small one inside it.
TEST(DrawsVsLlvmpipe, ViewportAndDepthRangePerDraw) {
  TESSREF_REQUIRE_GL(ctx);
  const DrawsOutcome o = compare_draws(*ctx, "viewports.json");
  EXPECT_EQ(o.stats.tess.patches_in, 4u);
  EXPECT_GT(o.stats.raster.fragments_shaded, 12000u);
  expect_matches(o);
  // The small view's depth range reversed (glDepthRange(1, 0.5)): its patches then hide the water plane.
  const DrawsOutcome swapped = compare_draws(*ctx, "viewports.json", {"draws.1.depth_range=[1.0, 0.5]"});
  expect_matches(swapped);
}

// A wireframe's lines face as their triangles do (gl_FrontFacing), with either winding in front.
TEST(DrawsVsLlvmpipe, PolygonModeLinesKeepTheirTrianglesFacing) {
  TESSREF_REQUIRE_GL(ctx);
  for (const char* winding : {"GL_CCW", "GL_CW"}) {
    const DrawsOutcome o = compare_draws(*ctx, "two_draws_depth.json",
                                         {"draws.1.polygon_mode=\"GL_LINE\"", "draws.1.shaders.fragment=\"facing.frag\"",
                                          std::string("draws.1.front_face=\"") + winding + "\""});
    EXPECT_GT(o.stats.raster.fragments_shaded, 10000u) << winding;
    expect_matches(o);
  }
}

}  // namespace
}  // namespace tessref::glref
