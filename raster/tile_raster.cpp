#include "raster/tile_raster.h"

#include <algorithm>

#include "common/fixed_point.h"
#include "raster/edge.h"

namespace tessref::raster {
namespace {

// floor(a / b) and ceil(a / b) for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

// Rows narrower than this are scanned pixel by pixel; wider ones get their exact span by
// division first (three 64-bit divisions cost about as much as a dozen pixel tests).
constexpr int kSpanDivisionMinWidth = 12;

// The covered centers of one row, [lo, hi] (empty when lo > hi): convex, so one span.
struct Span {
  int lo = 1, hi = 0;
};

Span row_span(const Edge* edges, int x0, int x1, int y) {
  const std::int64_t px0 = fixed::pixel_center(x0);
  const std::int64_t py = fixed::pixel_center(y);
  std::int64_t e[3];
  for (int i = 0; i < 3; ++i) e[i] = edges[i].at(px0, py);
  Span span;
  if (x1 - x0 + 1 < kSpanDivisionMinWidth) {
    // Inside iff E_i + bias_i >= 0 for all i, i.e. (E + bias) has no sign bit in any edge.
    for (int x = x0; x <= x1; ++x) {
      if (((e[0] + edges[0].bias) | (e[1] + edges[1].bias) | (e[2] + edges[2].bias)) >= 0) {
        if (span.lo > span.hi) span.lo = x;
        span.hi = x;
      } else if (span.lo <= span.hi) {
        break;  // past the span
      }
      for (int i = 0; i < 3; ++i) e[i] += edges[i].step_x;
    }
    return span;
  }
  // Exact span: E_i(x0 + k) + bias_i = e_i + bias_i + k * step_i >= 0 for all i.
  std::int64_t k_lo = 0, k_hi = x1 - x0;
  for (int i = 0; i < 3; ++i) {
    const std::int64_t c = e[i] + edges[i].bias;
    const std::int64_t s = edges[i].step_x;
    if (s == 0) {
      if (c < 0) k_hi = -1;
    } else if (s < 0) {
      k_hi = std::min(k_hi, floor_div(c, -s));
    } else {
      k_lo = std::max(k_lo, ceil_div(-c, s));
    }
  }
  if (k_lo <= k_hi) {
    span.lo = x0 + int(k_lo);
    span.hi = x0 + int(k_hi);
  }
  return span;
}

// The covered run of row y within [x0, x1] of a line's or point's four half-planes: E > 0 for
// all, E linear in X, so again one span, found exactly by division.
Span quad_row_span(const HalfPlane* planes, int x0, int x1, int y) {
  std::int64_t k_lo = 0, k_hi = x1 - x0;
  for (int i = 0; i < 4; ++i) {
    // E(x0 + k) = c0 + k s with s = -256 dcdx; inside when E >= 1.
    const std::int64_t c = planes[i].at(x0, y) - 1;
    const std::int64_t s = -planes[i].dcdx * fixed::kSubpixelOne;
    if (s == 0) {
      if (c < 0) k_hi = -1;
    } else if (s < 0) {
      k_hi = std::min(k_hi, floor_div(c, -s));
    } else {
      k_lo = std::max(k_lo, ceil_div(-c, s));
    }
  }
  Span span;
  if (k_lo <= k_hi) {
    span.lo = x0 + int(k_lo);
    span.hi = x0 + int(k_hi);
  }
  return span;
}

// The per-pixel interpolation of one triangle: the one definition both scan paths below use.
// Barycentrics come from the planes through the float positions (see SetupTriangle); window
// depth is linear in window space; varyings are perspective-correct (attribute/w and 1/w
// interpolated linearly, then divided), relative to vertex 0 so that a varying equal at all
// three vertices stays exact.
struct PixelInterpolation {
  const SetupTriangle& t;
  double dz1, dz2;
  double inv_w0, inv_w1, inv_w2;

  explicit PixelInterpolation(const SetupTriangle& tri)
      : t(tri),
        dz1(double(tri.z[1]) - tri.z[0]),
        dz2(double(tri.z[2]) - tri.z[0]),
        inv_w0(tri.inv_w[0]),
        inv_w1(tri.inv_w[1]),
        inv_w2(tri.inv_w[2]) {}

  // Barycentric weights of vertices 1 and 2 at the center of (x, y).
  void barycentrics(int x, int y, double& b1, double& b2) const {
    const double dx = double(x) + 0.5 - t.b_x0, dy = double(y) + 0.5 - t.b_y0;
    b1 = t.b1_dx * dx + t.b1_dy * dy;
    b2 = t.b2_dx * dx + t.b2_dy * dy;
  }
  // Window depth, kept in the depth range.
  float depth(double b1, double b2) const {
    return std::clamp(float(double(t.z[0]) + b1 * dz1 + b2 * dz2), t.z_lo, t.z_hi);
  }
  // The perspective-correct weights of vertices 1 and 2; returns 1/w at the pixel.
  double perspective(double b1, double b2, float& w1, float& w2) const {
    const double b0 = 1.0 - b1 - b2;
    const double p0 = b0 * inv_w0, p1 = b1 * inv_w1, p2 = b2 * inv_w2;
    const double inv_w = p0 + p1 + p2;
    const double w = 1.0 / inv_w;
    w1 = float(p1 * w);
    w2 = float(p2 * w);
    return inv_w;
  }
  // One varying from its stored a0, a1 - a0, a2 - a0.
  static float varying(float a0, float d1, float d2, float w1, float w2) {
    return a0 + w1 * d1 + w2 * d2;
  }
};

}  // namespace

bool triangle_may_cover(const SetupTriangle& t, const PixelRect& rect) {
  const TriangleEdges te(t.x, t.y);
  const std::int64_t cx0 = fixed::pixel_center(rect.x0), cx1 = fixed::pixel_center(rect.x1);
  const std::int64_t cy0 = fixed::pixel_center(rect.y0), cy1 = fixed::pixel_center(rect.y1);
  for (const Edge& e : te.e) {
    // E is linear, so its largest value over the rectangle of centers is at a corner.
    const std::int64_t best = std::max(std::max(e.at(cx0, cy0), e.at(cx1, cy0)),
                                       std::max(e.at(cx0, cy1), e.at(cx1, cy1)));
    if (best + e.bias < 0) return false;
  }
  return true;
}

bool quad_may_cover(const SetupQuad& q, const PixelRect& rect) {
  for (const HalfPlane& p : q.plane) {
    const std::int64_t best = std::max(std::max(p.at(rect.x0, rect.y0), p.at(rect.x1, rect.y0)),
                                       std::max(p.at(rect.x0, rect.y1), p.at(rect.x1, rect.y1)));
    if (best <= 0) return false;
  }
  return true;
}

struct FragmentSink::Lanes {
  std::size_t pixel[kFragmentLanes];
  alignas(32) double b1[kFragmentLanes];
  alignas(32) double b2[kFragmentLanes];
  FragmentBatch batch;
  // Lanes that are not live still go through the programs' SIMD loops: they start out with
  // harmless values and afterwards hold earlier fragments' ones.
  Lanes() {
    std::fill_n(pixel, kFragmentLanes, 0);
    std::fill_n(b1, kFragmentLanes, 0.0);
    std::fill_n(b2, kFragmentLanes, 0.0);
    for (auto* rows : {&batch.frag_coord[0], &batch.color[0], &batch.aux[0]})
      std::fill_n(rows[0], 4 * kFragmentLanes, 0.0f);
    std::fill_n(batch.more[0][0], (kMaxDrawBuffers - 2) * 4 * kFragmentLanes, 0.0f);
    std::fill_n(batch.varyings[0], kMaxVaryings * kFragmentLanes, 0.0f);
    std::fill_n(batch.live, kFragmentLanes, 0);
    std::fill_n(batch.front_facing, kFragmentLanes, 0);
  }
};

FragmentSink::Lanes& FragmentSink::thread_lanes(int num_varyings) {
  thread_local Lanes lanes;
  lanes.batch.quads = 0;
  lanes.batch.num_varyings = num_varyings;
  return lanes;
}

FragmentSink::FragmentSink(const FragmentProgram& fs, Framebuffer& fb, int num_varyings,
                           const RasterState& state, const VaryingMask* flat)
    : flat_(flat && flat->any() ? flat : nullptr),
      fs_(fs),
      fb_(fb),
      draw_buffers_(fb.draw_buffers()),
      depth_format_(fb.depth_format),
      depth_write_(state.depth_test && state.depth_write),
      depth_func_(state.depth_func),
      late_depth_(state.depth_test && (fs.may_discard() || fs.writes_depth() ||
                                       (fs.has_side_effects() && !fs.early_fragment_tests()))),
      early_test_(state.depth_test && !fs.writes_depth() && (!fs.has_side_effects() || fs.early_fragment_tests())),
      shader_depth_(fs.writes_depth()),
      helpers_(fs.reads_quads() || fs.shades_whole_vectors()),
      vectors_(fs.shades_whole_vectors()),
      blend_(state.blend),
      color_mask_(state.color_mask),
      srgb_write_(state.framebuffer_srgb),
      depth_clamp_(state.depth_clamp),
      clamp_lo_(float(std::min(state.depth_range_near, state.depth_range_far))),
      clamp_hi_(float(std::max(state.depth_range_near, state.depth_range_far))),
      lanes_(thread_lanes(num_varyings)),
      batch_(lanes_.batch),
      pixel_(lanes_.pixel),
      b1_(lanes_.b1),
      b2_(lanes_.b2) {
  plain_ = !blend_.enabled && color_mask_.all();
  for (int k = 0; k < draw_buffers_; ++k) {
    std::vector<glm::vec4>* b = fb.draw_buffer(k);
    targets_[k] = b ? b->data() : nullptr;
    if (b && fb.color_format[std::size_t(k)] != ColorFormat::kRgba32F) plain_ = false;
  }
}

void FragmentSink::flush() {
  if (batch_.quads == 0) return;
  fs_.shade_batch(batch_);
  const int lanes = batch_.lanes();
  for (int l = 0; l < lanes; ++l) {
    if (!batch_.live[l]) continue;
    const std::size_t idx = pixel_[l];
    if (late_depth_) {  // lanes in arrival order: the test against fragments shaded before
      const float z = shader_depth_ ? shader_depth(batch_.frag_depth[l]) : stored_depth(batch_.frag_coord[2][l]);
      if (!depth_passes(z, fb_.depth[idx])) {
        ++depth_failed_;
        continue;
      }
      if (depth_write_) fb_.depth[idx] = z;
    }
    // Blending and the colour mask (GL 4.6 17.3.6, 17.4.2) on every draw buffer, in arrival
    // order, each in its format's arithmetic.
    for (int k = 0; k < draw_buffers_; ++k) {
      glm::vec4* target = targets_[k];
      if (!target) continue;
      glm::vec4& stored = target[idx];
      glm::vec4 c(batch_.output(k, 0)[l], batch_.output(k, 1)[l], batch_.output(k, 2)[l], batch_.output(k, 3)[l]);
      if (plain_) {  // RGBA32F, no blending, every channel written: the common case
        stored = c;
        continue;
      }
      const ColorFormat f = fb_.color_format[std::size_t(k)];
      if (blend_.enabled) c = blended_color(f, srgb_write_, blend_, c, stored);
      else if (f != ColorFormat::kRgba32F) c = stored_color(f, srgb_write_, c);
      stored = color_mask_.all() ? c : color_mask_.apply(c, stored);
    }
  }
  batch_.quads = 0;
}

// The row loop both primitive kinds share: coverage comes from row_span(lo, hi, y), the covered
// run of row y within [lo, hi]; depth and varyings from t's interpolation planes.
struct Scanner {
  template <class RowSpan>
  static std::uint64_t rows(const SetupTriangle& t, const float* varyings, int num_varyings,
                            int x0, int x1, int y0, int y1, FragmentSink& sink,
                            RowSpan&& span_of_row) {
    const PixelInterpolation ip(t);
    const float* __restrict a0 = varyings;
    const float* __restrict d1 = varyings + num_varyings;
    const float* __restrict d2 = varyings + 2 * num_varyings;
    Framebuffer& fb = sink.fb_;
    FragmentBatch& batch = sink.batch_;
    std::uint64_t passed = 0;
    // Quad rows (aligned row pairs), each cut into segments of at most a batch of quads. The
    // per-pixel formulas run over a whole row segment or batch range in loops without branches
    // (so they vectorize).
    for (int qy = y0 & ~1; qy <= y1; qy += 2) {
      Span span[2];
      for (int r = 0; r < 2; ++r)
        if (qy + r >= y0 && qy + r <= y1) span[r] = span_of_row(x0, x1, qy + r);
      const bool has0 = span[0].lo <= span[0].hi, has1 = span[1].lo <= span[1].hi;
      if (!has0 && !has1) continue;
      const int lo = !has1 ? span[0].lo : !has0 ? span[1].lo : std::min(span[0].lo, span[1].lo);
      const int hi = !has1 ? span[0].hi : !has0 ? span[1].hi : std::max(span[0].hi, span[1].hi);
      // Segments start on 4-pixel columns, so that the two quads a texture lookup's vector holds
      // (llvmpipe's 4 x 2 pixels, Invocations::set_sampling_vectors) share a segment and a batch.
      for (int seg_x = lo & ~3; seg_x <= hi; seg_x += 2 * kFragmentQuads) {
        // Whole vectors (two quads) where the program shades them together.
        const int seg_quads = std::min(kFragmentQuads, ((hi - seg_x) / 2 + 1 + int(sink.vectors_)) & ~int(sink.vectors_));
        if (batch.quads + seg_quads > kFragmentQuads) sink.flush();
        const int base = 4 * batch.quads;
        const int lanes = 4 * seg_quads;
        // A lane at its own pixel centre: lane 4q + k is pixel (k & 1, k >> 1) of quad q.
        auto place = [&](int l, int x, int y) {
          ip.barycentrics(x, y, sink.b1_[l], sink.b2_[l]);
          batch.frag_coord[0][l] = float(x) + 0.5f;
          batch.frag_coord[1][l] = float(y) + 0.5f;
          batch.frag_coord[2][l] = ip.depth(sink.b1_[l], sink.b2_[l]);
        };
        // For a program that takes derivatives, every lane of the segment: those that cover
        // nothing (or fail the depth test) run as GL's helper invocations (gl_HelperInvocation),
        // with inputs interpolated at their own pixel, so that derivatives across a triangle's
        // edge difference real values, as on llvmpipe's quads. Other programs never read them.
        for (int l = base; l < base + lanes; ++l) {
          batch.live[l] = 0;
          if (sink.helpers_) place(l, seg_x + 2 * ((l - base) >> 2) + (l & 1), qy + ((l & 3) >> 1));
        }

        // The covered run of each row, then the depth test.
        for (int r = 0; r < 2; ++r) {
          const int y = qy + r;
          const int xs = std::max(span[r].lo, seg_x);
          const int xe = std::min(span[r].hi, seg_x + 2 * seg_quads - 1);
          const int n = xe - xs + 1;
          if (n <= 0) continue;
          float* depth = fb.depth.data() + fb.index(xs, y);
          for (int i = 0; i < n; ++i) {
            const int x = xs + i;
            const int lane = base + 2 * (x - seg_x) - (x & 1) + 2 * r;  // 4 * quad + (x & 1) + 2r
            if (!sink.helpers_) place(lane, x, y);
            if (sink.early_test_) {
              const float stored = sink.stored_depth(batch.frag_coord[2][lane]);
              if (!sink.depth_passes(stored, depth[i])) {
                ++sink.depth_failed_;
                continue;
              }
              if (sink.early_depth_write()) depth[i] = stored;  // no discard: the write is final
            }
            batch.live[lane] = 1;
            sink.pixel_[lane] = fb.index(x, y);
            ++passed;
          }
        }

        // Varyings of the segment's lanes (dead lanes compute what they hold, unused).
        float w1[kFragmentLanes], w2[kFragmentLanes];
        for (int l = base; l < base + lanes; ++l)
          batch.frag_coord[3][l] = float(ip.perspective(sink.b1_[l], sink.b2_[l], w1[l], w2[l]));
        for (int j = 0; j < num_varyings; ++j) {
          float* __restrict out = batch.varyings[j];
          const float a = a0[j], e1 = d1[j], e2 = d2[j];
          if (sink.is_flat(j)) {  // the provoking vertex's bits, not a sum (see FragmentSink)
            for (int l = base; l < base + lanes; ++l) out[l] = a;
            continue;
          }
          for (int l = base; l < base + lanes; ++l) out[l] = PixelInterpolation::varying(a, e1, e2, w1[l], w2[l]);
        }
        for (int l = base; l < base + lanes; ++l) batch.front_facing[l] = t.front_facing;

        // Keep only quads with a live lane, and their vector's other quad for shades_whole_vectors.
        auto any_live = [&](int q) {
          const int l = base + 4 * q;
          return (batch.live[l] | batch.live[l + 1] | batch.live[l + 2] | batch.live[l + 3]) != 0;
        };
        int kept = batch.quads;
        for (int q = 0; q < seg_quads; ++q) {
          const int src = base + 4 * q;
          if (!any_live(q) && !(sink.vectors_ && any_live(q ^ 1))) continue;
          const int dst = 4 * kept++;
          if (dst != src) sink.move_quad(src, dst);
        }
        batch.quads = kept;
        if (batch.quads == kFragmentQuads) sink.flush();
      }
    }
    sink.shaded_ += passed;
    return passed;
  }
};

std::uint64_t raster_triangle(const SetupTriangle& t, const float* varyings, int num_varyings,
                              const PixelRect& rect, FragmentSink& sink) {
  const int x0 = std::max(rect.x0, t.min_x), x1 = std::min(rect.x1, t.max_x);
  const int y0 = std::max(rect.y0, t.min_y), y1 = std::min(rect.y1, t.max_y);
  if (x0 > x1 || y0 > y1) return 0;

  const PixelInterpolation ip(t);
  const float* __restrict a0 = varyings;
  const float* __restrict d1 = varyings + num_varyings;
  const float* __restrict d2 = varyings + 2 * num_varyings;
  Framebuffer& fb = sink.fb_;
  FragmentBatch& batch = sink.batch_;

  std::uint64_t passed = 0;
  if (t.small_mask) {
    // Coverage known from setup: the box's covered centers, quad by quad, so that a quad's
    // covered pixels shade together and, for a program that takes derivatives, its other lanes
    // run as helper invocations at their own pixel centres (see Scanner::rows).
    const int width = t.max_x - t.min_x + 1;
    for (int qy = t.min_y & ~1; qy <= t.max_y; qy += 2)
      for (int qx = t.min_x & ~1; qx <= t.max_x; qx += 2) {
        unsigned live = 0, computed = 0;  // lanes covered (and passing), lanes with b1, b2, z
        std::size_t idx[4] = {};
        double b1[4], b2[4];
        float z[4];
        for (int k = 0; k < 4; ++k) {
          const int x = qx + (k & 1), y = qy + (k >> 1);
          if (x < t.min_x || x > t.max_x || y < t.min_y || y > t.max_y) continue;
          if (!(t.small_mask & (1u << ((y - t.min_y) * width + (x - t.min_x))))) continue;
          if (x < x0 || x > x1 || y < y0 || y > y1) continue;
          ip.barycentrics(x, y, b1[k], b2[k]);
          z[k] = ip.depth(b1[k], b2[k]);
          computed |= 1u << k;
          idx[k] = fb.index(x, y);
          if (sink.early_test_) {
            const float stored = sink.stored_depth(z[k]);
            if (!sink.depth_passes(stored, fb.depth[idx[k]])) {
              ++sink.depth_failed_;
              continue;
            }
            if (sink.early_depth_write()) fb.depth[idx[k]] = stored;
          }
          live |= 1u << k;
        }
        if (!live) continue;
        if (batch.quads == kFragmentQuads) sink.flush();
        const int base = 4 * batch.quads++;
        for (int k = 0; k < 4; ++k) {
          const int lane = base + k, x = qx + (k & 1), y = qy + (k >> 1);
          batch.live[lane] = (live >> k) & 1u;
          if (!batch.live[lane] && !sink.helpers_) continue;  // nothing reads the lane
          if (!((computed >> k) & 1u)) {  // a helper lane: not covered, so not computed above
            ip.barycentrics(x, y, b1[k], b2[k]);
            z[k] = ip.depth(b1[k], b2[k]);
          }
          float w1, w2;
          batch.frag_coord[3][lane] = float(ip.perspective(b1[k], b2[k], w1, w2));
          for (int j = 0; j < num_varyings; ++j)
            batch.varyings[j][lane] = sink.is_flat(j) ? a0[j] : PixelInterpolation::varying(a0[j], d1[j], d2[j], w1, w2);
          batch.frag_coord[0][lane] = float(x) + 0.5f;
          batch.frag_coord[1][lane] = float(y) + 0.5f;
          batch.frag_coord[2][lane] = z[k];
          batch.front_facing[lane] = t.front_facing;
          if (batch.live[lane]) {
            sink.pixel_[lane] = idx[k];
            ++passed;
          }
        }
      }
    if (batch.quads == kFragmentQuads) sink.flush();
    sink.shaded_ += passed;
    return passed;
  }
  const TriangleEdges te(t.x, t.y);
  return Scanner::rows(t, varyings, num_varyings, x0, x1, y0, y1, sink,
                       [&](int lo, int hi, int y) { return row_span(te.e, lo, hi, y); });
}

std::uint64_t raster_quad(const SetupQuad& q, const float* varyings, int num_varyings,
                          const PixelRect& rect, FragmentSink& sink) {
  const SetupTriangle& t = q.t;
  const int x0 = std::max(rect.x0, t.min_x), x1 = std::min(rect.x1, t.max_x);
  const int y0 = std::max(rect.y0, t.min_y), y1 = std::min(rect.y1, t.max_y);
  if (x0 > x1 || y0 > y1) return 0;
  return Scanner::rows(t, varyings, num_varyings, x0, x1, y0, y1, sink,
                       [&](int lo, int hi, int y) { return quad_row_span(q.plane, lo, hi, y); });
}

void FragmentSink::move_quad(int src, int dst) {
  for (int k = 0; k < 4; ++k) {
    for (int c = 0; c < 4; ++c) batch_.frag_coord[c][dst + k] = batch_.frag_coord[c][src + k];
    for (int j = 0; j < batch_.num_varyings; ++j)
      batch_.varyings[j][dst + k] = batch_.varyings[j][src + k];
    batch_.live[dst + k] = batch_.live[src + k];
    batch_.front_facing[dst + k] = batch_.front_facing[src + k];
    pixel_[dst + k] = pixel_[src + k];
  }
}

}  // namespace tessref::raster

namespace tessref {

void FragmentProgram::shade_batch(FragmentBatch& batch) const {
  float varyings[kMaxVaryings] = {};  // slots past num_varyings read as 0
  FragmentInput in;
  in.varyings = varyings;
  const int lanes = batch.lanes();
  for (int l = 0; l < lanes; ++l) {
    if (!batch.live[l]) continue;
    for (int j = 0; j < batch.num_varyings; ++j) varyings[j] = batch.varyings[j][l];
    in.frag_coord = glm::vec4(batch.frag_coord[0][l], batch.frag_coord[1][l],
                              batch.frag_coord[2][l], batch.frag_coord[3][l]);
    in.front_facing = batch.front_facing[l] != 0;
    const FragmentOutput out = shade(in);
    for (int c = 0; c < 4; ++c) {
      batch.color[c][l] = out.color[c];
      batch.aux[c][l] = out.aux[c];
    }
  }
}

}  // namespace tessref
