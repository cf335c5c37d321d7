// Embree 3 as an oracle on the default scene's actual screen-space triangles: the clip-space
// triangles the draw call hands to the rasterizer (the torus through the vertex shader, and the
// same torus PN-tessellated at the scene's levels) are rebuilt here with the scene's programs,
// shown to be those draw_mesh rasterizes (same depth buffer, bit for bit), and checked against
// Embree as tests/raster/embree_oracle_test.cpp does: coverage at every pixel center farther than
// 1e-4 pixel from an edge, depth within 1e-5 relative.
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../raster/embree_oracle.h"
#include "mesh/camera.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "stages/programs/transform.h"
#include "stages/schemes/pn_triangles.h"
#include "stages/tess_stage.h"

namespace tessref {
namespace {

// What draw_mesh hands to draw_triangles for this scene, concatenated (chunks drawn in order equal
// one draw of their concatenation). Positions are all the rasterizer needs here.
TriangleBatch screen_triangles(const Scene& scene, const Mesh& mesh) {
  const glm::mat4 view_projection =
      projection_matrix(scene.camera, scene.width, scene.height) * view_matrix(scene.camera);
  const auto vs =
      programs::TransformVertexShader::from(model_matrix(scene.transform), view_projection);
  std::vector<programs::VertexOut> shaded(mesh.vertex_count());
  for (std::size_t v = 0; v < shaded.size(); ++v)
    shaded[v] = vs.main(mesh.positions[v], mesh.normals[v]);

  TriangleBatch out;
  if (!scene.tessellation.enabled) {
    for (std::uint32_t index : mesh.indices) {
      ClipVertex v;
      v.position = shaded[index].gl_Position;
      out.vertices.push_back(v);
    }
    return out;
  }
  // The PN path of render/draw.cpp with constant levels.
  const TessellationSettings& settings = scene.tessellation;
  EXPECT_EQ(settings.scheme, SurfaceScheme::PN);
  EXPECT_FALSE(settings.adaptive.enabled);
  std::vector<StageVertex> control_points(shaded.size());
  for (std::size_t v = 0; v < shaded.size(); ++v) {
    control_points[v].attr[kAttrPosition] = glm::vec4(shaded[v].v_world_position, 1.0f);
    control_points[v].attr[kAttrNormal] = glm::vec4(shaded[v].v_world_normal, 0.0f);
  }
  PnTcs tcs;
  PnTes tes;
  EXPECT_TRUE(parse(to_string(settings.normal_mode), tcs.normal_mode));
  tcs.levels.constant = settings.levels;
  tes.normal_mode = tcs.normal_mode;
  tes.spacing = settings.spacing;
  tes.winding = settings.winding;
  tes.view_proj = vs.u_view_projection;
  tessellate_chunks(TessDrawInput{control_points, mesh.indices, 3}, 256, tcs, tes, {}, Parallel(2),
                    [&](const TriangleBatch& b) {
                      append_triangles(out, b);
                    });
  return out;
}

void check_scene(const Scene& scene, std::size_t expected_triangles) {
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  const TriangleBatch batch = screen_triangles(scene, mesh);
  ASSERT_EQ(batch.triangle_count(), expected_triangles);

  // The rebuilt triangles are the ones the draw call rasterizes: identical depth buffers.
  const RenderResult rendered = render_scene(scene, mesh, Parallel(2));
  EXPECT_EQ(rendered.stats.triangles_generated, expected_triangles);
  Framebuffer fb(scene.width, scene.height);
  test::CountingProgram counter(scene.width, scene.height);
  RasterState state;
  state.cull_back_faces = scene.cull_back_faces;
  draw_triangles(batch, state, counter, fb, Parallel(2));
  ASSERT_EQ(fb.depth.size(), rendered.framebuffer.depth.size());
  EXPECT_EQ(std::memcmp(fb.depth.data(), rendered.framebuffer.depth.data(),
                        fb.depth.size() * sizeof(float)),
            0);

  const test::OracleResult r =
      test::compare_with_embree(batch, scene.width, scene.height, scene.cull_back_faces);
  EXPECT_EQ(r.coverage_mismatches, 0);
  EXPECT_EQ(r.depth_mismatches, 0);
  EXPECT_GT(r.compared, scene.width * scene.height * 9 / 10);
  EXPECT_GT(r.covered, scene.width * scene.height / 4);  // the torus fills about 37% of the image
  std::printf("[ embree ] %d pixels compared (%d covered), %d near an edge left out; worst relative "
              "depth %.3g vs the exact plane, %.3g vs Embree's t\n",
              r.compared, r.covered, r.excluded, r.worst_vs_exact, r.worst_vs_ray);
  ::testing::Test::RecordProperty("compared", r.compared);
  ::testing::Test::RecordProperty("covered", r.covered);
  ::testing::Test::RecordProperty("excluded", r.excluded);
}

TEST(EmbreeDefaultScene, TorusThroughTheVertexShader) {
  const Scene scene = load_scene("", {"tessellation.enabled=false"});
  check_scene(scene, 16 * 8 * 2);  // major x minor segments, two triangles each
}

TEST(EmbreeDefaultScene, PnTessellatedTorus) {
  const Scene scene = load_scene("");
  ASSERT_TRUE(scene.tessellation.enabled);  // the default scene is the PN torus
  // fractional_odd, all levels 12: 253 triangles per patch (the count tessref's generator, matched
  // to llvmpipe's, emits; render_scene must hand over the same number).
  check_scene(scene, 16 * 8 * 2 * 253);
}

}  // namespace
}  // namespace tessref
