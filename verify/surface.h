#pragma once
// A tessellated surface as triangles in world space, and Embree 3 over it: the ray casts and
// closest-point queries that `tessref verify` measures with (silhouettes, distances, cracks).
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "raster/vertex.h"
#include "stages/tess_stage.h"

typedef struct RTCDeviceTy* RTCDevice;
typedef struct RTCSceneTy* RTCScene;

namespace tessref {

// What a draw tessellated: every domain point's record (patch id, gl_TessCoord, position, normal)
// and triangles indexing them, each triangle with its patch.
struct TessSurface {
  std::vector<TessDumpRecord> points;
  std::vector<std::uint32_t> indices;  // 3 per triangle
  std::size_t triangle_count() const { return indices.size() / 3; }
  std::uint32_t patch_of(std::size_t triangle) const { return points[indices[3 * triangle]].patch_id; }
  glm::vec3 corner(std::size_t triangle, int k) const { return points[indices[3 * triangle + k]].position; }

  // Appends one chunk of a draw (DrawOptions::tess_surface: vertex k of the indexed batch is
  // record k).
  void append(const std::vector<TessDumpRecord>& records, const TriangleBatch& batch);
  // A captured stream: one record per emitted vertex, three per triangle.
  static TessSurface from_emitted(std::vector<TessDumpRecord> emitted);
  // The bounding box's diagonal (1 for an empty surface).
  double diagonal() const;
};

class SurfaceOracle {
 public:
  // Embree in robust mode: a ray through an edge two triangles share bit for bit hits one of them.
  explicit SurfaceOracle(const TessSurface& surface);
  ~SurfaceOracle();
  SurfaceOracle(const SurfaceOracle&) = delete;
  SurfaceOracle& operator=(const SurfaceOracle&) = delete;

  struct Hit {
    float t = std::numeric_limits<float>::infinity();  // along dir (not normalized); inf: none
    std::uint32_t triangle = 0;
    bool hit() const { return t != std::numeric_limits<float>::infinity(); }
  };
  // cull_back: pass through triangles whose winding is clockwise seen from the ray's origin (as
  // the rasterizer culls them), so that a ray through a crack sees what the image shows there.
  Hit cast(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar, bool cull_back = false) const;

  struct Closest {
    double distance = std::numeric_limits<double>::infinity();
    std::uint32_t triangle = 0;  // the lowest index among equally close triangles
  };
  Closest closest(const glm::vec3& point) const;

 private:
  const TessSurface& surface_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

// The point of triangle (a, b, c) closest to p, in double precision.
glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c);

}  // namespace tessref
