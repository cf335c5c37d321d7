#include "mesh/procedural.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace tessref {
namespace {

// Appends triangle (a, b, c), turned if needed so that its face normal points away from the origin
// (all three shapes here are star-shaped around it).
void add_outward_triangle(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const glm::vec3 &pa = m.positions[a], &pb = m.positions[b], &pc = m.positions[c];
  if (glm::dot(glm::cross(pb - pa, pc - pa), pa + pb + pc) < 0.0f) std::swap(b, c);
  m.indices.insert(m.indices.end(), {a, b, c});
}

}  // namespace

Mesh make_icosphere(int refinements, float radius) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  Mesh m;
  m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (glm::vec3& p : m.positions) p = glm::normalize(p);
  static constexpr std::uint32_t kFaces[20][3] = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (const auto& f : kFaces) add_outward_triangle(m, f[0], f[1], f[2]);

  for (int level = 0; level < refinements; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      std::pair<std::uint32_t, std::uint32_t> key = std::minmax(a, b);
      auto [it, inserted] = midpoints.try_emplace(key, std::uint32_t(m.positions.size()));
      if (inserted) m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      return it->second;
    };
    std::vector<std::uint32_t> coarse = std::move(m.indices);
    m.indices.clear();
    m.indices.reserve(coarse.size() * 4);
    for (std::size_t k = 0; k < coarse.size(); k += 3) {
      std::uint32_t a = coarse[k], b = coarse[k + 1], c = coarse[k + 2];
      std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      m.indices.insert(m.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
  }
  m.normals = m.positions;  // unit sphere: the position is the normal
  for (glm::vec3& p : m.positions) p *= radius;
  return m;
}

Mesh make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments) {
  Mesh m;
  const int J = major_segments, K = minor_segments;
  m.positions.reserve(std::size_t(J) * K);
  m.normals.reserve(std::size_t(J) * K);
  for (int i = 0; i < J; ++i) {
    double theta = 2.0 * std::numbers::pi * i / J;
    for (int j = 0; j < K; ++j) {
      double phi = 2.0 * std::numbers::pi * j / K;
      glm::dvec3 n(std::cos(phi) * std::cos(theta), std::sin(phi), std::cos(phi) * std::sin(theta));
      glm::dvec3 center(major_radius * std::cos(theta), 0.0, major_radius * std::sin(theta));
      m.positions.push_back(glm::vec3(center + double(minor_radius) * n));
      m.normals.push_back(glm::vec3(n));
    }
  }
  auto vertex = [&](int i, int j) { return std::uint32_t((i % J) * K + (j % K)); };
  m.indices.reserve(std::size_t(J) * K * 6);
  for (int i = 0; i < J; ++i) {
    for (int j = 0; j < K; ++j) {
      // Walking the tube (j) before the ring (i) is counter-clockwise seen from outside.
      std::uint32_t v00 = vertex(i, j), v01 = vertex(i, j + 1), v11 = vertex(i + 1, j + 1),
                    v10 = vertex(i + 1, j);
      m.indices.insert(m.indices.end(), {v00, v01, v11, v00, v11, v10});
    }
  }
  return m;
}

Mesh make_cube(float size) {
  Mesh m;
  const float h = size / 2.0f;
  for (int k = 0; k < 8; ++k) {
    glm::vec3 s((k & 1) ? 1.0f : -1.0f, (k & 2) ? 1.0f : -1.0f, (k & 4) ? 1.0f : -1.0f);
    m.positions.push_back(h * s);
    m.normals.push_back(glm::normalize(s));
  }
  // Each face as a quad of corner ids (bit 0: +x, bit 1: +y, bit 2: +z), split along one diagonal.
  static constexpr std::uint32_t kQuads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                 {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& q : kQuads) {
    add_outward_triangle(m, q[0], q[1], q[2]);
    add_outward_triangle(m, q[0], q[2], q[3]);
  }
  return m;
}

}  // namespace tessref
