#include "verify/surface.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <embree3/rtcore.h>

#include "common/error.h"

namespace tessref {

void TessSurface::append(const std::vector<TessDumpRecord>& records, const TriangleBatch& batch) {
  if (records.size() != batch.vertex_count())
    throw std::logic_error("tess_surface: " + std::to_string(records.size()) + " records for " +
                           std::to_string(batch.vertex_count()) + " vertices");
  const auto base = std::uint32_t(points.size());
  points.insert(points.end(), records.begin(), records.end());
  for (std::size_t t = 0; t < batch.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) indices.push_back(base + std::uint32_t(batch.vertex_index(t, k)));
}

TessSurface TessSurface::from_emitted(std::vector<TessDumpRecord> emitted) {
  TessSurface s;
  emitted.resize(emitted.size() / 3 * 3);
  s.points = std::move(emitted);
  s.indices.resize(s.points.size());
  for (std::size_t i = 0; i < s.indices.size(); ++i) s.indices[i] = std::uint32_t(i);
  return s;
}

double TessSurface::diagonal() const {
  if (indices.empty()) return 1.0;
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (std::uint32_t i : indices) {
    lo = glm::min(lo, glm::dvec3(points[i].position));
    hi = glm::max(hi, glm::dvec3(points[i].position));
  }
  const double d = glm::length(hi - lo);
  return d > 0.0 ? d : 1.0;
}

namespace {

glm::dvec3 closest_on_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

// Embree's point-query callback: shrinks the query radius to the closest triangle so far.
bool closest_callback(RTCPointQueryFunctionArguments* args) {
  auto& [surface, best, point] =
      *static_cast<std::tuple<const TessSurface*, SurfaceOracle::Closest*, glm::dvec3>*>(args->userPtr);
  const std::size_t t = args->primID;
  const glm::dvec3 q = closest_point_on_triangle(point, surface->corner(t, 0), surface->corner(t, 1),
                                                 surface->corner(t, 2));
  const double d = glm::length(q - point);
  if (d < best->distance || (d == best->distance && t < best->triangle)) {
    best->distance = d;
    best->triangle = std::uint32_t(t);
    // The radius is a float: round it up so that the triangle found stays inside it.
    args->query->radius = std::nextafter(float(d), INFINITY);
    return true;
  }
  return false;
}

// The intersect context with the culling switch, which the filter below reads back.
struct CastContext {
  RTCIntersectContext embree;
  bool cull_back = false;
};

// Rejects hits on triangles facing away from the ray's origin (counter-clockwise is front, as
// GL's default front face; cross(b - a, c - a) then points toward a viewer in front).
void cull_filter(const RTCFilterFunctionNArguments* args) {
  const auto* ctx = reinterpret_cast<const CastContext*>(args->context);
  if (!ctx->cull_back) return;
  const auto* surface = static_cast<const TessSurface*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    const std::size_t t = RTCHitN_primID(args->hit, args->N, i);
    const glm::dvec3 a(surface->corner(t, 0)), b(surface->corner(t, 1)), c(surface->corner(t, 2));
    const glm::dvec3 o(RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
                       RTCRayN_org_z(args->ray, args->N, i));
    if (glm::dot(glm::cross(b - a, c - a), o - a) <= 0.0) args->valid[i] = 0;
  }
}

}  // namespace

glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double n2 = glm::dot(n, n);
  if (n2 > 0.0) {
    // The projection onto the plane, if it lies inside (on the inner side of all three edges).
    const glm::dvec3 q = p - (glm::dot(p - a, n) / n2) * n;
    if (glm::dot(n, glm::cross(b - a, q - a)) >= 0.0 && glm::dot(n, glm::cross(c - b, q - b)) >= 0.0 &&
        glm::dot(n, glm::cross(a - c, q - c)) >= 0.0)
      return q;
  }
  // Otherwise the closest point lies on an edge.
  glm::dvec3 best = closest_on_segment(p, a, b);
  for (const glm::dvec3& q : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)})
    if (glm::dot(q - p, q - p) < glm::dot(best - p, best - p)) best = q;
  return best;
}

SurfaceOracle::SurfaceOracle(const TessSurface& surface) : surface_(surface) {
  device_ = rtcNewDevice("verbose=0");
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), surface.points.size()));
  for (std::size_t i = 0; i < surface.points.size(); ++i)
    std::memcpy(v + 3 * i, &surface.points[i].position, 3 * sizeof(float));
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(unsigned), surface.triangle_count()));
  std::memcpy(idx, surface.indices.data(), surface.indices.size() * sizeof(unsigned));
  rtcSetGeometryUserData(geom, const_cast<TessSurface*>(&surface));
  rtcSetGeometryIntersectFilterFunction(geom, cull_filter);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene_, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("Embree: the scene could not be built");
}

SurfaceOracle::~SurfaceOracle() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

SurfaceOracle::Hit SurfaceOracle::cast(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar,
                                       bool cull_back) const {
  CastContext ctx;
  rtcInitIntersectContext(&ctx.embree);
  ctx.cull_back = cull_back;
  RTCRayHit rh{};
  rh.ray.org_x = origin.x, rh.ray.org_y = origin.y, rh.ray.org_z = origin.z;
  rh.ray.dir_x = dir.x, rh.ray.dir_y = dir.y, rh.ray.dir_z = dir.z;
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &ctx.embree, &rh);
  Hit h;
  if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) h.t = rh.ray.tfar, h.triangle = rh.hit.primID;
  return h;
}

SurfaceOracle::Closest SurfaceOracle::closest(const glm::vec3& point) const {
  Closest best;
  if (surface_.indices.empty()) return best;
  RTCPointQuery q{};
  q.x = point.x, q.y = point.y, q.z = point.z;
  q.radius = INFINITY;
  RTCPointQueryContext ctx;
  rtcInitPointQueryContext(&ctx);
  std::tuple<const TessSurface*, Closest*, glm::dvec3> user{&surface_, &best, glm::dvec3(point)};
  rtcPointQuery(scene_, &q, &ctx, closest_callback, &user);
  return best;
}

}  // namespace tessref
