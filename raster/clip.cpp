#include "raster/clip.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tessref::raster {
namespace {

using namespace outcode;
constexpr int kViewPlanes = 6;  // the first six bits
constexpr int kPlanes = kViewPlanes + kMaxUserPlanes;

// Plane i's outcode bit: the view planes' bits 0-5, then the user planes'.
constexpr std::uint32_t plane_bit(int i) {
  return i < kViewPlanes ? 1u << i : kUserPlane0 << (i - kViewPlanes);
}

struct Planes {
  float gx, gy;
  UserPlanes user;
  // Signed distance to plane i; >= 0 is inside. clip_outcode (clip.h) tests the same expressions
  // for the view planes; a user plane's is the vertex's gl_ClipDistance, interpolated like a
  // varying at the vertices clipping makes.
  float distance(int i, const ClipRecord& r) const {
    if (i >= kViewPlanes) return user.distance(i - kViewPlanes, r.position, r.varyings.data());
    const glm::vec4& p = r.position;
    switch (i) {
      case 0: return gx * p.w - p.x;
      case 1: return p.x + gx * p.w;
      case 2: return gy * p.w - p.y;
      case 3: return p.y + gy * p.w;
      case 4: return p.z + p.w;
      default: return p.w - p.z;
    }
  }
};

bool finite(const glm::vec4& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// The cut point of edge in-out, as Mesa's draw clipper computes it (draw_pipe_clip.c, plain float
// C): out + t (in - out) with t = d_out / (d_out - d_in), always from the outside vertex, so that
// an edge shared by two triangles is cut at bit-identical points.
ClipRecord cut(const ClipRecord& in, const ClipRecord& out, float d_in, float d_out,
               int num_varyings) {
  const float t = d_out / (d_out - d_in);
  ClipRecord r;
  r.position = out.position + t * (in.position - out.position);
  for (int k = 0; k < num_varyings; ++k)
    r.varyings[k] = out.varyings[k] + t * (in.varyings[k] - out.varyings[k]);
  return r;
}

// One Sutherland-Hodgman pass against plane i.
// generated[k]: whether vertex k was made by clipping (it then gets Mesa's unfused viewport
// transform, see setup.cpp).
// boundary: per vertex, whether its edge to the next vertex lies on an input edge.
// Returns -1 when a distance is infinite or NaN: Mesa's clipper then discards the primitive.
int clip_against(const Planes& planes, int i, const ClipRecord* src, const bool* src_generated,
                 const bool* src_boundary, int n, ClipRecord* dst, bool* dst_generated,
                 bool* dst_boundary, int num_varyings) {
  const bool user_plane = i >= kViewPlanes;
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const ClipRecord& cur = src[k];
    const ClipRecord& next = src[(k + 1) % n];
    float dc = planes.distance(i, cur);
    float dn = planes.distance(i, next);
    if (user_plane && (!std::isfinite(dc) || !std::isfinite(dn))) return -1;
    bool cur_in = dc >= 0.0f;
    bool next_in = dn >= 0.0f;
    if (cur_in) {
      dst_generated[m] = src_generated[k];
      dst_boundary[m] = src_boundary[k];
      dst[m++] = cur;
    }
    if (cur_in != next_in) {
      dst_generated[m] = true;
      // Leaving: the edge from the exit point runs along the plane, an edge for a user plane only
      // (Mesa follows NVIDIA there). Entering: the rest of k's edge.
      dst_boundary[m] = cur_in ? user_plane : src_boundary[k];
      dst[m++] = cur_in ? cut(cur, next, dc, dn, num_varyings) : cut(next, cur, dn, dc, num_varyings);
    }
  }
  return m;
}

}  // namespace

ClipTest classify_triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                           float guard_x, float guard_y) {
  return classify_outcodes(clip_outcode(a, guard_x, guard_y), clip_outcode(b, guard_x, guard_y),
                           clip_outcode(c, guard_x, guard_y));
}

ClipResult clip_triangle(const float* a, const float* b, const float* c, int num_varyings,
                         float guard_x, float guard_y, ClipPolygon& out, std::uint32_t outcode_mask,
                         const UserPlanes& user) {
  num_varyings = std::clamp(num_varyings, 0, kMaxVaryings);
  const float* in[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    out.v[k].position = glm::vec4(in[k][0], in[k][1], in[k][2], in[k][3]);
    std::copy_n(in[k] + 4, num_varyings, out.v[k].varyings.begin());
  }
  const glm::vec4 &pa = out.v[0].position, &pb = out.v[1].position, &pc = out.v[2].position;
  if (!finite(pa) || !finite(pb) || !finite(pc)) return ClipResult::kInvalid;
  const Planes planes{guard_x, guard_y, user};
  // The plane and viewport-side bits of clip_outcode (w <= 0 is handled after clipping).
  const std::uint32_t mask = outcode_mask & ~kNonPositiveW;
  const std::uint32_t ca = (clip_outcode(pa, guard_x, guard_y) & mask) | user_outcode(a, user);
  const std::uint32_t cb = (clip_outcode(pb, guard_x, guard_y) & mask) | user_outcode(b, user);
  const std::uint32_t cc = (clip_outcode(pc, guard_x, guard_y) & mask) | user_outcode(c, user);
  if (ca & cb & cc) return ClipResult::kRejected;

  const std::uint32_t to_clip = (ca | cb | cc) & kClipPlanes;
  out.count = 3;
  out.generated = {};
  out.boundary.fill(true);
  if (to_clip) {
    std::array<ClipRecord, kMaxClipVertices> tmp;
    std::array<bool, kMaxClipVertices> tmp_generated{}, tmp_boundary{};
    for (int i = 0; i < kPlanes && out.count >= 3; ++i) {
      if (!(to_clip & plane_bit(i))) continue;
      int n = clip_against(planes, i, out.v.data(), out.generated.data(), out.boundary.data(),
                           out.count, tmp.data(), tmp_generated.data(), tmp_boundary.data(),
                           num_varyings);
      if (n < 0) return ClipResult::kInvalid;
      for (int k = 0; k < n; ++k) {
        out.v[k] = tmp[k];
        out.generated[k] = tmp_generated[k];
        out.boundary[k] = tmp_boundary[k];
      }
      out.count = n;
    }
    if (out.count < 3) return ClipResult::kRejected;
  }
  // The near and far planes together leave only w >= 0; w == 0 (the eye point) must not be divided
  // by, and a huge or non-finite result of interpolation is dropped too.
  for (int k = 0; k < out.count; ++k) {
    if (!(out.v[k].position.w > 0.0f) || !finite(out.v[k].position)) return ClipResult::kInvalid;
  }
  return ClipResult::kKept;
}

ClipResult clip_line(const float* a, const float* b, int num_varyings, float guard_x,
                     float guard_y, ClipRecord out[2], bool generated[2], std::uint32_t outcode_mask,
                     const UserPlanes& user) {
  num_varyings = std::clamp(num_varyings, 0, kMaxVaryings);
  const float* in[2] = {a, b};
  for (int k = 0; k < 2; ++k) {
    out[k].position = glm::vec4(in[k][0], in[k][1], in[k][2], in[k][3]);
    std::copy_n(in[k] + 4, num_varyings, out[k].varyings.begin());
    generated[k] = false;
  }
  const ClipRecord v0 = out[0], v1 = out[1];
  if (!finite(v0.position) || !finite(v1.position)) return ClipResult::kInvalid;
  const Planes planes{guard_x, guard_y, user};
  const std::uint32_t c0 =
      (clip_outcode(v0.position, guard_x, guard_y) & outcode_mask & ~kNonPositiveW) | user_outcode(a, user);
  const std::uint32_t c1 =
      (clip_outcode(v1.position, guard_x, guard_y) & outcode_mask & ~kNonPositiveW) | user_outcode(b, user);
  if (c0 & c1) return ClipResult::kRejected;
  const std::uint32_t to_clip = (c0 | c1) & kClipPlanes;
  float t0 = 0.0f, t1 = 0.0f;
  for (int i = 0; i < kPlanes; ++i) {
    if (!(to_clip & plane_bit(i))) continue;
    const float d0 = planes.distance(i, v0), d1 = planes.distance(i, v1);
    if (i >= kViewPlanes && (!std::isfinite(d0) || !std::isfinite(d1))) return ClipResult::kInvalid;
    if (d1 < 0.0f) t1 = std::max(t1, d1 / (d1 - d0));
    if (d0 < 0.0f) t0 = std::max(t0, d0 / (d0 - d1));
    if (t0 + t1 >= 1.0f) return ClipResult::kRejected;
  }
  auto lerp = [&](ClipRecord& dst, float t, const ClipRecord& from, const ClipRecord& to) {
    dst.position = from.position + t * (to.position - from.position);
    for (int k = 0; k < num_varyings; ++k)
      dst.varyings[k] = from.varyings[k] + t * (to.varyings[k] - from.varyings[k]);
  };
  if (c0 & kClipPlanes) {
    lerp(out[0], t0, v0, v1);
    generated[0] = true;
  }
  if (c1 & kClipPlanes) {
    lerp(out[1], t1, v1, v0);
    generated[1] = true;
  }
  for (int k = 0; k < 2; ++k)
    if (!(out[k].position.w > 0.0f) || !finite(out[k].position)) return ClipResult::kInvalid;
  return ClipResult::kKept;
}

}  // namespace tessref::raster
