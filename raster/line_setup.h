#pragma once
// Line and point setup: a line or a point becomes a convex quadrilateral of four half-planes in
// 24.8 fixed point, found with the arithmetic llvmpipe uses (lp_setup_line.c: the diamond-exit
// rule for 1-pixel lines; lp_setup_point.c: points as squares), so that the pixels are llvmpipe's.
#include <cstdint>

#include "common/fixed_point.h"
#include "raster/setup.h"

namespace tessref::raster {

// Half-plane E(X, Y) = c - dcdx * 256 X + dcdy * 256 Y of pixel (X, Y) (integers: llvmpipe snaps
// x_w - 0.5, so pixel centers sit on whole pixels); inside when E > 0 for all four.
struct HalfPlane {
  std::int64_t c, dcdx, dcdy;
  std::int64_t at(int px, int py) const {
    return c - dcdx * fixed::kSubpixelOne * px + dcdy * fixed::kSubpixelOne * py;
  }
};

// A set-up line or point: its coverage planes, and a SetupTriangle that holds the box of
// candidate pixels, depth and varying interpolation (a line interpolates from corner 0 to corner
// 1 along its major axis, as llvmpipe's line coefficients do; corner 2 repeats corner 0 with
// weight 0; a point's values are constant).
struct SetupQuad {
  SetupTriangle t;
  HalfPlane plane[4];
};

// A vertex in window coordinates (before snapping), as projected.
struct LineVertex {
  float x, y;   // window coordinates
  float z;      // window depth, in the depth range
  float inv_w;  // 1 / clip w
  const float* varyings;
};

// Sets up the line a -> b (1 pixel wide) and appends it with its varyings (3 * num_varyings: a's
// values, b - a, 0) unless no pixel can be covered. flat: provoking vertex's values for the flat
// varyings (b, the last), or null. Returns whether it was stored.
bool setup_line(const LineVertex& a, const LineVertex& b, const Viewport& vp, int num_varyings,
                const VaryingMask* flat, std::vector<SetupQuad>& quads,
                std::vector<float>& varyings);

// A point of size 1 (GL's default; no program here writes gl_PointSize): the pixel centers
// inside the 1 x 1 square around it, left and bottom sides inclusive.
bool setup_point(const LineVertex& p, const Viewport& vp, int num_varyings,
                 std::vector<SetupQuad>& quads, std::vector<float>& varyings);

// Line `index` of batch (its vertices projected into `projected`, indexed like batch.vertices):
// clipped in clip space if it crosses a plane (clip_line), then set up. pieces_out: 1 when set up.
SetupOutcome setup_line(const LineBatch& batch, std::size_t index, const ProjectedVertex* projected,
                        const Viewport& vp, std::vector<SetupQuad>& quads,
                        std::vector<float>& varyings, int& pieces_out);
// Point `index`: drawn when its vertex lies inside the view volume (Mesa's clipper drops points
// outside any plane), else clipped away.
SetupOutcome setup_point(const PointBatch& batch, std::size_t index,
                         const ProjectedVertex* projected, const Viewport& vp,
                         std::vector<SetupQuad>& quads, std::vector<float>& varyings,
                         int& pieces_out);

// glPolygonMode(GL_FRONT_AND_BACK, GL_LINE or GL_POINT) on triangle `index`, in the order of
// Mesa's draw pipeline: culled by the sign of its window-space area (float, as the draw module's
// cull stage; zero area culled only when culling), clipped, then its edges v2 -> v0, v0 -> v1,
// v1 -> v2 set up as lines (edges made by clipping are not drawn), or its corners as points.
SetupOutcome setup_triangle_outline(const TriangleBatch& batch, std::size_t index,
                                    const ProjectedVertex* projected, const Viewport& vp,
                                    FaceRule faces, PolygonMode mode,
                                    std::vector<SetupQuad>& quads, std::vector<float>& varyings,
                                    int& pieces_out);

}  // namespace tessref::raster
