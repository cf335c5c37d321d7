#include "stats/surface_images.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/error.h"

namespace tessref::stats {
namespace {

std::uint8_t unorm8(double c) {  // as to_rgb8 stores colours: clamp, then round
  return std::uint8_t(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

// A little headlight shading under the false colours, so that the shape still reads:
// 1 facing the eye, 0.55 edge-on.
double headlight(const SurfaceSample& s, const glm::dvec3& eye) {
  return 0.55 + 0.45 * std::abs(glm::dot(s.normal, glm::normalize(eye - s.position)));
}

glm::dvec3 curvature_colour(double k, double range) {
  const double t = std::clamp(k / range, -1.0, 1.0);
  return t >= 0.0 ? glm::dvec3(1.0, 1.0 - t, 1.0 - t) : glm::dvec3(1.0 + t, 1.0 + t, 1.0);
}

// The camera's frame at the mesh: towards the eye, right, up (the light lines' direction).
struct ViewFrame {
  glm::dvec3 towards_eye, right, up;
};
ViewFrame view_frame(const SurfaceSamples& s, const glm::vec3& camera_up) {
  ViewFrame f;
  f.towards_eye = glm::normalize(s.eye - s.centre);
  glm::dvec3 r = glm::cross(glm::dvec3(camera_up), f.towards_eye);
  if (!(glm::dot(r, r) > 1e-12))  // up along the view: any perpendicular will do
    r = glm::cross(std::abs(f.towards_eye.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), f.towards_eye);
  f.right = glm::normalize(r);
  f.up = glm::cross(f.towards_eye, f.right);
  return f;
}

// Whether the normal line of s meets the light plane within half a width of a light line.
bool on_highlight_line(const SurfaceSample& s, const SurfaceSamples& all, const ViewFrame& f,
                       const HighlightLineParams& h) {
  const double nv = glm::dot(s.normal, f.towards_eye);
  if (std::abs(nv) < 1e-9) return false;  // the normal line runs parallel to the plane
  const glm::dvec3 p = s.position - all.centre;
  const double t = (h.plane_distance * all.radius - glm::dot(p, f.towards_eye)) / nv;
  const double across = glm::dot(p + t * s.normal, f.right) / (h.spacing * all.radius);
  return std::abs(across - std::round(across)) < 0.5 * h.width;
}

}  // namespace

const char* to_string(SurfaceImageKind k) {
  return k == SurfaceImageKind::HighlightLines ? "highlight_lines" : "gaussian_curvature";
}

SurfaceImage surface_image(const SurfaceSamples& samples, const SurfaceImageOptions& options,
                           const glm::vec3& camera_up, const glm::vec4& background) {
  SurfaceImage out;
  const double r2 = samples.radius * samples.radius;
  out.curvature_range = options.curvature_range == 0.0 ? 2.0 / std::max(r2, 1e-300) : options.curvature_range;
  if (!(std::isfinite(out.curvature_range) && out.curvature_range > 0.0))
    throw InputError("--curvature-range: must be a positive finite number (got " +
                     std::to_string(options.curvature_range) + ")");
  const HighlightLineParams& h = options.highlight;
  if (!(std::isfinite(h.spacing) && h.spacing > 0.0))
    throw InputError("--highlight-spacing: must be a positive finite number (got " + std::to_string(h.spacing) + ")");
  if (!(h.width > 0.0 && h.width <= 1.0))
    throw InputError("--highlight-width: must be in (0, 1], a fraction of the spacing (got " +
                     std::to_string(h.width) + ")");
  if (!std::isfinite(h.plane_distance)) throw std::invalid_argument("surface_image: plane distance not finite");
  const ViewFrame frame = view_frame(samples, camera_up);
  out.image.width = samples.width;
  out.image.height = samples.height;
  out.image.pixels.resize(std::size_t(samples.width) * std::size_t(samples.height) * 3);
  double sum = 0.0;
  std::size_t counted = 0;
  out.min_curvature = std::numeric_limits<double>::infinity();
  out.max_curvature = -out.min_curvature;
  for (int y = 0; y < samples.height; ++y)
    for (int x = 0; x < samples.width; ++x) {
      const SurfaceSample& s = samples.pixels[std::size_t(y) * std::size_t(samples.width) + std::size_t(x)];
      glm::dvec3 c(background);
      if (s.covered) {
        ++out.covered;
        out.max_position_deviation = std::max(out.max_position_deviation, s.position_deviation);
        if (s.normal == glm::dvec3(0.0) || !std::isfinite(s.gaussian_curvature)) {
          ++out.no_normal;
          c = glm::dvec3(0.0);
        } else if (options.kind == SurfaceImageKind::GaussianCurvature) {
          c = curvature_colour(s.gaussian_curvature, out.curvature_range) * headlight(s, samples.eye);
        } else {
          c = on_highlight_line(s, samples, frame, options.highlight) ? glm::dvec3(0.05)
                                                                       : glm::dvec3(0.95 * headlight(s, samples.eye));
        }
        if (std::isfinite(s.gaussian_curvature)) {
          sum += s.gaussian_curvature;
          ++counted;
          out.min_curvature = std::min(out.min_curvature, s.gaussian_curvature);
          out.max_curvature = std::max(out.max_curvature, s.gaussian_curvature);
        }
      }
      // Files are written top row first; the samples are in GL rows.
      std::uint8_t* px = &out.image.pixels[(std::size_t(samples.height - 1 - y) * std::size_t(samples.width) + std::size_t(x)) * 3];
      for (int k = 0; k < 3; ++k) px[k] = unorm8(c[k]);
    }
  if (counted) out.mean_curvature = sum / double(counted);
  else out.min_curvature = out.max_curvature = 0.0;
  return out;
}

}  // namespace tessref::stats
