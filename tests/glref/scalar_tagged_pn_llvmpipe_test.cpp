// Scalar Tagged PN drawn by the GL driver (llvmpipe) through its GLSL twins (tagged_transform.vert,
// scalar_tagged_pn.tesc, pn_triangles.tese) against tessref's C++ programs, on scenes/tagged_pn.json
// (two creases, one biased, two rings of tension): 8-bit images within 2/255 on every pixel and the
// same coverage, in every normal mode.
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "glref/scene_renderer.h"
#include "io/image_compare.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace tessref::glref {
namespace {

TEST(ScalarTaggedPnVsLlvmpipe, TwinsMatchTessref) {
  TESSREF_REQUIRE_GL(ctx);
  const std::string scene_file = std::string(TESSREF_SOURCE_DIR) + "/scenes/tagged_pn.json";
  for (const char* mode : {"linear", "quadratic", "quadratic_corrected", "analytic"}) {
    const Scene scene = load_scene(scene_file, {std::string("tessellation.normal_mode=") + mode, "image.width=512",
                                                "image.height=512"});
    std::vector<std::string> warnings;
    const Mesh mesh = build_mesh(scene.mesh, warnings);
    const RenderResult ours = render_scene(scene, mesh, Parallel());
    SceneRenderer renderer(*ctx, scene, mesh);
    const Framebuffer gl = renderer.render();
    const ImageComparison c = compare_framebuffers(ours.framebuffer, gl, 2, true);
    std::printf("[ figures  ] tagged_pn %s: %s\n", mode, c.summary().c_str());
    if (c.within_tolerance != c.pixels || c.coverage_mismatch != 0) {
      const std::string base = std::string(TESSREF_BINARY_DIR) + "/scalar_tagged_pn_llvmpipe_" + mode;
      write_rgb8_image(c.diff, base + "_diff.png");
      write_color_image(ours.framebuffer, base + "_tessref.png");
      write_color_image(gl, base + "_gl.png");
    }
    EXPECT_EQ(c.within_tolerance, c.pixels) << mode << ": " << c.summary();
    EXPECT_EQ(c.coverage_mismatch, 0u) << mode << ": " << c.summary();
    EXPECT_GT(ours.stats.raster.fragments_shaded, 50000u) << mode;
  }
}

}  // namespace
}  // namespace tessref::glref
