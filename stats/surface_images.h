#pragma once
// Surface interrogation images (seed 004, Figures 12-16): highlight lines and Gaussian curvature
// in false colour, pixel by pixel from the exact surface behind each fragment (surface_samples.h).
// The maps and their parameters are documented in docs/gallery.md.
#include <cstddef>
#include <string>

#include "io/image_output.h"
#include "stats/surface_samples.h"

namespace tessref::stats {

enum class SurfaceImageKind { HighlightLines, GaussianCurvature };
const char* to_string(SurfaceImageKind k);  // "highlight_lines" | "gaussian_curvature"

// Highlight lines (Beier and Chen): a family of parallel light lines in a light plane; a pixel is
// on a highlight line where its surface normal line {P + t n} meets the plane within half a line
// width of a light line. Here the plane faces the camera, perpendicular to the direction from the
// mesh's centre c to the eye, at plane_distance r from c towards the eye (r: the mesh's bounding
// radius, SurfaceSamples); the lines run along the camera's up direction, spacing r apart, and a
// line is width (a fraction of the spacing) wide. Tied to the mesh's size and the view, the same
// parameters suit every scene.
struct HighlightLineParams {
  double plane_distance = 2.0;
  double spacing = 0.5;
  double width = 0.3;
};

struct SurfaceImageOptions {
  SurfaceImageKind kind = SurfaceImageKind::GaussianCurvature;
  // Gaussian curvature: K = +range is full red, -range full blue, 0 white, linear between and
  // clamped beyond. 0: 2 / r^2 (K of a sphere of radius r / sqrt 2).
  double curvature_range = 0.0;
  HighlightLineParams highlight;
};

struct SurfaceImage {
  Rgb8Image image;  // top row first
  std::size_t covered = 0;         // pixels a fragment drew
  std::size_t no_normal = 0;       // covered pixels where du x dv vanished or K is not finite (black)
  double curvature_range = 0.0;    // the scale used (gaussian_curvature)
  // Gaussian curvature over covered pixels with a tangent plane, summed in pixel order.
  double mean_curvature = 0.0, min_curvature = 0.0, max_curvature = 0.0;
  double max_position_deviation = 0.0;  // the samples' largest chord error (surface_samples.h)
};

// InputError naming --curvature-range for a range that is not a positive finite number (0: the
// default), --highlight-spacing for a spacing that is not, --highlight-width outside (0, 1].
SurfaceImage surface_image(const SurfaceSamples& samples, const SurfaceImageOptions& options,
                           const glm::vec3& camera_up, const glm::vec4& background);

}  // namespace tessref::stats
