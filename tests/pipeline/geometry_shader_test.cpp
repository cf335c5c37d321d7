// Geometry shaders on tessref's pipeline (GL 4.5 section 11.3): what they emit is what is drawn,
// strips cut into lists, max_vertices and invocations honoured, and the bytes independent of the
// thread count and the executor's batch size.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "test_util.h"

namespace tessref {
namespace {

const std::string kDraws = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/";

RenderResult render_file(const std::string& file, const std::vector<std::string>& sets = {}, int threads = 2) {
  const Scene scene = load_scene(kDraws + file, sets);
  std::vector<std::string> warnings;
  return render_scene(scene, build_mesh(scene.mesh, warnings), Parallel(threads));
}

// A shader that hands every triangle on as it came draws the bytes the draw gives without it.
TEST(GeometryShader, PassThroughDrawsTheSameBytes) {
  const RenderResult plain = render_file("bicubic_arrays.json");
  const RenderResult through = render_file(
      "bicubic_arrays.json", {"shaders.geometry=\"passthrough.geom\"", "shaders.fragment=\"normal_out_color.frag\""});
  EXPECT_EQ(through.stats.triangles_generated, plain.stats.triangles_generated);
  EXPECT_EQ(plain.stats.triangles_generated, 576u);
  EXPECT_EQ(through.framebuffer.color, plain.framebuffer.color);
  EXPECT_EQ(through.framebuffer.depth, plain.framebuffer.depth);
  // After the vertex stage of an untessellated draw (a triangle strip, then the patches).
  const RenderResult strip = render_file("two_draws_depth.json");
  const RenderResult strip_through = render_file("two_draws_depth.json", {"draws.0.shaders.geometry=\"position_only.geom\""});
  EXPECT_EQ(strip_through.stats.triangles_generated, strip.stats.triangles_generated);
  EXPECT_EQ(strip_through.framebuffer.color, strip.framebuffer.color);
  EXPECT_EQ(strip_through.framebuffer.depth, strip.framebuffer.depth);
}

// Two invocations per triangle, each emitting one vertex past max_vertices = 3: one triangle
// each, so twice the evaluation stage's 64 triangles; a fourth vertex kept would make 256.
TEST(GeometryShader, InvocationsAndMaxVertices) {
  const RenderResult r = render_file("geometry_instanced.json");
  EXPECT_EQ(r.stats.tess.triangles_out, 64u);
  EXPECT_EQ(r.stats.triangles_generated, 128u);
  EXPECT_EQ(r.stats.raster.triangles_in, 128u);
  // The second invocation's colour (green 1) and the first's (green 0) both reach the image.
  std::size_t first = 0, second = 0;
  for (const glm::vec4& c : r.framebuffer.color) {
    first += c.a == 1.0f && c.g == 0.0f && c.r + c.b > 0.0f;
    second += c.a == 1.0f && c.g == 1.0f;
  }
  EXPECT_GT(first, 1000u);
  EXPECT_GT(second, 1000u);
}

// The executor's batch size (lanes per run) and the thread count never show in the bytes.
TEST(GeometryShader, SameBytesForEveryBatchSizeAndThreadCount) {
  for (const char* file : {"geometry_instanced.json", "geometry_hedgehog.json"}) {
    const RenderResult reference = render_file(file, {}, 1);
    for (const int lanes : {1, 7, 64}) {
      const RenderResult r = render_file(file, {"shaders.batch_lanes=" + std::to_string(lanes)}, 8);
      EXPECT_EQ(r.framebuffer.color, reference.framebuffer.color) << file << ", " << lanes << " lanes";
      EXPECT_EQ(r.framebuffer.depth, reference.framebuffer.depth) << file << ", " << lanes << " lanes";
    }
  }
}

// Facet normals over their surface: the surface's 144 triangles, then one line per triangle.
TEST(GeometryShader, LineStripsFromTrianglesOverlayTheSurface) {
  const RenderResult r = render_file("geometry_hedgehog.json");
  EXPECT_EQ(r.stats.tess.triangles_out, 2u * 144u);
  EXPECT_EQ(r.stats.triangles_generated, 144u + 144u);
  // The lines' colours (from yellow at the centroid to red at the tip) are in the image.
  std::size_t line_pixels = 0;
  for (const glm::vec4& c : r.framebuffer.color) line_pixels += c.r == 1.0f && c.g >= 0.3f && c.b >= 0.1f && c.b <= 0.2f;
  EXPECT_GT(line_pixels, 150u);
}

// GL refuses a draw whose primitives are not the geometry shader's input (GL_INVALID_OPERATION).
TEST(GeometryShader, ADrawOfOtherPrimitivesIsRefused) {
  try {
    render_file("bicubic_arrays.json", {"shaders.geometry=\"points_in.geom\"", "shaders.fragment=\"flat_color.frag\""});
    FAIL() << "drawn";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the geometry shader takes points; the draw hands it triangles"), std::string::npos)
        << e.what();
  }
}

// inspect's fragment views tag the evaluation stage's triangles: through a geometry shader they
// would name the wrong ones, so they refuse (exit 2), naming the key.
TEST(GeometryShader, InspectsFragmentViewsRefuseIt) {
  const test::CliRun r = test::run_cli("inspect " + std::string(TESSREF_SOURCE_DIR) + "/scenes/gs_facets.json --pixel 300,500");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--pixel: shaders.geometry: the program has a geometry shader"), std::string::npos) << r.output;
  const test::CliRun d = test::run_cli("inspect " + kDraws + "geometry_hedgehog.json --pixel 100,100");
  EXPECT_EQ(d.exit_code, 2) << d.output;
  EXPECT_NE(d.output.find("--pixel: draws.1.shaders.geometry: the program has a geometry shader"), std::string::npos) << d.output;
}

}  // namespace
}  // namespace tessref
