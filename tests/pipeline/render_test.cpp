// The draw call and image output: determinism across thread counts and batch sizes, the golden
// image of the default scene, what the depth and normal images hold.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "mesh/camera.h"
#include "io/image_compare.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "mesh/procedural.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "stages/tess_stage.h"
#include "test_util.h"

namespace tessref {
namespace {

using test::TempDir;

RenderResult render(const Scene& scene, int threads, std::size_t batch_triangles = 65536) {
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  DrawOptions options;
  options.batch_triangles = batch_triangles;
  return render_scene(scene, mesh, Parallel(threads), options);
}

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

TEST(Render, DefaultScenePngIsIdenticalForAnyThreadCount) {
  TempDir dir;
  const Scene scene = load_scene("");
  std::string first;
  for (int threads : {1, 2, 8}) {
    const auto path = dir.path() / ("default_" + std::to_string(threads) + ".png");
    write_color_image(render(scene, threads).framebuffer, path);
    const std::string bytes = test::read_file(path);
    ASSERT_GT(bytes.size(), 1000u);
    if (first.empty()) first = bytes;
    EXPECT_EQ(fnv1a(bytes), fnv1a(first)) << threads << " threads";
    EXPECT_TRUE(bytes == first) << threads << " threads";
  }
}

TEST(Render, TessellatedPngIsIdenticalForAnyThreadCount) {
  TempDir dir;
  const Scene scene = load_scene("", {"tessellation.enabled=true", "image.width=256", "image.height=256"});
  std::string first;
  for (int threads : {1, 2, 8}) {
    const auto path = dir.path() / ("pn_" + std::to_string(threads) + ".png");
    const RenderResult r = render(scene, threads);
    EXPECT_GT(r.stats.triangles_generated, 256u * 100u) << "PN at level 12 should refine the torus";
    write_color_image(r.framebuffer, path);
    const std::string bytes = test::read_file(path);
    if (first.empty()) first = bytes;
    EXPECT_TRUE(bytes == first) << threads << " threads";
  }
}

TEST(Render, BatchSizeDoesNotChangeTheImage) {
  const Scene scene = load_scene("", {"image.width=256", "image.height=256", "mesh.type=icosphere",
                                      "mesh.icosphere.refinements=3", "tessellation.enabled=false"});
  const RenderResult whole = render(scene, 2);
  const RenderResult pieces = render(scene, 2, 7);  // 1280 triangles in 183 batches
  EXPECT_EQ(whole.stats.triangles_in, 1280u);
  EXPECT_EQ(pieces.stats.triangles_generated, 1280u);
  EXPECT_EQ(whole.stats.raster.fragments_shaded, pieces.stats.raster.fragments_shaded);
  EXPECT_TRUE(to_rgb8(whole.framebuffer).pixels == to_rgb8(pieces.framebuffer).pixels);
  EXPECT_TRUE(whole.framebuffer.depth == pieces.framebuffer.depth);
}

// Small chunks: with several threads each chunk is tessellated while the one before it is drawn
// (tessellate_chunks' overlap); the image is the one-chunk, one-thread image.
TEST(Render, OverlappedChunksGiveTheSerialImage) {
  const Scene scene = load_scene("", {"image.width=256", "image.height=256"});
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  const RenderResult serial = render_scene(scene, mesh, Parallel(1), DrawOptions{});
  for (int threads : {2, 8}) {
    DrawOptions options;
    options.tess_chunk_patches = 7;  // 37 chunks of the 256 patches
    const RenderResult r = render_scene(scene, mesh, Parallel(threads), options);
    EXPECT_EQ(r.stats.triangles_generated, serial.stats.triangles_generated);
    EXPECT_EQ(r.stats.raster.fragments_shaded, serial.stats.raster.fragments_shaded);
    EXPECT_TRUE(r.framebuffer.color == serial.framebuffer.color) << threads << " threads";
    EXPECT_TRUE(r.framebuffer.depth == serial.framebuffer.depth) << threads << " threads";
    EXPECT_TRUE(r.framebuffer.aux == serial.framebuffer.aux) << threads << " threads";
  }
}

// Without the normals target (`tessref render` without --normals) the colour and depth are the
// same, in a framebuffer reused with and without it.
TEST(Render, TheNormalsTargetIsDroppedWhenNotAskedFor) {
  const Scene scene = load_scene("", {"image.width=256", "image.height=256"});
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  const Parallel parallel(2);
  Framebuffer with, fb;
  render_scene(scene, mesh, parallel, with, DrawOptions{});
  ASSERT_EQ(with.aux.size(), 256u * 256u);
  EXPECT_TRUE(std::any_of(with.aux.begin(), with.aux.end(), [](const glm::vec4& n) { return n != glm::vec4(0.0f); }));
  for (bool normals : {false, true, false}) {
    DrawOptions options;
    options.normals = normals;
    render_scene(scene, mesh, parallel, fb, options);
    EXPECT_TRUE(fb.color == with.color) << normals;
    EXPECT_TRUE(fb.depth == with.depth) << normals;
    if (normals) EXPECT_TRUE(fb.aux == with.aux);
    else EXPECT_TRUE(fb.aux.empty());
    EXPECT_EQ(fb.draw_buffers(), normals ? 2 : 1);
  }
}

// A frame drawn into a framebuffer of the same size defers its clear to the tiles the draw
// scans (Framebuffer::reset): the image must be a fresh framebuffer's, also where the earlier
// frame drew and this one does not, for the C++ programs and a GLSL program, on 1 and 2 threads.
TEST(Render, ADeferredClearGivesAFreshFramebuffersImage) {
  // 200 x 136: tiles cut by the right and top edges. The first frame fills the view; the second
  // draws a small torus on another background, so most tiles are cleared by finish_clear.
  const std::vector<std::string> size = {"image.width=200", "image.height=136"};
  std::vector<std::string> big = size, small = size;
  big.push_back("transform.scale=3");
  small.push_back("transform.scale=0.4");
  small.push_back("background=[0.5, 0.1, 0.7, 1.0]");
  for (const std::vector<std::string>& program : {std::vector<std::string>{}, std::vector<std::string>{"shaders.program=twins"}}) {
    std::vector<std::string> a = big, b = small;
    a.insert(a.end(), program.begin(), program.end());
    b.insert(b.end(), program.begin(), program.end());
    const Scene first = load_scene("", a), second = load_scene("", b);
    std::vector<std::string> warnings;
    const Mesh mesh = build_mesh(first.mesh, warnings);
    for (int threads : {1, 2}) {
      const Parallel parallel(threads);
      Framebuffer fresh, reused;
      render_scene(second, mesh, parallel, fresh, DrawOptions{});
      render_scene(first, mesh, parallel, reused, DrawOptions{});
      ASSERT_FALSE(reused.color == fresh.color);
      render_scene(second, mesh, parallel, reused, DrawOptions{});
      EXPECT_TRUE(reused.color == fresh.color) << threads << " threads, " << program.size() << " GLSL";
      EXPECT_TRUE(reused.depth == fresh.depth) << threads << " threads, " << program.size() << " GLSL";
      EXPECT_TRUE(reused.aux == fresh.aux) << threads << " threads, " << program.size() << " GLSL";
      EXPECT_FALSE(reused.clear_pending());
    }
  }
}

TEST(Render, StatsOfTheDefaultScene) {
  const RenderResult r = render(load_scene(""), 2);
  EXPECT_EQ(r.stats.triangles_in, 256u);  // the 16 x 8 torus
  EXPECT_EQ(r.stats.vertices_shaded, 128u);
  // PN at level 12, fractional_odd: 253 triangles per patch (`tessref tpg --spacing
  // fractional_odd --outer 12,12,12 --inner 12`), none discarded.
  EXPECT_EQ(r.stats.tess.patches_in, 256u);
  EXPECT_EQ(r.stats.tess.patches_discarded, 0u);
  EXPECT_EQ(r.stats.triangles_generated, 256u * 253u);
  // Back faces culled: about half the torus faces the camera.
  EXPECT_GT(r.stats.raster.triangles_rasterized, 256u * 253u * 4 / 10);
  EXPECT_LT(r.stats.raster.triangles_rasterized, 256u * 253u * 6 / 10);
  // Every covered pixel shaded exactly once (closed mesh, culled back faces, front faces of a
  // torus seen from outside may overlap only at the inner rim).
  std::size_t covered = 0;
  for (float d : r.framebuffer.depth) covered += d < 1.0f;
  EXPECT_GE(r.stats.raster.fragments_shaded, covered);
  EXPECT_GT(covered, 200000u);
}

TEST(Render, UprightImageAndFigure14Colors) {
  // A sphere pushed to the top of the image: the top rows of the file hold it.
  const Scene scene = load_scene("", {"image.width=64", "image.height=64", "mesh.type=icosphere",
                                      "mesh.icosphere.refinements=3", "mesh.icosphere.radius=0.5",
                                      "transform.translate=0,1.2,0", "transform.rotate_deg=0,0,0"});
  const RenderResult r = render(scene, 1);
  const Rgb8Image img = to_rgb8(r.framebuffer);
  auto covered_rows = [&](int y0, int y1) {
    int n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < 64; ++x) n += img.pixels[3 * (y * 64 + x) + 1] != 51;  // background 0.2
    return n;
  };
  EXPECT_GT(covered_rows(0, 32), 100);
  EXPECT_EQ(covered_rows(32, 64), 0);
  // The lit surface: red well above blue (color 0.988, 0, 0.427) and green 0 but for the white
  // specular term.
  int brightest = 0;
  for (std::size_t p = 0; p < img.pixels.size(); p += 3) {
    if (img.pixels[p + 1] == 51 && img.pixels[p] == 51) continue;
    EXPECT_GT(img.pixels[p], img.pixels[p + 2]);
    brightest = std::max<int>(brightest, img.pixels[p]);
  }
  EXPECT_GT(brightest, 200);
}

TEST(Render, DepthAndNormalImages) {
  TempDir dir;
  const Scene scene = load_scene("", {"image.width=96", "image.height=64"});
  const RenderResult r = render(scene, 2);
  write_depth_image(r.framebuffer, dir.path() / "depth.exr");
  write_normals_image(r.framebuffer, dir.path() / "normals.exr");
  const FloatImage depth = read_float_image(dir.path() / "depth.exr");
  const FloatImage normals = read_float_image(dir.path() / "normals.exr");
  ASSERT_EQ(depth.width, 96);
  ASSERT_EQ(depth.height, 64);
  ASSERT_EQ(depth.channels, 1);
  ASSERT_EQ(normals.channels, 3);
  int covered = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 96; ++x) {
      // File row y is framebuffer row 63 - y.
      const std::size_t fb = r.framebuffer.index(x, 63 - y), file = std::size_t(y) * 96 + x;
      EXPECT_EQ(depth.pixels[file], r.framebuffer.depth[fb]);
      if (depth.pixels[file] < 1.0f) {
        ++covered;
        const glm::vec3 n(normals.pixels[3 * file], normals.pixels[3 * file + 1], normals.pixels[3 * file + 2]);
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
      }
    }
  }
  EXPECT_GT(covered, 500);
}

TEST(Render, NormalsShading) {
  const Scene scene = load_scene("", {"image.width=64", "image.height=64", "shading=normals"});
  const RenderResult r = render(scene, 2);
  for (std::size_t i = 0; i < r.framebuffer.color.size(); ++i) {
    if (r.framebuffer.depth[i] == 1.0f) continue;
    const glm::vec3 n = glm::vec3(r.framebuffer.aux[i]);
    const glm::vec3 c = glm::vec3(r.framebuffer.color[i]);
    EXPECT_NEAR(glm::distance(c, n * 0.5f + 0.5f), 0.0f, 1e-6f);
  }
}

// Writes the interpolated world position (color) and world normal (aux) as they arrive.
struct VaryingsProbe final : FragmentProgram {
  FragmentOutput shade(const FragmentInput& in) const override {
    const float* v = in.varyings;
    FragmentOutput out;
    out.color = glm::vec4(v[kVaryingPosition], v[kVaryingPosition + 1], v[kVaryingPosition + 2], 1.0f);
    out.aux = glm::vec4(v[kVaryingNormal], v[kVaryingNormal + 1], v[kVaryingNormal + 2], 1.0f);
    return out;
  }
};

// End to end through the vertex shader and the rasterizer: on an icosphere every vertex normal
// is its position / radius, so the interpolated normal must point along the interpolated
// position, and that position must lie on the pixel's ray (perspective-correct interpolation).
TEST(Render, VaryingsAreInterpolatedConsistently) {
  const Scene scene = load_scene("", {"image.width=128", "image.height=96", "mesh.type=icosphere",
                                      "mesh.icosphere.refinements=1", "mesh.icosphere.radius=100",
                                      "transform.scale=0.01", "transform.rotate_deg=10,20,30",
                                      "tessellation.enabled=false"});
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  const glm::mat4 view_projection =
      projection_matrix(scene.camera, scene.width, scene.height) * view_matrix(scene.camera);
  const auto vs = programs::TransformVertexShader::from(model_matrix(scene.transform), view_projection);
  Framebuffer fb(scene.width, scene.height, glm::vec4(0.0f));
  const VaryingsProbe probe;
  RasterState state;
  state.cull_back_faces = true;
  const DrawStats stats = draw_mesh(mesh, vs, scene.tessellation, state, probe, fb, Parallel(2));
  ASSERT_GT(stats.raster.fragments_shaded, 1000u);

  const glm::dmat4 inverse_vp = glm::inverse(glm::dmat4(view_projection));
  int checked = 0;
  for (int y = 0; y < fb.height; ++y) {
    for (int x = 0; x < fb.width; ++x) {
      const std::size_t i = fb.index(x, y);
      if (fb.depth[i] == 1.0f) continue;
      const glm::vec3 position(fb.color[i]), normal(fb.aux[i]);
      ASSERT_GT(glm::dot(glm::normalize(position), glm::normalize(normal)), 0.99999f)
          << "pixel " << x << ", " << y;
      // Unproject the pixel center at its depth: it must land on the interpolated position.
      const glm::dvec4 ndc(2.0 * (x + 0.5) / fb.width - 1.0, 2.0 * (y + 0.5) / fb.height - 1.0,
                           2.0 * double(fb.depth[i]) - 1.0, 1.0);
      const glm::dvec4 world = inverse_vp * ndc;
      ASSERT_LT(glm::distance(glm::dvec3(world) / world.w, glm::dvec3(position)), 1e-3)
          << "pixel " << x << ", " << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

// ---- Golden image ------------------------------------------------------------------------------
// tests/golden/default.png is the default scene as rendered when it was last accepted. Regenerate
// it after an intended change with:
//   build/cli/tessref render -o tests/golden/default.png
// Tolerance: a pixel is off when a channel differs by more than 3 (of 255); at most 0.1% of the
// pixels may be off (coverage flips along silhouettes). On failure a difference image (|a - b| x 16)
// is written beside the build.
TEST(Golden, DefaultScene) {
  const std::string golden_path = std::string(TESSREF_SOURCE_DIR) + "/tests/golden/default.png";
  if (!std::filesystem::exists(golden_path)) GTEST_SKIP() << golden_path << " missing";
  const Rgb8Image golden = read_rgb8_image(golden_path);
  const Scene scene = load_scene("");
  const Rgb8Image image = to_rgb8(render(scene, 0).framebuffer);
  ASSERT_EQ(image.width, golden.width) << "regenerate: build/cli/tessref render -o tests/golden/default.png";
  ASSERT_EQ(image.height, golden.height);
  const ImageComparison c = compare_images(golden, image, scene.background, 3, true);
  const std::size_t off = c.pixels - c.within_tolerance;
  if (off * 1000 > c.pixels) {
    const std::string diff_path = std::string(TESSREF_BINARY_DIR) + "/golden_default_diff.png";
    write_rgb8_image(c.diff, diff_path);
    write_rgb8_image(image, std::string(TESSREF_BINARY_DIR) + "/golden_default_actual.png");
    ADD_FAILURE() << c.summary() << "; difference image: " << diff_path
                  << "; if the change is intended: build/cli/tessref render -o tests/golden/default.png";
  }
  RecordProperty("pixels_off", int(off));
  RecordProperty("max_diff", c.max_difference);
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

// A NaN inner level clamps to the lower bound (docs/tpg.md), in a scene as in a control shader:
// the frame is that of inner level 1.
// camera.fit: a mesh seen from far away along any direction fills the frame, with no pixel on the
// border covered.
TEST(Render, CameraFitFramesTheMesh) {
  for (const char* eye : {"0,0,1000", "300,-200,5", "0.01,0.02,-0.01"}) {
    SCOPED_TRACE(eye);
    const Scene scene = parse_scene("{}", "x", ".", {"camera.fit=true", std::string("camera.eye=") + eye,
                                                     "image.width=96", "image.height=64"});
    std::vector<std::string> warnings;
    const Mesh mesh = build_mesh(scene.mesh, warnings);
    Scene fitted = scene;
    fitted.camera = fitted_camera(scene, mesh);
    const RenderResult r = render_scene(fitted, mesh, Parallel(2));
    int lo_x = 96, hi_x = -1, lo_y = 64, hi_y = -1;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 96; ++x)
        if (r.framebuffer.depth[r.framebuffer.index(x, y)] < 1.0f)
          lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
    EXPECT_GT(lo_x, 0);
    EXPECT_GT(lo_y, 0);
    EXPECT_LT(hi_x, 95);
    EXPECT_LT(hi_y, 63);
    EXPECT_GE(std::max(hi_x - lo_x, hi_y - lo_y), 40) << "the mesh should fill most of the 64-pixel side";
  }
  // Off: the camera as given.
  const Scene plain = load_scene("");
  std::vector<std::string> warnings;
  EXPECT_EQ(fitted_camera(plain, build_mesh(plain.mesh, warnings)).eye, plain.camera.eye);
}

TEST(Render, NanInnerLevelDrawsAsTheLowerBound) {
  auto render_with = [](const std::string& inner) {
    const Scene scene = load_scene("", {"image.width=64", "image.height=64", "tessellation.inner=" + inner});
    std::vector<std::string> warnings;
    const RenderResult r = render_scene(scene, build_mesh(scene.mesh, warnings), Parallel(2));
    return std::pair{r.framebuffer.color, r.stats.tess.domain_points};
  };
  const auto nan = render_with("nan");
  const auto one = render_with("1");
  EXPECT_EQ(nan.second, one.second);
  EXPECT_GT(nan.second, 0u);
  EXPECT_TRUE(nan.first == one.first);
}

// fuzz_pipeline's case: a triangle with coordinates near 1e37 through adaptive flat tessellation
// and the clipper, whose float rounding put a window coordinate at 4.4e30 (undefined behaviour
// when snapped; fixed_point_test.cpp has the rule). The draw must end with a defined image.
TEST(Render, HugeCoordinatesThroughTheClipperAreDefined) {
  const Scene scene = load_scene(
      "", {"camera.eye=0,0,6", "camera.target=0,0,0", "camera.fov_y_deg=45", "camera.near=0.5",
           "camera.far=20", "transform.rotate_deg=0,0,0", "image.width=21", "image.height=30",
           "tessellation.enabled=true", "tessellation.scheme=flat", "tessellation.spacing=fractional_odd",
           "tessellation.winding=cw", "tessellation.inner=5.92376428e+22,-3.8424966e-38",
           "tessellation.outer=2,40.84375,14.34375,5.78125", "tessellation.adaptive.enabled=true",
           "tessellation.adaptive.pixels_per_segment=1", "shading=normals"});
  Mesh mesh;
  mesh.positions = {{0x1.8bce7ep+117f, 0x1p-2f, 0x1.5155aap-34f},
                    {-0x1.a8p+0f, -0x1.c8p+0f, 0x1.7p+0f},
                    {-0x1.e85ddap+123f, -0x1.ep-1f, -0x1.28p+0f}};
  mesh.normals = {{-0x1.8p-4f, -0x1.d8p+0f, -0x1.58p+1f},
                  {-0x1.6cp+1f, -0x1.7ea028p+61f, 0x1.34p+1f},
                  {-0x1.4p+1f, 0x1.5f86cap-23f, -0x1.cp-1f}};
  mesh.indices = {0, 1, 2};
  validate_mesh(mesh, "huge");
  const RenderResult r = render_scene(scene, mesh, Parallel(1));
  for (float z : r.framebuffer.depth) EXPECT_TRUE(z >= 0.0f && z <= 1.0f);
}

}  // namespace
}  // namespace tessref
