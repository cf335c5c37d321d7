#pragma once
// Helpers shared by the tessellation-stage tests.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

#include "stages/schemes/flat.h"
#include "stages/schemes/pn_triangles.h"
#include "stages/tess_stage.h"

namespace tessref::test {

inline constexpr PnNormalMode kPnNormalModes[] = {PnNormalMode::Linear, PnNormalMode::Quadratic,
                                                  PnNormalMode::QuadraticCorrected, PnNormalMode::Analytic};

inline StageVertex vertex(const glm::vec3& p, const glm::vec3& n) {
  StageVertex v;
  v.attr[kAttrPosition] = glm::vec4(p, 1.0f);
  v.attr[kAttrNormal] = glm::vec4(n, 0.0f);
  return v;
}

inline Patch make_patch(const std::vector<StageVertex>& vs, int primitive_id = 0) {
  Patch p;
  p.vertex_count = int(vs.size());
  p.primitive_id = primitive_id;
  for (std::size_t i = 0; i < vs.size(); ++i) p.vertices[i] = vs[i];
  return p;
}

// Runs a control program on one patch the way the executor does.
inline PatchOutput run_tcs(const TessControlProgram& tcs, const Patch& in) {
  PatchOutput out;
  out.vertex_count = tcs.output_vertices();
  for (int phase = 0; phase < tcs.phases(); ++phase)
    for (int id = 0; id < tcs.output_vertices(); ++id) tcs.run(phase, id, in, out);
  return out;
}

// Tessellates patches [0, patch_count) of the draw on two threads; every TES invocation's record.
inline std::vector<TessDumpRecord> tessellate_dump(const TessDrawInput& input, std::size_t patch_count,
                                                   const TessControlProgram& tcs,
                                                   const TessEvalProgram& tes) {
  std::vector<TessDumpRecord> dump;
  TessOptions opt;
  opt.dump = &dump;
  TriangleBatch out;
  tessellate(input, 0, patch_count, tcs, tes, opt, Parallel(2), out);
  return dump;
}

inline std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }
inline bool same_bits(const glm::vec3& a, const glm::vec3& b) {
  return bits(a.x) == bits(b.x) && bits(a.y) == bits(b.y) && bits(a.z) == bits(b.z);
}

// The same triangles, corner for corner, bit for bit (indexed or not).
inline bool same_bytes(const TriangleBatch& indexed_or_not_a, const TriangleBatch& indexed_or_not_b) {
  const TriangleBatch a = expand_indices(indexed_or_not_a), b = expand_indices(indexed_or_not_b);
  return a.num_varyings == b.num_varyings && a.vertices.size() == b.vertices.size() &&
         std::memcmp(a.vertices.data(), b.vertices.data(),
                     a.vertices.size() * sizeof(ClipVertex)) == 0;
}

// Small deterministic generator (tests must not depend on the platform's std::*_distribution).
struct Lcg {
  std::uint64_t s;
  explicit Lcg(std::uint64_t seed) : s(seed * 6364136223846793005ull + 1442695040888963407ull) {}
  float uniform(float lo, float hi) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    const float t = float(s >> 40) / float(1u << 24);
    return lo + (hi - lo) * t;
  }
  glm::vec3 vec(float lo, float hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
};

// Edge points of one patch: dump records whose gl_TessCoord is 0 for the corner opposite the
// shared edge, keyed by their position bits.
inline std::vector<std::tuple<glm::vec3, glm::vec3>> edge_points(
    const std::vector<TessDumpRecord>& dump, std::uint32_t patch, int opposite) {
  std::vector<std::tuple<glm::vec3, glm::vec3>> pts;
  for (const auto& r : dump)
    if (r.patch_id == patch && r.tess_coord[opposite] == 0.0f) pts.emplace_back(r.position, r.normal);
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) {
    const glm::vec3 &p = std::get<0>(a), &q = std::get<0>(b);
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  });
  return pts;
}

}  // namespace tessref::test
