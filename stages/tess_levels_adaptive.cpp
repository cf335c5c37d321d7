#include "stages/tess_levels_adaptive.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace tessref {

namespace {

// Lexicographic order of the bit patterns: a total order, even for NaN and signed zeros.
bool bits_less(const glm::vec3& a, const glm::vec3& b) {
  for (int i = 0; i < 3; ++i) {
    const auto x = std::bit_cast<std::uint32_t>(a[i]);
    const auto y = std::bit_cast<std::uint32_t>(b[i]);
    if (x != y) return x < y;
  }
  return false;
}

}  // namespace

float adaptive_edge_level(const glm::vec3& a_in, const glm::vec3& b_in,
                          const AdaptiveLevelSettings& s) {
  const bool swap = bits_less(b_in, a_in);
  const glm::vec3 a = swap ? b_in : a_in;
  const glm::vec3 b = swap ? a_in : b_in;
  const glm::vec4 ca = s.view_proj * glm::vec4(a, 1.0f);
  const glm::vec4 cb = s.view_proj * glm::vec4(b, 1.0f);
  if (std::isnan(ca.w) || std::isnan(cb.w)) return std::numeric_limits<float>::quiet_NaN();
  if (ca.w <= 0.0f || cb.w <= 0.0f) return s.max_level;  // no finite projection: be conservative
  // Window-space offsets in pixels: ndc * viewport / 2.
  const glm::vec2 half = s.viewport_pixels * 0.5f;
  const glm::vec2 wa = glm::vec2(ca.x / ca.w, ca.y / ca.w) * half;
  const glm::vec2 wb = glm::vec2(cb.x / cb.w, cb.y / cb.w) * half;
  const glm::vec2 d = wb - wa;
  const float level = std::sqrt(d.x * d.x + d.y * d.y) / s.pixels_per_segment;
  if (std::isnan(level)) return level;
  return std::min(std::max(level, s.min_level), s.max_level);
}

TessLevels triangle_levels(const TessLevelSettings& s, const glm::vec3& p0, const glm::vec3& p1,
                           const glm::vec3& p2) {
  if (!s.adaptive) return s.constant;
  TessLevels l;
  l.outer[0] = adaptive_edge_level(p1, p2, s.screen);
  l.outer[1] = adaptive_edge_level(p2, p0, s.screen);
  l.outer[2] = adaptive_edge_level(p0, p1, s.screen);
  l.outer[3] = 1.0f;  // unused by triangles
  const float inner = s.screen.inner_rule == InnerLevelRule::Max
                          ? std::max(std::max(l.outer[0], l.outer[1]), l.outer[2])
                          : (l.outer[0] + l.outer[1] + l.outer[2]) / 3.0f;
  l.inner = {inner, 1.0f};
  return l;
}

}  // namespace tessref
