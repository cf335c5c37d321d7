// tessref's rasterizer against Mesa llvmpipe, live: the same triangles (clip positions with w = 1,
// so window coordinates are exactly the ones chosen) drawn by llvmpipe into an FBO and by
// draw_triangles must cover the identical set of triangles at every pixel, and agree on window
// depth within kDepthTolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <utility>

#include "gl_fixture.h"
#include "probe_programs.h"
#include "glref/raster_probe.h"
#include "raster/rasterizer.h"

namespace tessref {
namespace {

using Mask = std::array<std::uint64_t, 3>;

// Window depth: both fit the depth plane through the same unsnapped float window positions, but
// llvmpipe sets it up in float and steps it across the triangle while tessref evaluates it in
// double and rounds once, so the two differ by float rounding of the plane terms: each a few ulps
// of the largest term (|z| <= 1, and the slope times the distance from the plane origin, <= 1
// here), ulp(1) = 2^-23. Measured up to 6.3e-7 (RecordProperty "max_depth_diff"; 9.5e-5 when
// tessref still fitted the plane through the snapped positions); the bound leaves room for that
// and stays far below the gap between the depth bands of different triangles (> 1e-3), so it
// cannot hide a wrong triangle.
constexpr float kDepthTolerance = 8.0f / (1 << 23);  // 9.5e-7

using test::clip_from_window;
using test::MaskProgram;

struct TessrefDraw {
  std::vector<Mask> mask;
  Framebuffer fb;  // color: (id, gl_FragCoord.xyz) of the last fragment, -1 where none
};

TessrefDraw tessref_draw(const std::vector<glm::vec4>& clip, int w, int h) {
  TriangleBatch b;
  b.num_varyings = 1;
  for (std::size_t i = 0; i < clip.size(); ++i) {
    ClipVertex v;
    v.position = clip[i];
    v.varyings[0] = float(i / 3);
    b.vertices.push_back(v);
  }
  TessrefDraw r;
  r.fb = Framebuffer(w, h, glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f));
  MaskProgram prog(w, h);
  draw_triangles(b, RasterState{}, prog, r.fb, Parallel(2));
  r.mask.resize(std::size_t(w) * h);
  for (std::size_t i = 0; i < r.mask.size(); ++i)
    for (int k = 0; k < 3; ++k) r.mask[i][k] = prog.mask[3 * i + k].load();
  return r;
}

// Triangles in window coordinates; depth is assigned per triangle by with_depth_bands.
using Scene = std::vector<glm::vec2>;

// Triangle i gets window depths in its own band, nearer for later triangles, bands 1/(2n) apart:
// with depth test LESS every fragment passes, so both renderers keep the last triangle per pixel
// and the comparison sees raw coverage plus the depth plane. Depths are multiples of 2^-16.
std::vector<glm::vec3> with_depth_bands(const Scene& s, std::mt19937& rng) {
  const std::size_t n = s.size() / 3;
  std::uniform_int_distribution<int> in_band(0, 1 << 14);
  std::vector<glm::vec3> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::size_t t = i / 3;
    const double band = 0.95 - 0.9 * double(t + 1) / double(n + 1);  // band start
    const double width = 0.45 / double(n + 1);
    const double z = band + width * in_band(rng) / double(1 << 14);
    out.push_back({s[i], float(std::round(z * 65536.0) / 65536.0)});
  }
  return out;
}

struct Totals {
  std::uint64_t scenes = 0, triangles = 0, pixels = 0, covered = 0, differing = 0;
  std::uint64_t differing_clipped = 0;  // differing only in triangles llvmpipe clips
  std::uint64_t depth_compared = 0, depth_over = 0;
  float max_depth_diff = 0.0f, max_clipped_depth_diff = 0.0f;
  std::string first_differences;
  void report(const char* name) const {
    std::printf(
        "[ %s ] %llu scenes, %llu triangles: %llu pixels compared (%llu covered), %llu differing; "
        "%llu differing in clipped triangles only; depth at %llu pixels, max |diff| %.3g "
        "(%llu over tolerance), %.3g where the triangle is clipped\n",
        name, (unsigned long long)scenes, (unsigned long long)triangles,
        (unsigned long long)pixels, (unsigned long long)covered, (unsigned long long)differing,
        (unsigned long long)differing_clipped,
        (unsigned long long)depth_compared, double(max_depth_diff),
        (unsigned long long)depth_over, double(max_clipped_depth_diff));
    ::testing::Test::RecordProperty("pixels_compared", std::to_string(pixels));
    ::testing::Test::RecordProperty("pixels_differing", std::to_string(differing));
    ::testing::Test::RecordProperty("pixels_differing_clipped", std::to_string(differing_clipped));
    ::testing::Test::RecordProperty("max_depth_diff", std::to_string(max_depth_diff));
  }
};

std::string mask_string(const Mask& m) {
  std::string s = "{";
  for (int id = 0; id < glref::kProbeMaxTriangles; ++id)
    if (m[id / 64] >> (id % 64) & 1) {
      if (s.size() > 1) s += ' ';
      s += std::to_string(id);
    }
  return s + "}";
}

// A vertex outside the view volume's x or y planes: llvmpipe's draw module clips such a triangle
// at the viewport sides (no guard band), and so does tessref (raster/clip.cpp).
bool llvmpipe_clips(const glm::vec3* v, int w, int h) {
  for (int k = 0; k < 3; ++k)
    if (v[k].x < 0.0f || v[k].x > float(w) || v[k].y < 0.0f || v[k].y > float(h)) return true;
  return false;
}

// Draws one scene (clip positions) both ways and adds the comparison to totals. clipped[t]:
// whether llvmpipe clips triangle t.
void compare_clip(glref::CoverageProber& prober, int w, int h, const std::vector<glm::vec4>& clip,
                  const std::vector<bool>& clipped, Totals& totals) {
  const glref::CoverageProbe gl = prober.draw(clip);
  const TessrefDraw ours = tessref_draw(clip, w, h);
  ++totals.scenes;
  totals.triangles += clip.size() / 3;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      ++totals.pixels;
      const bool any = gl.mask[i] != Mask{0, 0, 0};
      totals.covered += any;
      if (gl.mask[i] != ours.mask[i]) {
        bool clipped_only = true;
        for (int id = 0; id < glref::kProbeMaxTriangles; ++id)
          if ((gl.mask[i][id / 64] ^ ours.mask[i][id / 64]) >> (id % 64) & 1)
            clipped_only &= bool(clipped[std::size_t(id)]);
        if (clipped_only) {
          ++totals.differing_clipped;
          continue;
        }
        if (++totals.differing <= 10) {
          char buf[160];
          std::snprintf(buf, sizeof buf, "  pixel (%d, %d): llvmpipe %s, tessref ", x, y,
                        mask_string(gl.mask[i]).c_str());
          totals.first_differences += buf + mask_string(ours.mask[i]) + "\n";
        }
        continue;
      }
      if (!any) continue;
      // Same triangles; the last one wrote both: its depth.
      EXPECT_EQ(gl.last[i], int(ours.fb.color[i].x)) << x << "," << y;
      EXPECT_EQ(gl.frag_coord[i].x, ours.fb.color[i].y);
      EXPECT_EQ(gl.frag_coord[i].y, ours.fb.color[i].z);
      EXPECT_EQ(gl.depth[i], gl.frag_coord[i].z);  // the depth buffer holds gl_FragCoord.z
      const float d = std::abs(gl.frag_coord[i].z - ours.fb.color[i].w);
      EXPECT_EQ(ours.fb.depth[i], ours.fb.color[i].w);
      ++totals.depth_compared;
      const bool cut = clipped[std::size_t(gl.last[i])];
      float& max_diff = cut ? totals.max_clipped_depth_diff : totals.max_depth_diff;
      max_diff = std::max(max_diff, d);
      totals.depth_over += d > kDepthTolerance;
    }
}

// The same for a scene in window coordinates.
void compare(glref::CoverageProber& prober, int w, int h, const std::vector<glm::vec3>& window,
             Totals& totals) {
  std::vector<glm::vec4> clip;
  std::vector<bool> clipped;
  for (const glm::vec3& p : window) clip.push_back(clip_from_window(p, w, h));
  for (std::size_t t = 0; t < window.size() / 3; ++t)
    clipped.push_back(llvmpipe_clips(&window[3 * t], w, h));
  compare_clip(prober, w, h, clip, clipped, totals);
}

void expect_identical(const Totals& t, const char* name) {
  t.report(name);
  EXPECT_EQ(t.differing, 0u) << "first differences:\n" << t.first_differences;
  EXPECT_EQ(t.differing_clipped, 0u);
  EXPECT_EQ(t.depth_over, 0u) << "max depth difference " << t.max_depth_diff;
  EXPECT_GT(t.covered, t.pixels / 20);  // the scenes are not empty
}

// ---- Coordinates ------------------------------------------------------------------------------

constexpr int kW = 128, kH = 128;

// A window coordinate on the 1/256 grid near v: often exactly on a pixel center (.5) or a pixel
// corner (integer), where the fill rule and the snapping decide.
float grid_coord(float v, std::mt19937& rng) {
  switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
    case 0:
    case 1: return std::floor(v) + 0.5f;
    case 2: return std::round(v);
    default: return std::round(v * 256.0f) / 256.0f;
  }
}

glm::vec2 grid_point(glm::vec2 p, std::mt19937& rng) {
  return {grid_coord(p.x, rng), grid_coord(p.y, rng)};
}

glm::vec2 clamp_to(glm::vec2 p, float margin) {
  return glm::clamp(p, glm::vec2(-margin), glm::vec2(kW + margin, kH + margin));
}

// Random triangles, sizes from sub-pixel to larger than the target, vertices within `margin`
// pixels of the target, both windings, many axis-aligned edges.
Scene random_triangles(std::mt19937& rng, int count, float margin) {
  std::uniform_real_distribution<float> pos(-16.0f, kW + 16.0f), unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> size_class(0, 3), pick(0, 9);
  const float sizes[] = {1.5f, 6.0f, 25.0f, 90.0f};
  Scene s;
  while (int(s.size()) < 3 * count) {
    const glm::vec2 c(pos(rng), pos(rng));
    const float r = sizes[size_class(rng)];
    glm::vec2 v[3];
    for (glm::vec2& p : v)
      p = clamp_to(grid_point(c + r * glm::vec2(unit(rng), unit(rng)), rng), margin);
    // Axis-aligned edges: share an x or a y between two vertices.
    const int k = pick(rng);
    if (k < 2) v[1].x = v[0].x;
    if (k == 2 || k == 3) v[2].y = v[1].y;
    if (k == 4) {
      v[1].y = v[0].y;
      v[2].x = v[0].x;
    }
    const glm::vec2 e1 = v[1] - v[0], e2 = v[2] - v[0];
    if (e1.x * e2.y - e1.y * e2.x == 0.0f) continue;  // zero area: both drop it
    s.insert(s.end(), v, v + 3);
  }
  return s;
}

// A closed fan around a center: each rim edge and spoke shared by two triangles, windings mixed;
// vertices within `margin` pixels of the target.
Scene fan(std::mt19937& rng, int spokes, float margin) {
  std::uniform_real_distribution<float> pos(24.0f, kW - 24.0f), radius(4.0f, 60.0f);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
  std::bernoulli_distribution flip(0.5);
  const glm::vec2 c = grid_point({pos(rng), pos(rng)}, rng);
  std::vector<glm::vec2> rim;
  for (int k = 0; k < spokes; ++k) {
    const float a = 2.0f * std::numbers::pi_v<float> * (float(k) + jitter(rng)) / float(spokes);
    const float r = radius(rng);
    glm::vec2 p = clamp_to(grid_point(c + r * glm::vec2(std::cos(a), std::sin(a)), rng), margin);
    // Some spokes exactly horizontal or vertical.
    if (k % 7 == 3) p.y = c.y;
    if (k % 11 == 5) p.x = c.x;
    rim.push_back(p);
  }
  Scene s;
  for (int k = 0; k < spokes; ++k) {
    const glm::vec2 a = rim[k], b = rim[(k + 1) % spokes];
    const glm::vec2 e1 = a - c, e2 = b - c;
    if (e1.x * e2.y - e1.y * e2.x <= 0.0f) continue;  // snapping folded this wedge over: skip it
    if (flip(rng)) {
      s.insert(s.end(), {c, b, a});
    } else {
      s.insert(s.end(), {c, a, b});
    }
  }
  return s;
}

// A grid mesh with vertices on pixel centers or corners, or jittered on the 1/256 grid; both
// diagonals; every interior edge shared.
Scene grid_mesh(std::mt19937& rng, int cells_x, int cells_y, float cell, bool jitter) {
  std::uniform_real_distribution<float> j(-0.45f, 0.45f);
  std::bernoulli_distribution coin(0.5);
  const float origin = coin(rng) ? 0.5f : 0.0f;  // pixel centers or pixel corners
  std::vector<glm::vec2> v;
  for (int y = 0; y <= cells_y; ++y)
    for (int x = 0; x <= cells_x; ++x) {
      glm::vec2 p(origin + 2.0f + x * cell, origin + 2.0f + y * cell);
      if (jitter) p = glm::vec2(std::round((p.x + j(rng) * cell) * 256.0f) / 256.0f,
                                std::round((p.y + j(rng) * cell) * 256.0f) / 256.0f);
      v.push_back(p);
    }
  Scene s;
  auto at = [&](int x, int y) { return v[std::size_t(y) * (cells_x + 1) + x]; };
  for (int y = 0; y < cells_y; ++y)
    for (int x = 0; x < cells_x; ++x) {
      const glm::vec2 a = at(x, y), b = at(x + 1, y), c = at(x + 1, y + 1), d = at(x, y + 1);
      if (coin(rng)) {
        s.insert(s.end(), {a, b, c, a, c, d});
      } else {
        s.insert(s.end(), {a, b, d, b, c, d});
      }
    }
  return s;
}

// ---- Tests ------------------------------------------------------------------------------------

using PixelSet = std::set<std::pair<int, int>>;

PixelSet llvmpipe_covers(glref::CoverageProber& prober, std::vector<glm::vec2> tri) {
  std::vector<glm::vec4> clip;
  for (const glm::vec2& p : tri) clip.push_back(clip_from_window({p, 0.5f}, 16, 16));
  const glref::CoverageProbe gl = prober.draw(clip);
  PixelSet s;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      if (gl.mask[std::size_t(y) * 16 + x][0]) s.insert({x, y});
  return s;
}

// What the fill rule in common/fixed_point.h was measured from: on the square of pixel centers
// [2.5, 10.5]^2 cut along y = x, llvmpipe keeps centers on left and bottom edges (smallest
// window y) and drops those on top and right edges.
TEST(RasterVsLlvmpipe, LlvmpipeOwnsBottomAndLeftEdges) {
  TESSREF_REQUIRE_GL(ctx);
  glref::CoverageProber prober(*ctx, 16, 16);
  const glm::vec2 bl(2.5f, 2.5f), tl(2.5f, 10.5f), tr(10.5f, 10.5f), br(10.5f, 2.5f);
  PixelSet upper_left, lower_right;
  for (int x = 2; x <= 8; ++x)
    for (int y = x + 1; y <= 9; ++y) upper_left.insert({x, y});  // left in; top, diagonal out
  for (int x = 2; x <= 9; ++x)
    for (int y = 2; y <= x; ++y) lower_right.insert({x, y});  // bottom, diagonal in; right out
  EXPECT_EQ(llvmpipe_covers(prober, {tl, bl, tr}), upper_left);
  EXPECT_EQ(llvmpipe_covers(prober, {tl, tr, bl}), upper_left);
  EXPECT_EQ(llvmpipe_covers(prober, {bl, br, tr}), lower_right);
  EXPECT_EQ(llvmpipe_covers(prober, {bl, tr, br}), lower_right);
}

int scene_count(int fallback) {
  const char* env = std::getenv("TESSREF_RASTER_SCENES");  // more for a longer soak
  return env ? std::max(1, std::atoi(env)) : fallback;
}

TEST(RasterVsLlvmpipe, RandomTrianglesOnTheSubpixelGrid) {
  TESSREF_REQUIRE_GL(ctx);
  glref::CoverageProber prober(*ctx, kW, kH);
  std::mt19937 rng(20261123);
  Totals t;
  for (int scene = 0; scene < scene_count(60); ++scene)
    compare(prober, kW, kH,
            with_depth_bands(random_triangles(rng, glref::kProbeMaxTriangles, 0.0f), rng), t);
  expect_identical(t, "random triangles");
}

TEST(RasterVsLlvmpipe, SharedEdgeFans) {
  TESSREF_REQUIRE_GL(ctx);
  glref::CoverageProber prober(*ctx, kW, kH);
  std::mt19937 rng(7);
  Totals t;
  for (int scene = 0; scene < scene_count(60); ++scene) {
    Scene s;
    for (int f = 0; f < 4; ++f) {
      const Scene one = fan(rng, 8 + 8 * f, 0.0f);
      s.insert(s.end(), one.begin(), one.end());
    }
    compare(prober, kW, kH, with_depth_bands(s, rng), t);
  }
  expect_identical(t, "shared-edge fans");
}

// Triangles reaching off screen: llvmpipe's draw module clips them at the viewport sides and
// snaps the cut vertices. With tessref clipping at its old guard band instead, 93 of these
// 983,040 pixels differed (centers on or within float rounding of a cut edge); with Mesa's planes,
// order and arithmetic (raster/clip.cpp), none.
TEST(RasterVsLlvmpipe, OffScreenVerticesClippedAsLlvmpipeClipsThem) {
  TESSREF_REQUIRE_GL(ctx);
  glref::CoverageProber prober(*ctx, kW, kH);
  std::mt19937 rng(20261124);
  Totals t;
  for (int scene = 0; scene < scene_count(60); ++scene) {
    Scene s = random_triangles(rng, glref::kProbeMaxTriangles / 2, 40.0f);
    for (int f = 0; f < 2; ++f) {
      const Scene one = fan(rng, 24 + 8 * f, 40.0f);
      s.insert(s.end(), one.begin(), one.end());
    }
    s.resize(std::min<std::size_t>(s.size(), 3 * glref::kProbeMaxTriangles));
    compare(prober, kW, kH, with_depth_bands(s, rng), t);
  }
  expect_identical(t, "off-screen vertices");
}

TEST(RasterVsLlvmpipe, GridMeshes) {
  TESSREF_REQUIRE_GL(ctx);
  glref::CoverageProber prober(*ctx, kW, kH);
  std::mt19937 rng(99);
  Totals t;
  for (int scene = 0; scene < scene_count(60); ++scene) {
    const float cells[] = {1.0f, 3.0f, 8.0f, 13.0f};
    const float cell = cells[scene % 4];
    const int n = std::min(9, int(120.0f / cell));
    compare(prober, kW, kH, with_depth_bands(grid_mesh(rng, n, n, cell, scene % 3 != 0), rng), t);
  }
  expect_identical(t, "grid meshes");
}

}  // namespace
}  // namespace tessref
namespace tessref {
namespace {

// Off the 1/256 grid: random float clip coordinates, w in [0.5, 2] in every other scene, on a
// viewport whose half-sizes are not powers of two, so the divide, the viewport transform's rounding
// and the 24.8 snap all show. Inside the view volume: nothing is clipped. Depth sloped across each
// triangle: the depth plane must go through the unsnapped positions, as llvmpipe's does.
TEST(RasterVsLlvmpipe, FloatClipCoordinatesOnAnOddViewport) {
  TESSREF_REQUIRE_GL(ctx);
  const int w = 200, h = 152;
  glref::CoverageProber prober(*ctx, w, h);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), clip_w(0.5f, 2.0f);
  Totals t;
  const int n = glref::kProbeMaxTriangles;
  for (int scene = 0; scene < scene_count(100); ++scene) {
    std::vector<glm::vec4> clip;
    for (int k = 0; k < n; ++k) {
      const glm::vec2 c(u(rng), u(rng));
      const float r = std::exp2(6.0f * u(rng) - 5.0f);  // 1/2048 to 2 in NDC
      // Depth bands as in with_depth_bands: later triangles nearer.
      const float band = 0.9f - 1.8f * float(k + 1) / float(n + 1);
      for (int v = 0; v < 3; ++v) {
        const float z = band + 0.9f / float(n + 1) * 0.5f * (u(rng) + 1.0f);
        const glm::vec2 p = glm::clamp(c + r * glm::vec2(u(rng), u(rng)), -1.0f, 1.0f);
        const float wv = scene % 2 ? clip_w(rng) : 1.0f;
        clip.push_back(glm::vec4(p * wv, z * wv, wv));
      }
    }
    compare_clip(prober, w, h, clip, std::vector<bool>(n, false), t);
  }
  expect_identical(t, "float clip coordinates");
}

}  // namespace
}  // namespace tessref
namespace tessref {
namespace {

// Extreme clip coordinates, one triangle per draw. Known difference, not tested: the triangle
// (-1e30, -1e30), (1e30, -1e30), (0, 1e30) (w = 1) collapses to a point in tessref's clipper, and
// llvmpipe draws 4,608 pixels of it.
TEST(RasterVsLlvmpipe, ExtremeClipCoordinates) {
  TESSREF_REQUIRE_GL(ctx);
  const int w = 128, h = 96;
  glref::CoverageProber prober(*ctx, w, h);
  const std::vector<std::vector<glm::vec4>> tris = {
      {{-1e-30f, 0, 0, 1e-30f}, {1, -1, 0, 1}, {1, 1, 0, 1}},
      {{-3e4f, -2e4f, 0.5f, 1}, {3e4f, -2.5e4f, -0.5f, 1}, {1e3f, 4e4f, 0, 1}},
      {{-0.5f, -0.5f, -3, 1}, {0.9f, -0.7f, 3, 1}, {0.2f, 0.8f, 0.5f, 1}},  // near and far cut
  };
  Totals t;
  for (const auto& tri : tris) compare_clip(prober, w, h, tri, {true}, t);
  t.report("extreme clip coordinates");
  EXPECT_EQ(t.differing + t.differing_clipped, 0u) << t.first_differences;
  EXPECT_EQ(t.depth_over, 0u);
  EXPECT_EQ(t.covered, 6144u + 12288u + 1633u);
}

}  // namespace
}  // namespace tessref
