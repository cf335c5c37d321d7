#include "mesh/reference_meshes.h"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tessref {
namespace {

constexpr double kPi = std::numbers::pi;

// Appends (a, b, c), turned if needed so that its face normal has a positive dot product with
// `outside` (a direction pointing out of the solid near the triangle).
void add_facing(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c, const glm::dvec3& outside) {
  const glm::dvec3 pa(m.positions[a]), pb(m.positions[b]), pc(m.positions[c]);
  if (glm::dot(glm::cross(pb - pa, pc - pa), outside) < 0.0) std::swap(b, c);
  m.indices.insert(m.indices.end(), {a, b, c});
}

glm::dvec3 centroid(const Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return (glm::dvec3(m.positions[a]) + glm::dvec3(m.positions[b]) + glm::dvec3(m.positions[c])) / 3.0;
}

}  // namespace

std::vector<glm::vec3> face_average_normals(const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices) {
  std::vector<glm::dvec3> sum(positions.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t i[3] = {indices[t], indices[t + 1], indices[t + 2]};
    const glm::dvec3 a(positions[i[0]]), b(positions[i[1]]), c(positions[i[2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    if (!(len > 0.0)) continue;
    for (std::uint32_t k : i) sum[k] += n / len;
  }
  std::vector<glm::vec3> out(positions.size(), glm::vec3(0.0f));
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const double len = glm::length(sum[v]);
    if (len > 0.0) out[v] = glm::vec3(sum[v] / len);
  }
  return out;
}

Mesh make_seed004_torus(int j, ReferenceNormals normals) {
  if (j < 3) throw std::invalid_argument("make_seed004_torus: j = " + std::to_string(j) + " < 3");
  constexpr double R = 1.0, r = 0.5;
  Mesh m;
  m.positions.reserve(std::size_t(j) * j);
  m.normals.reserve(std::size_t(j) * j);
  for (int a = 0; a < j; ++a) {
    const double u = 2.0 * kPi * a / j;
    for (int b = 0; b < j; ++b) {
      const double v = kPi + 2.0 * kPi * b / j;  // from the inner equator
      const glm::dvec3 n(std::cos(v) * std::cos(u), std::sin(v), -std::cos(v) * std::sin(u));
      const glm::dvec3 centre(R * std::cos(u), 0.0, -R * std::sin(u));
      m.positions.push_back(glm::vec3(centre + r * n));
      m.normals.push_back(glm::vec3(n));
    }
  }
  auto id = [&](int a, int b) { return std::uint32_t((a % j) * j + (b % j)); };
  m.indices.reserve(std::size_t(j) * j * 6);
  for (int a = 0; a < j; ++a)
    for (int b = 0; b < j; ++b) {
      // Counter-clockwise from outside (du x dv points out). First triangle: third edge along u;
      // second: third edge along v.
      const std::uint32_t v00 = id(a, b), v10 = id(a + 1, b), v11 = id(a + 1, b + 1), v01 = id(a, b + 1);
      m.indices.insert(m.indices.end(), {v10, v11, v00, v00, v11, v01});
    }
  if (normals == ReferenceNormals::FaceAverage) m.normals = face_average_normals(m.positions, m.indices);
  return m;
}

float seed004_torus_distance(const glm::vec3& p) {
  const float q = std::sqrt(p.x * p.x + p.z * p.z) - 1.0f;
  return std::sqrt(q * q + p.y * p.y) - 0.5f;
}

float seed004_sphere_distance(const glm::vec3& p) { return glm::length(p) - 1.0f; }

Mesh make_rounded_cube(float cut, float half_size) {
  if (!(cut > 0.0f && cut < 1.0f))
    throw std::invalid_argument("make_rounded_cube: cut must be in (0, 1)");
  if (!(half_size > 0.0f && half_size < 1e18f))
    throw std::invalid_argument("make_rounded_cube: half_size must be in (0, 1e18)");
  Mesh m;
  std::map<std::array<float, 3>, std::uint32_t> ids;
  auto vertex = [&](glm::vec3 p) {
    auto [it, inserted] = ids.try_emplace({p.x, p.y, p.z}, std::uint32_t(m.positions.size()));
    if (inserted) m.positions.push_back(p);
    return it->second;
  };
  const float k = 1.0f - cut;
  // Corner triangles: the three points at `cut` from corner s along its edges.
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 s((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, (c & 4) ? 1.0f : -1.0f);
    std::uint32_t t[3];
    for (int axis = 0; axis < 3; ++axis) {
      glm::vec3 p = s;
      p[axis] = s[axis] * k;
      t[axis] = vertex(p);
    }
    add_facing(m, t[0], t[1], t[2], glm::dvec3(s));
  }
  // Faces: the octagon of cut points around the face centre, fanned.
  static constexpr float kRing[8][2] = {{1, 0}, {0, 1}, {0, 1}, {-1, 0}, {-1, 0}, {0, -1}, {0, -1}, {1, 0}};
  static constexpr float kRingSide[8][2] = {{0, 1}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}, {-1, 0}, {1, 0}, {0, -1}};
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      const int b = (axis + 1) % 3, c = (axis + 2) % 3;
      glm::vec3 centre(0.0f);
      centre[axis] = side;
      const std::uint32_t ci = vertex(centre);
      std::uint32_t ring[8];
      for (int q = 0; q < 8; ++q) {
        // Octagon corner q: on the face's edge kRing[q] (unit coordinates along b, c), shifted
        // from that edge's midpoint towards one end by k.
        glm::vec3 p = centre;
        p[b] = kRing[q][0] + k * kRingSide[q][0];
        p[c] = kRing[q][1] + k * kRingSide[q][1];
        ring[q] = vertex(p);
      }
      glm::dvec3 out(0.0);
      out[axis] = side;
      for (int q = 0; q < 8; ++q) add_facing(m, ci, ring[q], ring[(q + 1) % 8], out);
    }
  // Built on [-1, 1]^3 so that shared points are found bit for bit, then scaled.
  for (glm::vec3& p : m.positions) p *= half_size;
  m.normals = face_average_normals(m.positions, m.indices);
  return m;
}

Mesh make_seed004_vase() {
  constexpr int kAround = 20, kRings = 12;
  constexpr double kHeight = 3.0, kBulge = 0.25, kStar = 0.12;
  Mesh m;
  for (int ring = 0; ring < kRings; ++ring) {
    const double h = double(ring) / (kRings - 1), y = kHeight * h;
    // A belly at the bottom, a neck at mid height, a flared lip; the star's depth fades from
    // kStar at the bottom ring to 0 at the middle ring and above.
    const double profile = 1.0 + kBulge * std::cos(2.0 * kPi * h);
    const double depth = ring < kRings / 2 ? kStar * (1.0 - double(ring) / (kRings / 2)) : 0.0;
    for (int i = 0; i < kAround; ++i) {
      const double theta = 2.0 * kPi * i / kAround;
      const double radius = profile * (1.0 + ((i % 2 == 0) ? depth : -depth));
      m.positions.push_back(glm::vec3(glm::dvec3(radius * std::cos(theta), y, -radius * std::sin(theta))));
    }
  }
  const std::uint32_t bottom = std::uint32_t(m.positions.size());
  m.positions.push_back(glm::vec3(0.0f));
  auto id = [&](int ring, int i) { return std::uint32_t(ring * kAround + (i % kAround)); };
  for (int ring = 0; ring + 1 < kRings; ++ring)
    for (int i = 0; i < kAround; ++i) {
      const std::uint32_t a = id(ring, i), b = id(ring, i + 1), c = id(ring + 1, i + 1), d = id(ring + 1, i);
      glm::dvec3 out = centroid(m, a, b, c);
      add_facing(m, a, b, c, glm::dvec3(out.x, 0.0, out.z));
      out = centroid(m, a, c, d);
      add_facing(m, a, c, d, glm::dvec3(out.x, 0.0, out.z));
    }
  for (int i = 0; i < kAround; ++i) add_facing(m, bottom, id(0, i), id(0, i + 1), glm::dvec3(0.0, -1.0, 0.0));
  m.normals = face_average_normals(m.positions, m.indices);
  return m;
}

}  // namespace tessref
