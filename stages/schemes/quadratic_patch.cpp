#include "stages/schemes/quadratic_patch.h"

#include "stages/schemes/bezier_nets.h"
#include "stages/schemes/canonical.h"
#include "stages/schemes/flat.h"

namespace tessref {

namespace {

glm::vec3 xyz(const glm::vec4& v) { return glm::vec3(v); }

bool quadratic_normals(PnNormalMode m) {
  return m == PnNormalMode::Quadratic || m == PnNormalMode::QuadraticCorrected;
}

// The TES's view of the control program's output, named as in quadratic_patch.tese.
struct Net {
  const PatchOutput& po;
  int x, y, z;  // canonical corner order

  explicit Net(const PatchOutput& patch) : po(patch) {
    // Clamped so that garbage in the slot cannot index out of bounds.
    auto slot = [&](int i) {
      const float o = po.patch[kQuadPatchOrder][i];
      return o >= 1.0f ? (o >= 2.0f ? 2 : 1) : 0;
    };
    x = slot(0), y = slot(1), z = slot(2);
  }
  glm::vec3 P(int i) const { return xyz(po.vertices[i].attr[kAttrPosition]); }
  glm::vec3 N(int i) const { return xyz(po.vertices[i].attr[kAttrNormal]); }
  // Mid-edge control point and mid-edge normal of the edge {i, j}.
  glm::vec3 B(int i, int j) const {
    return xyz(po.vertices[j == (i + 1) % 3 ? i : j].attr[kQuadAttrEdgePoint]);
  }
  glm::vec3 M(int i, int j) const {
    return xyz(po.vertices[j == (i + 1) % 3 ? i : j].attr[kQuadAttrMidNormal]);
  }

  // Terms in canonical order: for any corner pair (r, s), r before s, the three terms that survive
  // on their edge (rr, ss, rs) come in this same relative order, whichever slots they use.
  glm::vec3 position(const glm::vec3& tc) const {
    const float a = tc[x], b = tc[y], c = tc[z];
    glm::vec3 p = P(x) * (a * a);
    p += P(y) * (b * b);
    p += P(z) * (c * c);
    p += B(x, y) * (2.0f * a * b);
    p += B(y, z) * (2.0f * b * c);
    p += B(x, z) * (2.0f * a * c);
    return canonical_zero(p);
  }

  void derivatives(const glm::vec3& tc, glm::vec3& d1, glm::vec3& d2) const {
    // b_ijk: exponents of tc.x, tc.y, tc.z.
    const glm::vec3 b200 = P(0), b020 = P(1), b002 = P(2);
    const glm::vec3 b110 = B(0, 1), b011 = B(1, 2), b101 = B(0, 2);
    const float s = tc.x, t = tc.y, u = tc.z;
    d1 = 2.0f * ((b110 - b200) * s + (b020 - b110) * t + (b011 - b101) * u);
    d2 = 2.0f * ((b101 - b200) * s + (b011 - b110) * t + (b002 - b101) * u);
  }

  glm::vec3 normal(const glm::vec3& tc, PnNormalMode mode) const {
    const float a = tc[x], b = tc[y], c = tc[z];
    const glm::vec3 lin = N(x) * a + N(y) * b + N(z) * c;
    glm::vec3 n;
    if (mode == PnNormalMode::Linear) {
      n = safe_normalize(lin);
    } else if (quadratic_normals(mode)) {
      glm::vec3 q = N(x) * (a * a);
      q += N(y) * (b * b);
      q += N(z) * (c * c);
      q += M(x, y) * (a * b);
      q += M(y, z) * (b * c);
      q += M(x, z) * (a * c);
      n = safe_normalize(q);
    } else {
      glm::vec3 d1, d2;
      derivatives(tc, d1, d2);
      n = safe_normalize(glm::cross(d1, d2));
      if (n == glm::vec3(0.0f)) n = safe_normalize(lin);  // degenerate tangents
      else if (glm::dot(n, lin) < 0.0f) n = -n;           // orient like the input normals
    }
    return canonical_zero(n);
  }
};

}  // namespace

void QuadraticTcs::run(int phase, int id, const Patch& in, PatchOutput& out) const {
  if (phase == 0) {
    auto in_pos = [&](int c) { return xyz(in.vertices[c].attr[kAttrPosition]); };
    auto& a = out.vertices[id].attr;
    a[kAttrPosition] = glm::vec4(in_pos(id), 1.0f);
    a[kAttrNormal] = glm::vec4(safe_normalize(xyz(in.vertices[id].attr[kAttrNormal])), 0.0f);
    if (id == 0) out.levels = triangle_levels(levels, in_pos(0), in_pos(1), in_pos(2));
    return;
  }
  // Phase 1 (after barrier()): reads the other invocations' corners and normals.
  auto pos = [&](int c) { return xyz(out.vertices[c].attr[kAttrPosition]); };
  auto nrm = [&](int c) { return xyz(out.vertices[c].attr[kAttrNormal]); };
  const int j = (id + 1) % 3;
  auto& a = out.vertices[id].attr;
  a[kQuadAttrEdgePoint] = glm::vec4(edge_point(pos(id), nrm(id), pos(j), nrm(j)), 1.0f);
  glm::vec3 mid(0.0f);
  if (quadratic_normals(normal_mode)) {
    const bool corrected = normal_mode == PnNormalMode::QuadraticCorrected;
    const glm::vec3 h = schemes::quadratic_normal_mid(pos(id), nrm(id), pos(j), nrm(j), corrected);
    mid = corrected ? h : safe_normalize(h);
  }
  a[kQuadAttrMidNormal] = glm::vec4(mid, 0.0f);
  if (id != 0) return;
  const auto o = canonical_corner_order({pos(0), pos(1), pos(2)}, {nrm(0), nrm(1), nrm(2)});
  out.patch[kQuadPatchOrder] = glm::vec4(float(o[0]), float(o[1]), float(o[2]), 0.0f);
}

glm::vec3 quadratic_position(const PatchOutput& patch, const glm::vec3& tc) {
  return Net(patch).position(tc);
}

glm::vec3 quadratic_normal(const PatchOutput& patch, const glm::vec3& tc, PnNormalMode mode) {
  return Net(patch).normal(tc, mode);
}

void quadratic_derivatives(const PatchOutput& patch, const glm::vec3& tc, glm::vec3& d1,
                           glm::vec3& d2) {
  Net(patch).derivatives(tc, d1, d2);
}

ClipVertex QuadraticTes::evaluate(const glm::vec3& tc, const PatchOutput& patch, int) const {
  const Net net(patch);
  return make_clip_vertex(view_proj, net.position(tc), net.normal(tc, normal_mode));
}

void QuadraticTes::evaluate_batch(const PatchOutput& patch, int, TessEvalBatch& batch) const {
  const Net net(patch);
  for (int i = 0; i < batch.count; ++i) {
    const glm::vec3 tc(batch.tess_coord[0][i], batch.tess_coord[1][i], batch.tess_coord[2][i]);
    const ClipVertex v = make_clip_vertex(view_proj, net.position(tc), net.normal(tc, normal_mode));
    for (int c = 0; c < 4; ++c) batch.position[c][i] = v.position[c];
    for (int k = 0; k < kBuiltinVaryings; ++k) batch.varyings[k][i] = v.varyings[k];
  }
}

}  // namespace tessref
