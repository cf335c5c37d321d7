#include "raster/setup.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "common/fixed_point.h"
#include "common/simd.h"
#include "raster/edge.h"

namespace tessref::raster {
namespace {

struct WindowVertex {
  std::int32_t x, y;  // 24.8 fixed point
  float xf, yf;       // before snapping
  float z;
  float inv_w;
  const float* varyings;
};

// GL 4.6 section 13.8.1: x_w = (x_ndc + 1) W/2, y_w = (y_ndc + 1) H/2,
// z_w = n + (f - n)(z_ndc + 1)/2; then x_w, y_w snap to 24.8. Evaluated as llvmpipe does (its
// draw module's viewport code): x_ndc * scale + translate with one fused multiply-add, scale =
// W/2, translate = x + W/2 (Viewport). Measured (raster_vs_llvmpipe_test, 200 x 152 viewport, random float clip
// coordinates): with the fma 0 of 3,040,000 pixels differ, with (x_ndc + 1) * W/2 rounded twice 2
// do. This is llvmpipe on a CPU with FMA (LLVM fuses its fmuladd); without FMA it would round
// twice. llvmpipe snaps x_w - 0.5 instead of x_w: the same 24.8 value, since that subtraction is
// exact for every x_w the viewport transform can produce (W >= 1).
// Vertices made by clipping (generated) go through Mesa's clipper instead, plain C floats:
// x_ndc * scale + translate rounded twice.
WindowVertex to_window(const glm::vec4& position, const float* varyings, const Viewport& vp,
                       bool generated = false) {
  const float inv_w = 1.0f / position.w;
  const float x_ndc = position.x * inv_w;
  const float y_ndc = position.y * inv_w;
  const float z_ndc = position.z * inv_w;
  WindowVertex r;
  auto transform = [generated](float ndc, float scale, float translate) {
    return generated ? ndc * scale + translate : std::fma(ndc, scale, translate);
  };
  r.xf = transform(x_ndc, vp.scale_x(), vp.translate_x());
  r.yf = transform(y_ndc, vp.scale_y(), vp.translate_y());
  r.x = fixed::snap_subpixel(r.xf);
  r.y = fixed::snap_subpixel(r.yf);
  const float z = transform(z_ndc, vp.scale_z(), vp.translate_z());
  // Clipping leaves z_ndc in [-1, 1] up to rounding; keep the rounding inside the depth range.
  r.z = std::clamp(z, vp.vertex_z_lo(), vp.vertex_z_hi());
  r.inv_w = inv_w;
  r.varyings = varyings;
  return r;
}


enum class PieceResult { kCulled, kRasterized };


// The pixels whose centers k * 256 + 128 (0 <= k < size) lie in [lo, hi] (24.8): [first, last],
// empty when first > last. Floor division by 256 as an arithmetic shift.
void pixel_range(std::int64_t lo, std::int64_t hi, int size, int& first, int& last) {
  const std::int64_t one = fixed::kSubpixelOne, half = fixed::kSubpixelHalf;
  static_assert(fixed::kSubpixelOne == 256);
  first = int(std::max<std::int64_t>(0, (lo - half + one - 1) >> 8));
  last = int(std::min<std::int64_t>(size - 1, (hi - half) >> 8));
}

WindowVertex from_projected(const ProjectedVertex& p, const float* varyings) {
  return WindowVertex{p.x, p.y, p.xf, p.yf, p.z, p.inv_w, varyings};
}

// The snapped area test, culling and the box of candidate pixels, from the snapped positions
// alone: what every piece goes through before anything is stored.
struct PieceBox {
  std::int64_t area2;
  bool ccw;    // counter-clockwise with y up
  bool front;  // front-facing by the face rule
  int min_x, min_y, max_x, max_y;  // pixels whose centers may be covered, inclusive
  bool empty() const { return min_x > max_x || min_y > max_y; }
};

template <class V>
bool piece_box(const V& a, const V& b, const V& c, const Viewport& vp, FaceRule faces,
               PieceBox& box) {
  box.area2 = std::int64_t(b.x - a.x) * (c.y - a.y) - std::int64_t(c.x - a.x) * (b.y - a.y);
  if (box.area2 == 0) return false;
  box.ccw = box.area2 > 0;
  box.front = faces.front(box.ccw);
  if (faces.culled(box.ccw)) return false;
  // Pixel x is a candidate when its center x * 256 + 128 lies in [min x, max x].
  pixel_range(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), vp.width, box.min_x, box.max_x);
  pixel_range(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), vp.height, box.min_y, box.max_y);
  return true;
}

// Stores a piece that passed piece_box with a non-empty box (or drops it when it is small and
// covers no center): what remains of setup_piece.
// Flat varyings (flat.mask) take the provoking vertex's values, with zero differences.
struct FlatVaryings {
  const VaryingMask* mask = nullptr;  // null: none is flat
  const float* provoking = nullptr;
};

void store_piece(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                 const PieceBox& box, const Viewport& vp, int num_varyings, FlatVaryings flat,
                 std::vector<SetupTriangle>& tris, std::vector<float>& varyings) {
  const bool ccw = box.ccw;
  const int min_x = box.min_x, min_y = box.min_y, max_x = box.max_x, max_y = box.max_y;
  // Wind every triangle counter-clockwise so that the edge functions are positive inside.
  const WindowVertex* v[3] = {&a, ccw ? &b : &c, ccw ? &c : &b};

  SetupTriangle t;
  for (int i = 0; i < 3; ++i) {
    t.x[i] = v[i]->x;
    t.y[i] = v[i]->y;
    t.z[i] = v[i]->z;
    t.inv_w[i] = v[i]->inv_w;
  }
  // Small triangles: test the few candidate centers now; most cover none and need no more setup.
  t.small_mask = 0;
  if ((max_x - min_x + 1) * (max_y - min_y + 1) <= kSmallTrianglePixels) {
    // E_i + bias_i at each center, stepped exactly in integers from the box's first center.
    const TriangleEdges edges(t.x, t.y);
    std::int64_t row[3];
    for (int i = 0; i < 3; ++i)
      row[i] = edges.e[i].at(fixed::pixel_center(min_x), fixed::pixel_center(min_y)) + edges.e[i].bias;
    int bit = 0;
    for (int py = min_y; py <= max_y; ++py) {
      std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
      for (int px = min_x; px <= max_x; ++px, ++bit) {
        if ((e0 | e1 | e2) >= 0) t.small_mask |= std::uint8_t(1u << bit);
        e0 += edges.e[0].step_x;
        e1 += edges.e[1].step_x;
        e2 += edges.e[2].step_x;
      }
      for (int i = 0; i < 3; ++i) row[i] += edges.e[i].dx * fixed::kSubpixelOne;
    }
    if (!t.small_mask) return;
  }
  // Interpolation planes through the float positions: llvmpipe sets up depth and every varying
  // from them, not from the snapped ones; off the 1/256 grid the two differ (measured: up to 9.5e-5
  // in depth on random float triangles with sloped depth; 6e-7 with these planes,
  // raster_vs_llvmpipe_test).
  {
    double px[3], py[3];
    for (int i = 0; i < 3; ++i) {
      px[i] = v[i]->xf;
      py[i] = v[i]->yf;
    }
    double area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
    if (!(area != 0.0) || !std::isfinite(area)) {  // degenerate before snapping: use the snapped
      for (int i = 0; i < 3; ++i) {
        px[i] = t.x[i] / double(fixed::kSubpixelOne);
        py[i] = t.y[i] / double(fixed::kSubpixelOne);
      }
      area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
    }
    const double ex1 = px[1] - px[0], ey1 = py[1] - py[0];
    const double ex2 = px[2] - px[0], ey2 = py[2] - py[0];
    t.b_x0 = px[0];
    t.b_y0 = py[0];
    t.b1_dx = ey2 / area;
    t.b1_dy = -ex2 / area;
    t.b2_dx = -ey1 / area;
    t.b2_dy = ex1 / area;
    t.z_lo = vp.vertex_z_lo();  // GL_DEPTH_CLAMP: gl_FragCoord.z unclamped, the depth test clamps
    t.z_hi = vp.vertex_z_hi();
  }
  t.front_facing = box.front;
  t.min_x = min_x;
  t.min_y = min_y;
  t.max_x = max_x;
  t.max_y = max_y;

  // Stored as a0, a1 - a0, a2 - a0 (see SetupTriangle::varying_offset).
  t.varying_offset = std::uint32_t(varyings.size());
  varyings.resize(varyings.size() + 3 * std::size_t(num_varyings));
  float* __restrict out = varyings.data() + t.varying_offset;
  const float* __restrict a0 = v[0]->varyings;
  const float* __restrict a1 = v[1]->varyings;
  const float* __restrict a2 = v[2]->varyings;
  if (num_varyings > 0) std::memcpy(out, a0, sizeof(float) * std::size_t(num_varyings));
  for (int j = 0; j < num_varyings; ++j) {
    out[num_varyings + j] = a1[j] - a0[j];
    out[2 * num_varyings + j] = a2[j] - a0[j];
  }
  if (flat.mask)
    for (int j = 0; j < num_varyings; ++j)
      if ((*flat.mask)[std::size_t(j)]) {
        out[j] = flat.provoking[j];
        out[num_varyings + j] = out[2 * num_varyings + j] = 0.0f;
      }
  tris.push_back(t);
}

PieceResult setup_piece(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                        const Viewport& vp, FaceRule faces, int num_varyings,
                        FlatVaryings flat, std::vector<SetupTriangle>& tris,
                        std::vector<float>& varyings) {
  PieceBox box;
  if (!piece_box(a, b, c, vp, faces, box)) return PieceResult::kCulled;
  // No pixel center in the bounding box: set up (it counts) but nothing to scan. Most triangles
  // of a finely tessellated surface end here.
  if (!box.empty()) store_piece(a, b, c, box, vp, num_varyings, flat, tris, varyings);
  return PieceResult::kRasterized;
}

}  // namespace

// llvmpipe (Mesa's draw module) clips at the viewport sides, with no guard band: measured in
// raster_vs_llvmpipe_test, where a triangle reaching 1.5 pixels past the top edge already gets cut
// vertices. Clipping at the same planes with the same arithmetic gives the same pixels.
float Viewport::guard_x() const { return 1.0f; }
float Viewport::guard_y() const { return 1.0f; }

void project_vertices(const ClipVertex* vertices, std::size_t count, int records,
                      const Viewport& vp, ProjectedVertex* out) {
  static const bool kernel = project_kernel_available();
  if (kernel && simd_path() == SimdPath::Avx2) {
    static_assert(sizeof(ClipVertex) % sizeof(float) == 0 && offsetof(ClipVertex, position) == 0);
    const ProjectParams params{vp.guard_x(),     vp.guard_y(),     vp.scale_x(),     vp.translate_x(),
                               vp.scale_y(),     vp.translate_y(), vp.scale_z(),     vp.translate_z(),
                               vp.vertex_z_lo(), vp.vertex_z_hi(), vp.outcode_mask()};
    project_vertices_avx2(reinterpret_cast<const float*>(vertices),
                          std::size_t(records) * sizeof(ClipVertex) / sizeof(float), count, params, out);
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      ProjectedVertex& p = out[i];
      const ClipVertex& v = vertices[i * std::size_t(records)];
      const std::uint32_t code = clip_outcode(v.position, vp.guard_x(), vp.guard_y()) & vp.outcode_mask();
      p.code = code;
      if (!outcode_projectable(code)) continue;  // only clipped (or dropped) triangles use it
      p = project_position(v.position, vp, false);
      p.code = code;
    }
  }
  // The user planes' bits (a non-finite position has no other bit: the primitive is dropped).
  if (vp.user.mask)
    for (std::size_t i = 0; i < count; ++i)
      if (!(out[i].code & outcode::kNonFinite))
        out[i].code |= user_outcode(&vertices[i * std::size_t(records)].position.x, vp.user);
}

ProjectedVertex project_position(const glm::vec4& position, const Viewport& vp, bool generated) {
  const WindowVertex w = to_window(position, nullptr, vp, generated);
  return ProjectedVertex{w.x, w.y, w.xf, w.yf, w.z, w.inv_w, 0u};
}

SetupOutcome setup_triangle(const TriangleBatch& batch, std::size_t index,
                            const ProjectedVertex* projected, const Viewport& vp,
                            FaceRule faces, std::vector<SetupTriangle>& tris,
                            std::vector<float>& varyings, int& pieces_out) {
  pieces_out = 0;
  const std::size_t i0 = batch.vertex_index(index, 0), i1 = batch.vertex_index(index, 1),
                    i2 = batch.vertex_index(index, 2);
  const int nv = std::clamp(batch.num_varyings, 0, kMaxVaryings);
  const float* d0 = batch.vertex_data(i0);
  const float* d1 = batch.vertex_data(i1);
  const float* d2 = batch.vertex_data(i2);
  const FlatVaryings flat{batch.flat_varyings.any() ? &batch.flat_varyings : nullptr, d2 + 4};
  if (vp.culled({d0 + 4, d1 + 4, d2 + 4})) return SetupOutcome::kCulled;
  switch (classify_outcodes(projected[i0].code, projected[i1].code, projected[i2].code)) {
    case ClipTest::kInvalid:
    case ClipTest::kRejected: return SetupOutcome::kClippedAway;
    case ClipTest::kInside: {
      // Fast exits first, from the snapped positions alone, as setup_piece decides them.
      PieceBox box;
      if (!piece_box(projected[i0], projected[i1], projected[i2], vp, faces, box))
        return SetupOutcome::kCulled;
      pieces_out = 1;
      if (!box.empty())
        store_piece(from_projected(projected[i0], d0 + 4), from_projected(projected[i1], d1 + 4),
                    from_projected(projected[i2], d2 + 4), box, vp, nv, flat, tris, varyings);
      return SetupOutcome::kRasterized;
    }
    case ClipTest::kNeedsClip: break;
  }

  ClipPolygon poly;
  ClipResult clipped = clip_triangle(d0, d1, d2, nv, vp.guard_x(), vp.guard_y(), poly, vp.outcode_mask(), vp.user);
  if (clipped != ClipResult::kKept) return SetupOutcome::kClippedAway;

  WindowVertex w[kMaxClipVertices];
  for (int k = 0; k < poly.count; ++k)
    w[k] = to_window(poly.v[k].position, poly.v[k].varyings.data(), vp, poly.generated[k]);
  // A planar convex polygon: fan from its first vertex.
  for (int k = 1; k + 1 < poly.count; ++k) {
    if (setup_piece(w[0], w[k], w[k + 1], vp, faces, nv, flat, tris, varyings) ==
        PieceResult::kRasterized)
      ++pieces_out;
  }
  return pieces_out > 0 ? SetupOutcome::kRasterized : SetupOutcome::kCulled;
}

SetupOutcome setup_triangle(const TriangleBatch& batch, std::size_t index, const Viewport& vp,
                            FaceRule faces, std::vector<SetupTriangle>& tris,
                            std::vector<float>& varyings, int& pieces_out) {
  // A three-vertex batch of this triangle's corners, projected here.
  TriangleBatch one;
  one.num_varyings = batch.num_varyings;
  one.flat_varyings = batch.flat_varyings;
  const std::size_t r = std::size_t(batch.records());
  for (int k = 0; k < 3; ++k) {
    const ClipVertex* v = &batch.corner(index, k);
    one.vertices.insert(one.vertices.end(), v, v + r);
  }
  ProjectedVertex projected[3];
  project_vertices(one.vertices.data(), 3, one.records(), vp, projected);
  return setup_triangle(one, 0, projected, vp, faces, tris, varyings, pieces_out);
}

}  // namespace tessref::raster
