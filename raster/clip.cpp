#include "raster/clip.h"

#include <cmath>
#include <cstdint>

namespace tessref::raster {
namespace {

// Outcode bits: planes that clip (near, far, guard band) and the viewport sides, which only reject.
enum : std::uint32_t {
  kNear = 1u << 0,
  kFar = 1u << 1,
  kGuardLeft = 1u << 2,
  kGuardRight = 1u << 3,
  kGuardBottom = 1u << 4,
  kGuardTop = 1u << 5,
  kLeft = 1u << 6,
  kRight = 1u << 7,
  kBottom = 1u << 8,
  kTop = 1u << 9,
};
constexpr int kClipPlaneCount = 6;  // the first six bits

struct Planes {
  float gx, gy;
  // Signed distance to plane i (bit 1 << i); >= 0 is inside.
  float distance(int i, const glm::vec4& p) const {
    switch (i) {
      case 0: return p.z + p.w;
      case 1: return p.w - p.z;
      case 2: return p.x + gx * p.w;
      case 3: return gx * p.w - p.x;
      case 4: return p.y + gy * p.w;
      default: return gy * p.w - p.y;
    }
  }
  std::uint32_t outcode(const glm::vec4& p) const {
    std::uint32_t code = 0;
    for (int i = 0; i < kClipPlaneCount; ++i)
      if (distance(i, p) < 0.0f) code |= 1u << i;
    if (p.x < -p.w) code |= kLeft;
    if (p.x > p.w) code |= kRight;
    if (p.y < -p.w) code |= kBottom;
    if (p.y > p.w) code |= kTop;
    return code;
  }
};

bool finite(const glm::vec4& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// Linear interpolation in clip space, always from the inside vertex toward the outside one, so
// that an edge shared by two triangles is cut at bit-identical points.
ClipVertex lerp(const ClipVertex& in, const ClipVertex& out, float t, int num_varyings) {
  ClipVertex r;
  r.position = in.position + t * (out.position - in.position);
  for (int k = 0; k < num_varyings; ++k)
    r.varyings[k] = in.varyings[k] + t * (out.varyings[k] - in.varyings[k]);
  return r;
}

// One Sutherland-Hodgman pass against plane i.
int clip_against(const Planes& planes, int i, const ClipVertex* src, int n, ClipVertex* dst,
                 int num_varyings) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const ClipVertex& cur = src[k];
    const ClipVertex& next = src[(k + 1) % n];
    float dc = planes.distance(i, cur.position);
    float dn = planes.distance(i, next.position);
    bool cur_in = dc >= 0.0f;
    bool next_in = dn >= 0.0f;
    if (cur_in) dst[m++] = cur;
    if (cur_in != next_in) {
      dst[m++] = cur_in ? lerp(cur, next, dc / (dc - dn), num_varyings)
                        : lerp(next, cur, dn / (dn - dc), num_varyings);
    }
  }
  return m;
}

}  // namespace

ClipTest classify_triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                           float guard_x, float guard_y) {
  if (!finite(a) || !finite(b) || !finite(c)) return ClipTest::kInvalid;
  const Planes planes{guard_x, guard_y};
  const std::uint32_t ca = planes.outcode(a), cb = planes.outcode(b), cc = planes.outcode(c);
  if (ca & cb & cc) return ClipTest::kRejected;
  if ((ca | cb | cc) & ((1u << kClipPlaneCount) - 1)) return ClipTest::kNeedsClip;
  // Inside near and far means w >= 0; w == 0 (the eye point) must not be divided by.
  if (!(a.w > 0.0f && b.w > 0.0f && c.w > 0.0f)) return ClipTest::kInvalid;
  return ClipTest::kInside;
}

ClipResult clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                         int num_varyings, float guard_x, float guard_y, ClipPolygon& out) {
  if (!finite(a.position) || !finite(b.position) || !finite(c.position))
    return ClipResult::kInvalid;
  const Planes planes{guard_x, guard_y};
  std::uint32_t ca = planes.outcode(a.position);
  std::uint32_t cb = planes.outcode(b.position);
  std::uint32_t cc = planes.outcode(c.position);
  if (ca & cb & cc) return ClipResult::kRejected;

  std::uint32_t to_clip = (ca | cb | cc) & ((1u << kClipPlaneCount) - 1);
  out.v[0] = a;
  out.v[1] = b;
  out.v[2] = c;
  out.count = 3;
  if (to_clip) {
    std::array<ClipVertex, kMaxClipVertices> tmp;
    for (int i = 0; i < kClipPlaneCount && out.count >= 3; ++i) {
      if (!(to_clip & (1u << i))) continue;
      int n = clip_against(planes, i, out.v.data(), out.count, tmp.data(), num_varyings);
      for (int k = 0; k < n; ++k) out.v[k] = tmp[k];
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

}  // namespace tessref::raster
