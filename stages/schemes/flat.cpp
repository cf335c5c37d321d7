#include "stages/schemes/flat.h"

#include <algorithm>

#include "stages/schemes/canonical.h"

namespace tessref {

ClipVertex make_clip_vertex(const glm::mat4& view_proj, const glm::vec3& position,
                            const glm::vec3& normal) {
  ClipVertex v;
  v.position = view_proj * glm::vec4(position, 1.0f);
  for (int i = 0; i < 3; ++i) {
    v.varyings[kVaryingPosition + i] = position[i];
    v.varyings[kVaryingNormal + i] = normal[i];
  }
  return v;
}

void PassThroughTcs::run(int, int id, const Patch& in, PatchOutput& out) const {
  out.vertices[id] = in.vertices[std::min(id, in.vertex_count - 1)];
  if (id == 0) {
    auto pos = [&](int k) {
      return glm::vec3(in.vertices[std::min(k, in.vertex_count - 1)].attr[kAttrPosition]);
    };
    out.levels = triangle_levels(levels, pos(0), pos(1), pos(2));
  }
}

ClipVertex FlatTes::evaluate(const glm::vec3& tc, const PatchOutput& patch, int) const {
  auto pos = [&](int k) { return glm::vec3(patch.vertices[k].attr[kAttrPosition]); };
  auto nrm = [&](int k) { return glm::vec3(patch.vertices[k].attr[kAttrNormal]); };
  glm::vec3 p, n;
  switch (tess_layout.domain) {
    case TessDomain::Triangles: {
      const std::array<glm::vec3, 3> ps{pos(0), pos(1), pos(2)};
      const std::array<glm::vec3, 3> ns{nrm(0), nrm(1), nrm(2)};
      const auto o = canonical_corner_order(ps, ns);
      p = canonical_zero(ps[o[0]] * tc[o[0]] + ps[o[1]] * tc[o[1]] + ps[o[2]] * tc[o[2]]);
      n = canonical_zero(ns[o[0]] * tc[o[0]] + ns[o[1]] * tc[o[1]] + ns[o[2]] * tc[o[2]]);
      break;
    }
    case TessDomain::Quads: {
      const float u = tc.x, v = tc.y;
      const float a = (1.0f - u) * (1.0f - v), b = u * (1.0f - v), c = u * v, d = (1.0f - u) * v;
      p = pos(0) * a + pos(1) * b + pos(2) * c + pos(3) * d;
      n = nrm(0) * a + nrm(1) * b + nrm(2) * c + nrm(3) * d;
      break;
    }
    case TessDomain::Isolines: {
      p = pos(0) * (1.0f - tc.x) + pos(1) * tc.x;
      n = nrm(0) * (1.0f - tc.x) + nrm(1) * tc.x;
      break;
    }
  }
  return make_clip_vertex(view_proj, p, safe_normalize(n));
}

}  // namespace tessref
