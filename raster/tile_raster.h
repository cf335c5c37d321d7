#pragma once
// Scan conversion of one set-up triangle inside one screen rectangle (a tile).
#include <cstdint>

#include "raster/line_setup.h"
#include "raster/setup.h"

namespace tessref::raster {

struct PixelRect {
  int x0, y0, x1, y1;  // inclusive
};

// Collects the fragments of one tile's triangles into quad batches and shades them batch by
// batch. Depth is tested and written as fragments arrive (for programs that may discard: tested
// on arrival against what is written, tested again and written after shading), so a later
// triangle is tested against an earlier one's depth even in the same batch; colors are written in
// arrival order when a batch is shaded, so the last fragment to pass wins, as in submission order.
class FragmentSink {
 public:
  // state: the depth test (off: every covered fragment is shaded and depth is neither tested nor
  // written, as glDisable(GL_DEPTH_TEST)), its function and write mask, blending and the colour
  // mask. The scissor is applied by the caller (the rectangles it scans).
  // flat: varyings passed to the fragments as the provoking vertex's bits, not interpolated (an
  // integer's bit pattern could be a NaN or -0.0 as a float); null: none.
  FragmentSink(const FragmentProgram& fs, Framebuffer& fb, int num_varyings, const RasterState& state,
               const VaryingMask* flat = nullptr);
  // Callers flush() when done: a fragment program may throw (a runaway shader), which a
  // destructor must not.
  void flush();
  std::uint64_t shaded() const { return shaded_; }
  std::uint64_t depth_failed() const { return depth_failed_; }
  bool is_flat(int varying) const { return flat_ && (*flat_)[std::size_t(varying)]; }

 private:
  friend std::uint64_t raster_triangle(const SetupTriangle&, const float*, int, const PixelRect&,
                                       FragmentSink&);
  friend struct Scanner;
  void move_quad(int src_lane, int dst_lane);  // lanes src..src+3 to dst..dst+3
  const VaryingMask* flat_;
  const FragmentProgram& fs_;
  Framebuffer& fb_;
  int draw_buffers_;  // fb's draw buffers 0 .. draw_buffers_ - 1 (some may be absent)
  DepthFormat depth_format_;  // fragment depths are converted to it before the test
  bool depth_write_;
  DepthFunc depth_func_;
  bool late_depth_;  // depth written after shading (the program may discard or write gl_FragDepth)
  bool early_test_;  // the interpolated depth tested before shading (not with gl_FragDepth)
  bool shader_depth_;  // the depth tested is gl_FragDepth
  bool helpers_;     // lanes that cover nothing get their own inputs (the program reads quads)
  bool vectors_;     // a vector's uncovered quad is shaded with its covered one (shades_whole_vectors)
  BlendState blend_;
  ColorMask color_mask_;
  bool srgb_write_;
  bool depth_clamp_;
  float clamp_lo_, clamp_hi_;  // the depth range, low end first
  glm::vec4* targets_[kMaxDrawBuffers] = {};  // each draw buffer's pixels (null: absent)
  bool plain_ = true;  // every present buffer RGBA32F, no blending, full colour mask
  // The depth buffer's value for a fragment's window z: with GL_DEPTH_CLAMP clamped to the depth
  // range first (ARB_depth_clamp: before the test; gl_FragCoord.z keeps the unclamped z), then
  // converted to the buffer's format (GL 4.6 13.8.1).
  float stored_depth(float z) const {
    if (depth_clamp_) z = z < clamp_lo_ ? clamp_lo_ : (clamp_hi_ < z ? clamp_hi_ : z);
    return tessref::stored_depth(depth_format_, z);
  }
  // gl_FragDepth's value in the buffer: clamped to [0, 1] (GL requires it for a fixed-point buffer;
  // llvmpipe clamps a GL_DEPTH_COMPONENT32F one too, whatever the depth range: measured), to the
  // depth range with GL_DEPTH_CLAMP, then converted as a window z is (GL 4.6 15.2.3, 13.8.1).
  float shader_depth(float z) const {
    z = z < 0.0f ? 0.0f : (1.0f < z ? 1.0f : z);  // NaN stays NaN, and fails every test but
    return stored_depth(z);                        // GL_ALWAYS and GL_NOTEQUAL
  }
  // GL_LESS, the common case, without the switch.
  bool depth_passes(float z, float stored) const {
    return depth_func_ == DepthFunc::kLess ? z < stored : tessref::depth_passes(depth_func_, z, stored);
  }
  bool early_depth_write() const { return depth_write_ && !late_depth_; }
  std::uint64_t shaded_ = 0;
  std::uint64_t depth_failed_ = 0;
  // The lanes live in per-thread storage, set up once per thread rather than once per tile (a
  // thread scans one tile at a time, so one sink per thread is alive at a time).
  struct Lanes;
  static Lanes& thread_lanes(int num_varyings);
  Lanes& lanes_;
  FragmentBatch& batch_;
  std::size_t* pixel_;  // framebuffer index of each lane
  double* b1_;          // barycentrics of the lanes being filled
  double* b2_;
};

// Sends the pixels of rect whose centers the triangle covers (fill rule in common/fixed_point.h)
// and that pass the depth test LESS to sink; returns how many passed. varyings: the triangle's
// 3 * num_varyings values as SetupTriangle stores them. The result for a pixel does not depend
// on rect.
std::uint64_t raster_triangle(const SetupTriangle& t, const float* varyings, int num_varyings,
                              const PixelRect& rect, FragmentSink& sink);

// False when no pixel center of rect can be inside t (every center is outside one edge): lets the
// binner skip tiles that a large triangle's bounding box overlaps but the triangle misses. Exact
// and conservative: true whenever raster_triangle would cover a pixel of rect.
bool triangle_may_cover(const SetupTriangle& t, const PixelRect& rect);

// The same for a set-up line or point (line_setup.h): its covered pixels of rect, in the order
// raster_triangle sends them.
std::uint64_t raster_quad(const SetupQuad& q, const float* varyings, int num_varyings,
                          const PixelRect& rect, FragmentSink& sink);
bool quad_may_cover(const SetupQuad& q, const PixelRect& rect);

}  // namespace tessref::raster
