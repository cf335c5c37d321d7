#include "mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <unordered_map>

#include "common/error.h"
#include "common/hash.h"

namespace tessref {
namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}


glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  return glm::cross(b - a, c - a);
}

bool degenerate(const Mesh& m, std::size_t t) {
  const std::uint32_t* i = &m.indices[3 * t];
  if (i[0] == i[1] || i[1] == i[2] || i[2] == i[0]) return true;
  return !usable_normal(face_normal(m.positions[i[0]], m.positions[i[1]], m.positions[i[2]]));
}

// Interior angle at a between the edges towards b and c, in radians.
float corner_angle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  glm::vec3 e1 = b - a, e2 = c - a;
  float l1 = glm::length(e1), l2 = glm::length(e2);
  if (!(l1 > 0.0f && l2 > 0.0f)) return 0.0f;
  return std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0f, 1.0f));
}

}  // namespace

bool usable_normal(const glm::vec3& n) { return finite(n) && glm::dot(n, n) > 1e-30f; }

std::vector<glm::vec3> face_weighted_normals(const std::vector<glm::vec3>& positions,
                                             const std::vector<std::uint32_t>& indices) {
  // Angle-weighted sums, and area-weighted ones for the vertices whose every corner angle rounds
  // to zero (the sharp tip of a needle triangle), which would otherwise get no normal at all.
  std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.0f)), by_area(positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    std::uint32_t i[3] = {indices[t], indices[t + 1], indices[t + 2]};
    if (i[0] >= positions.size() || i[1] >= positions.size() || i[2] >= positions.size()) continue;
    const glm::vec3 &a = positions[i[0]], &b = positions[i[1]], &c = positions[i[2]];
    const glm::vec3 area = face_normal(a, b, c);
    if (!usable_normal(area)) continue;
    const glm::vec3 n = glm::normalize(area);
    sum[i[0]] += corner_angle(a, b, c) * n;
    sum[i[1]] += corner_angle(b, c, a) * n;
    sum[i[2]] += corner_angle(c, a, b) * n;
    for (std::uint32_t k : i) by_area[k] += area;
  }
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const glm::vec3 n = usable_normal(sum[v]) ? sum[v] : by_area[v];
    sum[v] = usable_normal(n) ? glm::normalize(n) : glm::vec3(0.0f);
  }
  return sum;
}

Mesh weld_by_position(const std::vector<glm::vec3>& positions,
                      const std::vector<glm::vec3>& normals,
                      const std::vector<std::uint32_t>& indices) {
  Mesh out;
  std::vector<std::uint32_t> remap(positions.size());
  std::unordered_map<FloatBits3, std::uint32_t, FloatBits3::Hash> first;
  first.reserve(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const glm::vec3 p = positions[v] + 0.0f;  // -0 and +0 weld together
    const FloatBits3 k(&p.x);
    auto [it, inserted] = first.try_emplace(k, static_cast<std::uint32_t>(out.positions.size()));
    if (inserted) out.positions.push_back(positions[v]);
    remap[v] = it->second;
  }
  out.indices.reserve(indices.size());
  for (std::uint32_t i : indices) out.indices.push_back(i < remap.size() ? remap[i] : i);

  out.normals.assign(out.positions.size(), glm::vec3(0.0f));
  if (normals.size() == positions.size()) {
    for (std::size_t v = 0; v < positions.size(); ++v)
      if (finite(normals[v])) out.normals[remap[v]] += normals[v];
  }
  bool need_faces = false;
  for (glm::vec3& n : out.normals) {
    if (usable_normal(n)) n = glm::normalize(n);
    else need_faces = true;
  }
  if (need_faces) {
    std::vector<glm::vec3> from_faces = face_weighted_normals(out.positions, out.indices);
    for (std::size_t v = 0; v < out.normals.size(); ++v)
      if (!usable_normal(out.normals[v])) out.normals[v] = from_faces[v];
  }
  return out;
}

MeshRepairs validate_mesh(Mesh& m, const std::string& source) {
  auto fail = [&](const std::string& what) { throw InputError(source + ": " + what); };
  if (m.positions.empty() || m.indices.empty()) fail("the mesh is empty (no triangles)");
  if (m.indices.size() % 3 != 0)
    fail("index count " + std::to_string(m.indices.size()) + " is not a multiple of 3");
  if (!m.normals.empty() && m.normals.size() != m.positions.size())
    fail(std::to_string(m.normals.size()) + " normals for " + std::to_string(m.positions.size()) +
         " positions");
  for (std::size_t v = 0; v < m.positions.size(); ++v)
    if (!finite(m.positions[v]))
      fail("vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
  for (std::size_t k = 0; k < m.indices.size(); ++k)
    if (m.indices[k] >= m.positions.size())
      fail("triangle " + std::to_string(k / 3) + " uses vertex " + std::to_string(m.indices[k]) +
           ", but the mesh has " + std::to_string(m.positions.size()) + " vertices");

  // Finite coordinates whose edge cross product is not: the mesh is too large for single precision
  // (every triangle would otherwise be dropped as "degenerate").
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const std::uint32_t* i = &m.indices[3 * t];
    if (finite(face_normal(m.positions[i[0]], m.positions[i[1]], m.positions[i[2]]))) continue;
    float largest = 0.0f;
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(m.positions[i[k]][c]));
    char size[32];
    std::snprintf(size, sizeof size, "%g", double(largest));
    fail("triangle " + std::to_string(t) + ": the cross product of its edges overflows single "
         "precision (coordinates up to " + size + "); scale the mesh down (below 1e18)");
  }

  MeshRepairs repairs;
  std::vector<std::uint32_t> kept;
  kept.reserve(m.indices.size());
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    if (degenerate(m, t)) {
      ++repairs.degenerate_triangles_dropped;
      continue;
    }
    kept.insert(kept.end(), m.indices.begin() + 3 * t, m.indices.begin() + 3 * t + 3);
  }
  if (kept.empty())
    fail("all " + std::to_string(m.triangle_count()) + " triangles are degenerate (zero area)");
  m.indices = std::move(kept);

  if (m.normals.empty()) m.normals.assign(m.positions.size(), glm::vec3(0.0f));
  std::vector<bool> referenced(m.positions.size(), false);
  for (std::uint32_t i : m.indices) referenced[i] = true;
  std::vector<glm::vec3> from_faces;
  for (std::size_t v = 0; v < m.normals.size(); ++v) {
    glm::vec3& n = m.normals[v];
    if (usable_normal(n)) {
      n = glm::normalize(n);
      continue;
    }
    if (!referenced[v]) {
      n = glm::vec3(0.0f, 0.0f, 1.0f);  // unused by any triangle: any unit vector will do
      continue;
    }
    if (from_faces.empty()) from_faces = face_weighted_normals(m.positions, m.indices);
    if (!usable_normal(from_faces[v]))
      fail("vertex " + std::to_string(v) +
           " has no usable normal: the faces around it cancel out (a two-sided sheet?)");
    n = from_faces[v];
    ++repairs.normals_recomputed;
  }
  return repairs;
}

}  // namespace tessref
