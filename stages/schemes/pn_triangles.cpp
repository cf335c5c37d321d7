#include "stages/schemes/pn_triangles.h"

#include "stages/schemes/bezier_nets.h"
#include "stages/schemes/canonical.h"
#include "stages/schemes/pn_batch.h"
#include "stages/schemes/flat.h"

namespace tessref {

const char* to_string(PnNormalMode m) {
  switch (m) {
    case PnNormalMode::Linear: return "linear";
    case PnNormalMode::Quadratic: return "quadratic";
    case PnNormalMode::QuadraticCorrected: return "quadratic_corrected";
    case PnNormalMode::Analytic: return "analytic";
  }
  return "?";
}

bool parse(const std::string& s, PnNormalMode& out) {
  for (PnNormalMode m : {PnNormalMode::Linear, PnNormalMode::Quadratic,
                         PnNormalMode::QuadraticCorrected, PnNormalMode::Analytic})
    if (s == to_string(m)) return out = m, true;
  return false;
}

namespace {

glm::vec3 xyz(const glm::vec4& v) { return glm::vec3(v); }

struct Net {
  glm::vec3 p[3];      // corners
  glm::vec3 n[3];      // unit corner normals (or zero)
  glm::vec3 next[3];   // tangent coefficient at i towards (i+1)%3
  glm::vec3 prev[3];   // tangent coefficient at i towards (i+2)%3
  glm::vec3 mid[3];    // mid-edge normal of edge (i, (i+1)%3)
  glm::vec3 center;    // b111
  int order[3];

  explicit Net(const PatchOutput& po) {
    for (int i = 0; i < 3; ++i) {
      const auto& a = po.vertices[i].attr;
      p[i] = xyz(a[kAttrPosition]);
      n[i] = xyz(a[kAttrNormal]);
      next[i] = xyz(a[kPnAttrTangentNext]);
      prev[i] = xyz(a[kPnAttrTangentPrev]);
      mid[i] = xyz(a[kPnAttrMidNormal]);
      // Clamped so that garbage in the slot cannot index out of bounds.
      const float o = po.patch[kPnPatchOrder][i];
      order[i] = o >= 1.0f ? (o >= 2.0f ? 2 : 1) : 0;
    }
    center = xyz(po.patch[kPnPatchCenter]);
  }
  // Tangent coefficient at corner x towards corner y (x != y).
  const glm::vec3& tangent(int x, int y) const { return y == (x + 1) % 3 ? next[x] : prev[x]; }
  const glm::vec3& mid_normal(int x, int y) const { return y == (x + 1) % 3 ? mid[x] : mid[y]; }
};

glm::vec3 linear_normal_sum(const Net& net, const glm::vec3& tc) {
  const int x = net.order[0], y = net.order[1], z = net.order[2];
  return net.n[x] * tc[x] + net.n[y] * tc[y] + net.n[z] * tc[z];
}

}  // namespace

void PnTcs::run(int phase, int id, const Patch& in, PatchOutput& out) const {
  const int j = (id + 1) % 3, k = (id + 2) % 3;
  auto in_pos = [&](int c) { return xyz(in.vertices[c].attr[kAttrPosition]); };
  if (phase == 0) {
    const glm::vec3 pi = in_pos(id);
    const glm::vec3 ni = safe_normalize(xyz(in.vertices[id].attr[kAttrNormal]));
    auto& a = out.vertices[id].attr;
    a[kAttrPosition] = glm::vec4(pi, 1.0f);
    a[kAttrNormal] = glm::vec4(ni, 0.0f);
    a[kPnAttrTangentNext] = glm::vec4(schemes::pn_tangent_point(pi, ni, in_pos(j)), 1.0f);
    a[kPnAttrTangentPrev] = glm::vec4(schemes::pn_tangent_point(pi, ni, in_pos(k)), 1.0f);
    if (id == 0) out.levels = triangle_levels(levels, in_pos(0), in_pos(1), in_pos(2));
    return;
  }
  // Phase 1 (after barrier()): reads the other invocations' phase-0 outputs.
  auto pos = [&](int c) { return xyz(out.vertices[c].attr[kAttrPosition]); };
  auto nrm = [&](int c) { return xyz(out.vertices[c].attr[kAttrNormal]); };
  glm::vec3 mid(0.0f);
  if (normal_mode == PnNormalMode::Quadratic || normal_mode == PnNormalMode::QuadraticCorrected) {
    const bool swap = corner_less(pos(j), nrm(j), pos(id), nrm(id));
    const int a = swap ? j : id, b = swap ? id : j;
    // Both patches of the edge compute it from its ends in canonical order: the same bits.
    const bool corrected = normal_mode == PnNormalMode::QuadraticCorrected;
    const glm::vec3 h = schemes::quadratic_normal_mid(pos(a), nrm(a), pos(b), nrm(b), corrected);
    mid = corrected ? h : safe_normalize(h);
  }
  out.vertices[id].attr[kPnAttrMidNormal] = glm::vec4(mid, 0.0f);
  if (id != 0) return;
  glm::vec3 e(0.0f), v(0.0f);
  for (int c = 0; c < 3; ++c) {
    e += xyz(out.vertices[c].attr[kPnAttrTangentNext]) + xyz(out.vertices[c].attr[kPnAttrTangentPrev]);
    v += pos(c);
  }
  e /= 6.0f;
  v /= 3.0f;
  out.patch[kPnPatchCenter] = glm::vec4(e + (e - v) / 2.0f, 1.0f);
  const auto o = canonical_corner_order({pos(0), pos(1), pos(2)}, {nrm(0), nrm(1), nrm(2)});
  out.patch[kPnPatchOrder] = glm::vec4(float(o[0]), float(o[1]), float(o[2]), 0.0f);
}

glm::vec3 pn_position(const PatchOutput& patch, const glm::vec3& tc) {
  const Net net(patch);
  const int x = net.order[0], y = net.order[1], z = net.order[2];
  const float a = tc[x], b = tc[y], c = tc[z];
  // Terms in canonical order: for any corner pair (r, s), r before s, the four terms that survive
  // on their edge (rrr, sss, rrs, rss) come in this same relative order, whichever slots they use.
  glm::vec3 s = net.p[x] * (a * a * a);
  s += net.p[y] * (b * b * b);
  s += net.p[z] * (c * c * c);
  s += net.tangent(x, y) * (3.0f * a * a * b);
  s += net.tangent(y, x) * (3.0f * a * b * b);
  s += net.tangent(y, z) * (3.0f * b * b * c);
  s += net.tangent(z, y) * (3.0f * b * c * c);
  s += net.tangent(x, z) * (3.0f * a * a * c);
  s += net.tangent(z, x) * (3.0f * a * c * c);
  s += net.center * (6.0f * a * b * c);
  return canonical_zero(s);
}

void pn_derivatives(const PatchOutput& patch, const glm::vec3& tc, glm::vec3& d1, glm::vec3& d2) {
  const Net net(patch);
  // b_ijk: exponents of tc.x, tc.y, tc.z.
  const glm::vec3 &b300 = net.p[0], &b030 = net.p[1], &b003 = net.p[2];
  const glm::vec3 &b210 = net.next[0], &b201 = net.prev[0];
  const glm::vec3 &b021 = net.next[1], &b120 = net.prev[1];
  const glm::vec3 &b102 = net.next[2], &b012 = net.prev[2];
  const glm::vec3& b111 = net.center;
  const float s = tc.x, t = tc.y, u = tc.z;
  // Quadratic Bernstein weights.
  const float w200 = s * s, w020 = t * t, w002 = u * u;
  const float w110 = 2.0f * s * t, w011 = 2.0f * t * u, w101 = 2.0f * s * u;
  d1 = 3.0f * ((b210 - b300) * w200 + (b030 - b120) * w020 + (b012 - b102) * w002 +
               (b120 - b210) * w110 + (b021 - b111) * w011 + (b111 - b201) * w101);
  d2 = 3.0f * ((b201 - b300) * w200 + (b021 - b120) * w020 + (b003 - b102) * w002 +
               (b111 - b210) * w110 + (b012 - b111) * w011 + (b102 - b201) * w101);
}

glm::vec3 pn_normal(const PatchOutput& patch, const glm::vec3& tc, PnNormalMode mode) {
  const Net net(patch);
  const int x = net.order[0], y = net.order[1], z = net.order[2];
  switch (mode) {
    case PnNormalMode::Linear:
      return canonical_zero(safe_normalize(linear_normal_sum(net, tc)));
    case PnNormalMode::Quadratic:
    case PnNormalMode::QuadraticCorrected: {
      const float a = tc[x], b = tc[y], c = tc[z];
      glm::vec3 s = net.n[x] * (a * a);
      s += net.n[y] * (b * b);
      s += net.n[z] * (c * c);
      s += net.mid_normal(x, y) * (a * b);
      s += net.mid_normal(y, z) * (b * c);
      s += net.mid_normal(x, z) * (a * c);
      return canonical_zero(safe_normalize(s));
    }
    case PnNormalMode::Analytic: {
      glm::vec3 d1, d2;
      pn_derivatives(patch, tc, d1, d2);
      const glm::vec3 lin = linear_normal_sum(net, tc);
      glm::vec3 n = safe_normalize(glm::cross(d1, d2));
      if (n == glm::vec3(0.0f)) return canonical_zero(safe_normalize(lin));
      // Orient like the input normals (a clockwise corner order flips the cross product).
      if (glm::dot(n, lin) < 0.0f) n = -n;
      return canonical_zero(n);
    }
  }
  return glm::vec3(0.0f);
}

ClipVertex PnTes::evaluate(const glm::vec3& tc, const PatchOutput& patch, int) const {
  return make_clip_vertex(view_proj, pn_position(patch, tc), pn_normal(patch, tc, normal_mode));
}

void PnTes::evaluate_batch(const PatchOutput& patch, int primitive_id,
                           TessEvalBatch& batch) const {
  if (normal_mode == PnNormalMode::Analytic) {
    TessEvalProgram::evaluate_batch(patch, primitive_id, batch);
    return;
  }
  // The net in canonical order, exactly the operands pn_position and pn_normal pick.
  const Net net(patch);
  const int x = net.order[0], y = net.order[1], z = net.order[2];
  PnBatchPatch k;
  auto put = [](float (&dst)[3], const glm::vec3& v) {
    for (int c = 0; c < 3; ++c) dst[c] = v[c];
  };
  put(k.p[0], net.p[x]);
  put(k.p[1], net.p[y]);
  put(k.p[2], net.p[z]);
  put(k.t[0], net.tangent(x, y));
  put(k.t[1], net.tangent(y, x));
  put(k.t[2], net.tangent(y, z));
  put(k.t[3], net.tangent(z, y));
  put(k.t[4], net.tangent(x, z));
  put(k.t[5], net.tangent(z, x));
  put(k.center, net.center);
  put(k.n[0], net.n[x]);
  put(k.n[1], net.n[y]);
  put(k.n[2], net.n[z]);
  put(k.mid[0], net.mid_normal(x, y));
  put(k.mid[1], net.mid_normal(y, z));
  put(k.mid[2], net.mid_normal(x, z));
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) k.view_proj[4 * col + row] = view_proj[col][row];
  k.quadratic = normal_mode != PnNormalMode::Linear;
  float* const clip[4] = {batch.position[0], batch.position[1], batch.position[2],
                          batch.position[3]};
  float* const var[6] = {batch.varyings[kVaryingPosition], batch.varyings[kVaryingPosition + 1],
                         batch.varyings[kVaryingPosition + 2], batch.varyings[kVaryingNormal],
                         batch.varyings[kVaryingNormal + 1], batch.varyings[kVaryingNormal + 2]};
  pn_batch_kernel()(k, batch.count, batch.tess_coord[x], batch.tess_coord[y], batch.tess_coord[z],
                    clip, var);
}

}  // namespace tessref
