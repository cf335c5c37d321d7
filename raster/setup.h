#pragma once
// Perspective divide, viewport transform, sub-pixel snapping and triangle setup.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raster/clip.h"
#include "raster/project_kernel.h"
#include "raster/rasterizer.h"
#include "raster/triage.h"

namespace tessref::raster {

// A triangle ready to scan: wound counter-clockwise in window space (y up).
struct SetupTriangle {
  // Held per tile pass for every triangle that covers a pixel centre, so kept small: the scan
  // needs no unsnapped positions (the interpolation planes below hold them) and no area.
  std::int32_t x[3], y[3];         // window coordinates, 24.8 fixed point
  float z[3];                      // window depth, already in the depth range
  // Barycentric weights of vertices 1 and 2 as planes through the unsnapped window positions
  // (where llvmpipe fits depth and varyings): b_k(x, y) = bk_dx (x - b_x0) + bk_dy (y - b_y0).
  // Depth (clamped to [z_lo, z_hi]) and varyings are interpolated with them; coverage uses the
  // snapped edges.
  double b_x0, b_y0, b1_dx, b1_dy, b2_dx, b2_dy;
  float z_lo, z_hi;
  float inv_w[3];                  // 1 / clip w, for perspective-correct varyings
  int min_x, min_y, max_x, max_y;  // pixels whose centers may be covered, inclusive, on screen
  bool front_facing;
  // Small triangles (bounding box of at most kSmallTrianglePixels pixels): which pixel centers of
  // the box are covered, bit k for pixel (min_x + k % width, min_y + k / width), found during
  // setup; the scan then needs no edge functions. 0 for other triangles.
  std::uint8_t small_mask;
  // 3 * num_varyings floats in the owner's varying store: vertex 0's values, then the
  // differences a1 - a0 and a2 - a0 (a constant varying then interpolates exactly).
  std::uint32_t varying_offset;
};

// The viewport transform and the framebuffer it draws into.
struct Viewport {
  int width = 0, height = 0;  // the framebuffer: coverage is cut to it (and to the scissor box)
  double depth_near = 0.0, depth_far = 1.0;
  // glViewport(x, y, w, h); w = 0: the whole framebuffer.
  int x = 0, y = 0, w = 0, h = 0;
  float guard_x() const;  // clip-space guard plane factors, see clip_triangle
  float guard_y() const;
  // GL 4.5, 13.6.1: x_w = (w/2) x_ndc + (x + w/2), z_w = ((f - n)/2) z_ndc + (n + f)/2, with the
  // factors as Mesa forms them (_mesa_get_viewport_xform): w/2 and x + w/2 in float, the depth
  // ones in double rounded to float.
  float scale_x() const { return 0.5f * float(w ? w : width); }
  float scale_y() const { return 0.5f * float(w ? h : height); }
  float translate_x() const { return scale_x() + float(w ? x : 0); }
  float translate_y() const { return scale_y() + float(w ? y : 0); }
  float scale_z() const { return float(0.5 * (depth_far - depth_near)); }
  float translate_z() const { return float(0.5 * (depth_near + depth_far)); }
  float depth_lo() const { return float(std::min(depth_near, depth_far)); }
  float depth_hi() const { return float(std::max(depth_near, depth_far)); }
  // GL_DEPTH_CLAMP: the near and far planes do not clip, so a vertex's window z may leave the
  // depth range, and gl_FragCoord.z is not clamped: the depth test clamps (raster/tile_raster.h).
  bool depth_clamp = false;
  float vertex_z_lo() const { return depth_clamp ? -INFINITY : depth_lo(); }
  float vertex_z_hi() const { return depth_clamp ? INFINITY : depth_hi(); }
  std::uint32_t outcode_mask() const { return depth_clamp ? ~(outcode::kNear | outcode::kFar) : ~0u; }
  // The enabled user planes the program writes a distance for (GL leaves an enabled plane without
  // one undefined: it does not clip), and the cull distances, which need no enable.
  UserPlanes user{};
  int cull_first = 0, cull_count = 0;
  template <int N>
  bool culled(const float* const (&varyings)[N]) const {
    return cull_count > 0 && culled_by_distance(varyings, cull_first, cull_count);
  }
  static Viewport of(int fb_width, int fb_height, const RasterState& state) {
    Viewport v;
    v.width = fb_width, v.height = fb_height;
    v.depth_near = state.depth_range_near, v.depth_far = state.depth_range_far;
    v.depth_clamp = state.depth_clamp;
    const DistanceVaryings& d = state.distances;
    v.user = {state.clipping_distances(), d.clip_first};
    // Without gl_ClipDistance: glClipPlane's planes against the clip vertex.
    if (d.clip_count == 0 && state.clip_distances)
      v.user = {state.clip_distances, 0, state.clip_planes.data(), d.clip_vertex_first};
    v.cull_first = d.cull_first;
    v.cull_count = std::clamp(d.cull_count, 0, kMaxUserPlanes);
    if (state.viewport) {
      v.x = state.viewport->x, v.y = state.viewport->y;
      v.w = state.viewport->width, v.h = state.viewport->height;
    }
    return v;
  }
};

// Which faces are culled, and which winding is the front (RasterState's culling).
struct FaceRule {
  bool cull_front = false, cull_back = false, front_cw = false;
  bool front(bool ccw) const { return ccw != front_cw; }
  bool culled(bool ccw) const { return front(ccw) ? cull_front : cull_back; }
  static FaceRule of(const RasterState& s) { return {s.cull_front_faces, s.cull_back_faces, s.front_face_cw}; }
};

// What became of one input triangle.
enum class SetupOutcome { kClippedAway, kCulled, kRasterized };

// Projects every vertex (ProjectedVertex, project_kernel.h): the AVX2 + FMA kernel where the CPU
// has it and simd_path() is AVX2, else the portable code; the same bits either way.
// `records`: ClipVertex records per vertex (TriangleBatch::records).
void project_vertices(const ClipVertex* vertices, std::size_t count, int records,
                      const Viewport& vp, ProjectedVertex* out);

// One clip-space position through the perspective divide and the viewport transform, as the
// triangle setup projects it; generated: a vertex made by clipping (Mesa's unfused arithmetic).
// The position must be finite with w > 0.
ProjectedVertex project_position(const glm::vec4& position, const Viewport& vp, bool generated);

// Sets up triangle `index` of batch, whose vertices were projected into `projected` (indexed like
// batch.vertices): clips it if needed and appends its pieces (0 to 7 triangles) to tris, their
// varyings to varyings. pieces_out receives the number of pieces set up; a piece whose bounding
// box holds no pixel center (most triangles of a fine tessellation) counts but is not stored, as
// it cannot produce a fragment.
SetupOutcome setup_triangle(const TriangleBatch& batch, std::size_t index,
                            const ProjectedVertex* projected, const Viewport& vp,
                            FaceRule faces, std::vector<SetupTriangle>& tris,
                            std::vector<float>& varyings, int& pieces_out);
// The same, projecting the triangle's three corners on the fly (for tools and tests).
SetupOutcome setup_triangle(const TriangleBatch& batch, std::size_t index, const Viewport& vp,
                            FaceRule faces, std::vector<SetupTriangle>& tris,
                            std::vector<float>& varyings, int& pieces_out);

}  // namespace tessref::raster
