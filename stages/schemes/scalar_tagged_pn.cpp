#include "stages/schemes/scalar_tagged_pn.h"

#include <cmath>

#include "stages/schemes/canonical.h"

namespace tessref {
namespace {

glm::vec3 xyz(const glm::vec4& v) { return glm::vec3(v); }

// The sharp normal on side s (+1 or -1): N' = normalize(N + s sigma Delta); N itself on a vertex
// without sharpness (not renormalized, so an untagged corner keeps its bits).
glm::vec3 sharp_normal(const glm::vec3& n, const glm::vec4& tags, const glm::vec3& crease, float side) {
  const float sigma = tags.y;
  if (!(sigma > 0.0f) || crease == glm::vec3(0.0f)) return n;
  return safe_normalize(n + crease * (side * sigma));
}

// Seed 001 Appendix B, Eq. 3: the coefficient next to P_j on the edge towards P_k.
glm::vec3 tagged_coefficient(const glm::vec3& pj, const glm::vec3& nj, const glm::vec4& tags,
                             const glm::vec3& crease, const glm::vec3& pk, bool crease_edge) {
  const float theta = tags.x, sigma = tags.y, beta = tags.z;
  const glm::vec3 d = pj + (pk - pj) * ((1.0f - theta) / 3.0f);
  if (crease_edge) {
    const glm::vec3 y = safe_normalize(nj + crease * beta);
    return d + y * -glm::dot(nj, d - pj);
  }
  const float side = glm::dot(crease, pk - pj) >= 0.0f ? 1.0f : -1.0f;
  const glm::vec3 x = safe_normalize(nj * (1.0f - sigma) + sharp_normal(nj, tags, crease, side));
  return d + x * -glm::dot(x, d - pj);
}

// Whether the tags leave corner j's coefficient towards k as PN's.
bool pn_coefficient(const glm::vec4& tags, const glm::vec3& crease, bool crease_edge) {
  return tags.x == 0.0f && !crease_edge && !(tags.y > 0.0f && crease != glm::vec3(0.0f));
}

}  // namespace

glm::vec3 world_crease(const glm::mat3& normal_matrix, const glm::vec3& crease) {
  const float length = std::sqrt(glm::dot(crease, crease));
  return safe_normalize(normal_matrix * crease) * length;
}

void ScalarTaggedPnTcs::run(int phase, int id, const Patch& in, PatchOutput& out) const {
  pn.run(phase, id, in, out);
  auto in_pos = [&](int c) { return xyz(in.vertices[c].attr[kAttrPosition]); };
  auto crease = [&](int c) { return xyz(in.vertices[c].attr[kAttrCrease]); };
  if (phase == 0) {
    const int j = (id + 1) % 3, k = (id + 2) % 3;
    const glm::vec3 p = in_pos(id);
    const glm::vec4 tags = in.vertices[id].attr[kAttrTags];
    auto& a = out.vertices[id].attr;
    const glm::vec3 n = xyz(a[kAttrNormal]);  // PnTcs's safe_normalize(input normal)
    a[kStpnAttrSmoothNormal] = glm::vec4(n, 0.0f);
    const glm::vec3 delta = crease(id);
    const bool creased = delta != glm::vec3(0.0f);
    const glm::vec3 to_centroid = (in_pos(j) - p) + (in_pos(k) - p);
    a[kAttrNormal] = glm::vec4(sharp_normal(n, tags, delta, glm::dot(delta, to_centroid) >= 0.0f ? 1.0f : -1.0f), 0.0f);
    const int slot[2] = {kPnAttrTangentNext, kPnAttrTangentPrev};
    const int other[2] = {j, k};
    for (int e = 0; e < 2; ++e) {
      const bool crease_edge = creased && crease(other[e]) != glm::vec3(0.0f);
      if (pn_coefficient(tags, delta, crease_edge)) continue;
      a[slot[e]] = glm::vec4(tagged_coefficient(p, n, tags, delta, in_pos(other[e]), crease_edge), 1.0f);
    }
    return;
  }
  // Phase 1: PnTcs made the mid-edge normals from the per-side normals and b111 from the tagged
  // coefficients; the corner order comes from the smooth normals.
  if (id != 0) return;
  auto pos = [&](int c) { return xyz(out.vertices[c].attr[kAttrPosition]); };
  auto smooth = [&](int c) { return xyz(out.vertices[c].attr[kStpnAttrSmoothNormal]); };
  const auto o = canonical_corner_order({pos(0), pos(1), pos(2)}, {smooth(0), smooth(1), smooth(2)});
  out.patch[kPnPatchOrder] = glm::vec4(float(o[0]), float(o[1]), float(o[2]), 0.0f);
}

}  // namespace tessref
