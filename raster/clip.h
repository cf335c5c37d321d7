#pragma once
// Clip-space clipping of one triangle (GL 4.6 section 13.7) against the six planes of the view
// volume (guard factors 1: Viewport::guard_x/y), with the plane order and float arithmetic of
// Mesa's draw clipper (draw_pipe_clip.c), so that the cut vertices, and the pixels, are llvmpipe's.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "raster/project_kernel.h"
#include "raster/vertex.h"

namespace tessref::raster {

// The user clip planes: gl_ClipDistance[0..7] (GL_MAX_CLIP_DISTANCES).
inline constexpr int kMaxUserPlanes = 8;

// Three vertices, each of near, far, the four guard planes and the user planes can add at most
// one more.
inline constexpr int kMaxClipVertices = 3 + 6 + kMaxUserPlanes;

// The user clip planes a draw clips against: bit i of mask for gl_ClipDistance[i], which each
// vertex carries as varying first + i (DistanceVaryings); or, with planes (glClipPlane), the
// distance dot(clip vertex, planes[i]), the clip vertex being the 4 varyings from `vertex`, or
// gl_Position when vertex < 0.
struct UserPlanes {
  std::uint32_t mask = 0;
  int first = 0;
  const glm::vec4* planes = nullptr;
  int vertex = -1;
  float distance(int i, const glm::vec4& position, const float* varyings) const {
    if (!planes) return varyings[first + i];
    const glm::vec4 v = vertex < 0 ? position : glm::vec4(varyings[vertex], varyings[vertex + 1],
                                                          varyings[vertex + 2], varyings[vertex + 3]);
    const glm::vec4& p = planes[i];
    return v.x * p.x + v.y * p.y + v.z * p.z + v.w * p.w;  // Mesa's dot4, in this order
  }
};

// The user-plane outcode bits of one vertex (gl_Position, then its varyings): outside is a negative
// distance, and, as Mesa's draw module tests it, an infinite or NaN one (such a primitive is then
// dropped whole).
inline std::uint32_t user_outcode(const float* vertex, const UserPlanes& user) {
  std::uint32_t code = 0;
  const glm::vec4 position(vertex[0], vertex[1], vertex[2], vertex[3]);
  for (std::uint32_t m = user.mask; m; m &= m - 1) {
    const int i = std::countr_zero(m);
    const float d = user.distance(i, position, vertex + 4);
    if (!(d >= 0.0f) || std::isinf(d)) code |= outcode::kUserPlane0 << i;
  }
  return code;
}

// gl_CullDistance (GL 4.6 13.7): a primitive is discarded when, for some cull distance, every
// vertex's is negative (NaN and infinities count as negative, as Mesa's cull stage has them).
template <int N>
bool culled_by_distance(const float* const (&varyings)[N], int first, int count) {
  for (int j = 0; j < count; ++j) {
    bool all_out = true;
    for (int k = 0; k < N && all_out; ++k) {
      const float d = varyings[k][first + j];
      all_out = !(d >= 0.0f) || std::isinf(d);
    }
    if (all_out) return true;
  }
  return false;
}

// A vertex of the clipped polygon: position and every varying a vertex can carry.
struct ClipRecord {
  glm::vec4 position{0.0f};
  std::array<float, kMaxVaryings> varyings;
};

struct ClipPolygon {
  int count = 0;
  std::array<ClipRecord, kMaxClipVertices> v;
  std::array<bool, kMaxClipVertices> generated{};  // made by clipping, not an input vertex
  // Edge k -> k + 1 lies on an input edge (false: made by clipping, along a clip plane). Mesa's
  // clipper clears the edge flags of such edges, so polygon mode line does not draw them.
  std::array<bool, kMaxClipVertices> boundary{};
};

enum class ClipResult {
  kInvalid,   // a non-finite position, or a piece that would reach w <= 0: dropped
  kRejected,  // wholly outside one plane of the view volume
  kKept,      // out.count >= 3 vertices, all with finite positions and w > 0
};

enum class ClipTest {
  kInvalid,    // a non-finite position, or w <= 0 with nothing to clip
  kRejected,   // wholly outside one plane of the view volume
  kInside,     // inside near, far and the guard band: no clipping needed, all w > 0
  kNeedsClip,  // crosses near, far or a guard plane
};

// The outcode test alone (cheap; most triangles need no clipping).
ClipTest classify_triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                           float guard_x, float guard_y);

// The same test split into a per-vertex part and a per-triangle part, so that a vertex shared by
// several triangles is classified once: classify_outcodes(clip_outcode(a), clip_outcode(b),
// clip_outcode(c)) == classify_triangle(a, b, c).
// Outcode bits: raster/project_kernel.h (namespace outcode).

// The signed distances are those the clipper cuts with (clip.cpp, Planes::distance), term for term.
inline std::uint32_t clip_outcode(const glm::vec4& p, float guard_x, float guard_y) {
  using namespace outcode;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w))
    return kNonFinite;
  std::uint32_t code = 0;
  if (guard_x * p.w - p.x < 0.0f) code |= kGuardRight;
  if (p.x + guard_x * p.w < 0.0f) code |= kGuardLeft;
  if (guard_y * p.w - p.y < 0.0f) code |= kGuardTop;
  if (p.y + guard_y * p.w < 0.0f) code |= kGuardBottom;
  if (p.z + p.w < 0.0f) code |= kNear;
  if (p.w - p.z < 0.0f) code |= kFar;
  if (p.x < -p.w) code |= kLeft;
  if (p.x > p.w) code |= kRight;
  if (p.y < -p.w) code |= kBottom;
  if (p.y > p.w) code |= kTop;
  if (!(p.w > 0.0f)) code |= kNonPositiveW;
  return code;
}

inline ClipTest classify_outcodes(std::uint32_t ca, std::uint32_t cb, std::uint32_t cc) {
  using namespace outcode;
  if ((ca | cb | cc) & kNonFinite) return ClipTest::kInvalid;
  if (ca & cb & cc & ~kNonPositiveW) return ClipTest::kRejected;
  if ((ca | cb | cc) & kClipPlanes) return ClipTest::kNeedsClip;
  // Inside near and far means w >= 0; w == 0 (the eye point) must not be divided by.
  if ((ca | cb | cc) & kNonPositiveW) return ClipTest::kInvalid;
  return ClipTest::kInside;
}

// True when a vertex with this outcode may be a corner of a kInside triangle (finite, w > 0,
// inside every clipping plane): only then is its window position computed.
inline bool outcode_projectable(std::uint32_t code) {
  using namespace outcode;
  return (code & (kNonFinite | kNonPositiveW | kClipPlanes)) == 0;
}

// guard_x, guard_y: the guard planes are x = +-guard_x * w and y = +-guard_y * w, in clip space
// (>= 1; Viewport gives 1: llvmpipe clips at the viewport sides).
// a, b, c: each vertex's floats, gl_Position then num_varyings varyings
// (TriangleBatch::vertex_data).
// outcode_mask: the outcode bits that apply (Viewport::outcode_mask: without the near and far
// planes under GL_DEPTH_CLAMP).
// user: the user planes, clipped against after the six others, in order of i, as Mesa does; an
// edge cut along a user plane stays a boundary edge (Mesa draws it in polygon mode line).
ClipResult clip_triangle(const float* a, const float* b, const float* c, int num_varyings,
                         float guard_x, float guard_y, ClipPolygon& out, std::uint32_t outcode_mask = ~0u,
                         const UserPlanes& user = {});
inline ClipResult clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                                int num_varyings, float guard_x, float guard_y, ClipPolygon& out) {
  return clip_triangle(&a.position.x, &b.position.x, &c.position.x,
                       std::min(num_varyings, kRecordVaryings), guard_x, guard_y, out);
}

// Clips the line a -> b (each gl_Position then num_varyings varyings) as Mesa's draw clipper
// does (draw_pipe_clip.c, do_clip_line): per plane crossed, the fraction cut from each end, both
// from the unclipped ends; a cut end is a + t0 (b - a) or b + t1 (a - b). out[0], out[1] are the
// kept ends, generated[k] whether end k was cut.
ClipResult clip_line(const float* a, const float* b, int num_varyings, float guard_x,
                     float guard_y, ClipRecord out[2], bool generated[2], std::uint32_t outcode_mask = ~0u,
                     const UserPlanes& user = {});

}  // namespace tessref::raster
