// Indexed batches: drawing a vertex array through an index list gives the bytes of drawing the
// same triangles as consecutive triples, clipped ones included; bad indices are refused.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>

#include "common/simd.h"
#include "raster/rasterizer.h"
#include "raster/setup.h"
#include "raster_test_util.h"

namespace tessref {
namespace {

// A grid of shared vertices in clip space, some behind the eye or outside the view volume, so
// that inside, clipped and rejected triangles all share vertices.
TriangleBatch grid_batch(int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
  TriangleBatch b;
  b.indexed = true;
  b.num_varyings = 4;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) {
      ClipVertex v;
      const float w = 0.5f + 2.0f * float(y) / float(n) + jitter(rng);  // some w < 0.5, none 0
      v.position = glm::vec4((2.4f * x / n - 1.2f + jitter(rng) * 0.01f) * w,
                             (2.4f * y / n - 1.2f) * w, (jitter(rng) * 3.0f) * w, w);
      for (int k = 0; k < 4; ++k) v.varyings[k] = float(x * 7 + y * 3 + k) * 0.01f;
      b.vertices.push_back(v);
    }
  auto id = [n](int x, int y) { return std::uint32_t(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      b.indices.insert(b.indices.end(), {id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      b.indices.insert(b.indices.end(), {id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  return b;
}

struct Flat : FragmentProgram {
  FragmentOutput shade(const FragmentInput& in) const override {
    FragmentOutput o;
    o.color = glm::vec4(in.varyings[0], in.varyings[1], in.varyings[2], in.frag_coord.w);
    o.aux = glm::vec4(in.frag_coord.z, in.front_facing ? 1.0f : 0.0f, in.varyings[3], 0.0f);
    return o;
  }
};

TEST(IndexedBatch, DrawsTheBytesOfItsExpandedTriangles) {
  const TriangleBatch indexed = grid_batch(120, 3);
  const TriangleBatch expanded = expand_indices(indexed);
  ASSERT_EQ(expanded.triangle_count(), indexed.triangle_count());
  const Flat fs;
  for (bool cull : {false, true}) {
    RasterState state;
    state.cull_back_faces = cull;
    Framebuffer a(97, 83), b(97, 83);
    const RasterStats sa = draw_triangles(indexed, state, fs, a, Parallel(2));
    const RasterStats sb = draw_triangles(expanded, state, fs, b, Parallel(1));
    EXPECT_GT(sa.fragments_shaded, 1000u);
    EXPECT_GT(sa.triangles_clipped_away, 0u);
    EXPECT_GT(sa.triangles_rasterized, sa.fragments_shaded / 100);
    EXPECT_EQ(sa.triangles_rasterized, sb.triangles_rasterized);
    EXPECT_EQ(sa.triangles_culled, sb.triangles_culled);
    EXPECT_EQ(sa.triangles_clipped_away, sb.triangles_clipped_away);
    EXPECT_EQ(sa.fragments_shaded, sb.fragments_shaded);
    EXPECT_EQ(std::memcmp(a.color.data(), b.color.data(), a.color.size() * sizeof(glm::vec4)), 0);
    EXPECT_EQ(std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(a.aux.data(), b.aux.data(), a.aux.size() * sizeof(glm::vec4)), 0);
  }
}

TEST(IndexedBatch, AppendKeepsTheTriangleOrder) {
  const TriangleBatch a = grid_batch(4, 1), b = grid_batch(5, 2);
  TriangleBatch joined = expand_indices(a);  // a triple batch, then an indexed one appended
  append_triangles(joined, b);
  ASSERT_TRUE(joined.indexed);
  ASSERT_EQ(joined.triangle_count(), a.triangle_count() + b.triangle_count());
  const TriangleBatch flat = expand_indices(joined);
  const TriangleBatch fa = expand_indices(a), fb = expand_indices(b);
  EXPECT_EQ(std::memcmp(flat.vertices.data(), fa.vertices.data(), fa.vertices.size() * sizeof(ClipVertex)), 0);
  EXPECT_EQ(std::memcmp(flat.vertices.data() + fa.vertices.size(), fb.vertices.data(),
                        fb.vertices.size() * sizeof(ClipVertex)), 0);
}

TEST(IndexedBatch, AnIndexPastTheVertexArrayIsRefused) {
  TriangleBatch b = grid_batch(3, 1);
  b.indices[7] = std::uint32_t(b.vertices.size());
  Framebuffer fb(16, 16);
  const Flat fs;
  EXPECT_THROW(draw_triangles(b, RasterState{}, fs, fb, Parallel(1)), std::invalid_argument);
  b = grid_batch(3, 1);
  b.indices.pop_back();
  EXPECT_THROW(draw_triangles(b, RasterState{}, fs, fb, Parallel(1)), std::invalid_argument);
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

TEST(ProjectVertices, KernelAndPortableCodeAgreeBitForBit) {
  if (!raster::project_kernel_available()) GTEST_SKIP() << "no AVX2 + FMA: only the portable code runs";
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  std::vector<ClipVertex> vs(20000);
  for (std::size_t i = 0; i < vs.size(); ++i) {
    vs[i].position = glm::vec4(u(rng), u(rng), u(rng), u(rng));
    if (i % 97 == 0) vs[i].position.y = std::numeric_limits<float>::infinity();
    if (i % 89 == 0) vs[i].position.w = 0.0f;
  }
  const raster::Viewport vp{997, 613, 0.25f, 0.75f};
  const SimdPath saved = simd_path();
  std::vector<raster::ProjectedVertex> a(vs.size()), b(vs.size());
  set_simd_path(SimdPath::Avx2);
  raster::project_vertices(vs.data(), vs.size(), 1, vp, a.data());
  set_simd_path(SimdPath::Scalar);
  raster::project_vertices(vs.data(), vs.size(), 1, vp, b.data());
  set_simd_path(saved);
  std::size_t projected = 0;
  for (std::size_t i = 0; i < vs.size(); ++i) {
    ASSERT_EQ(a[i].code, b[i].code) << i;
    if (!raster::outcode_projectable(a[i].code)) continue;
    ++projected;
    ASSERT_EQ(a[i].x, b[i].x) << i;
    ASSERT_EQ(a[i].y, b[i].y) << i;
    for (auto f : {&raster::ProjectedVertex::xf, &raster::ProjectedVertex::yf,
                   &raster::ProjectedVertex::z, &raster::ProjectedVertex::inv_w})
      ASSERT_EQ(std::memcmp(&(a[i].*f), &(b[i].*f), sizeof(float)), 0) << i;
  }
  EXPECT_GT(projected, 1000u);
}

}  // namespace
}  // namespace tessref
