#pragma once
// Tessellation levels for the built-in control programs: constant, or adaptive in screen space.
#include <glm/glm.hpp>

#include "stages/tpg.h"

namespace tessref {

// How the inner level follows the outer ones in adaptive mode.
enum class InnerLevelRule {
  Max,   // inner = max(outer): interior at least as fine as the finest edge (the default)
  Mean,  // inner = (outer0 + outer1 + outer2) / 3
};

struct AdaptiveLevelSettings {
  glm::mat4 view_proj{1.0f};                // world -> clip
  glm::vec2 viewport_pixels{512.0f, 512.0f};  // width, height
  float pixels_per_segment = 8.0f;          // target projected length of one edge segment
  float min_level = 1.0f;
  float max_level = 64.0f;
  InnerLevelRule inner_rule = InnerLevelRule::Max;
};

struct TessLevelSettings {
  bool adaptive = false;
  TessLevels constant{{4.0f, 4.0f, 4.0f, 4.0f}, {4.0f, 4.0f}};  // constant mode: written as is
  AdaptiveLevelSettings screen;

  // Constant mode with every outer level = outer and every inner level = inner.
  static TessLevelSettings uniform(float outer, float inner) {
    TessLevelSettings s;
    s.constant.outer = {outer, outer, outer, outer};
    s.constant.inner = {inner, inner};
    return s;
  }
};

// The level of the edge a-b: its projected length in pixels / pixels_per_segment, clamped to
// [min_level, max_level]. The endpoints are put in a canonical order (by their bit patterns) before
// any arithmetic, so the result is bit-identical whichever patch asks and in whichever direction:
// neighbouring patches agree on their shared edge. An endpoint on or behind the eye plane
// (clip w <= 0) gives max_level; a NaN endpoint gives NaN (the generator then discards the patch).
float adaptive_edge_level(const glm::vec3& a, const glm::vec3& b, const AdaptiveLevelSettings& s);

// Levels of a triangle patch with corners p0, p1, p2 = gl_in[0..2] (GL: outer[0] is the u = 0
// edge p1-p2, outer[1] the v = 0 edge p2-p0, outer[2] the w = 0 edge p0-p1).
TessLevels triangle_levels(const TessLevelSettings& s, const glm::vec3& p0, const glm::vec3& p1,
                           const glm::vec3& p2);

}  // namespace tessref
