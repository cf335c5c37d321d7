#include "cli/stats_images.h"

#include <cstdio>

#include "common/error.h"
#include "mesh/camera.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "scene/scene_loader.h"
#include "stats/normal_mode_difference.h"
#include "stats/surface_images.h"

namespace tessref::cli {
namespace {

nlohmann::json surface(const Scene& scene, const Mesh& mesh, const StatsImageArgs& a,
                       const Parallel& parallel, const std::filesystem::path& temp) {
  stats::SurfaceImageOptions o;
  o.kind = a.kind == "highlight_lines" ? stats::SurfaceImageKind::HighlightLines
                                       : stats::SurfaceImageKind::GaussianCurvature;
  o.curvature_range = a.curvature_range;
  o.highlight = {o.highlight.plane_distance, a.highlight_spacing, a.highlight_width};
  const stats::SurfaceSamples samples = stats::sample_surface(scene, mesh, parallel, "--image");
  const stats::SurfaceImage img = stats::surface_image(samples, o, scene.camera.up, scene.background);
  write_rgb8_image(img.image, temp);
  std::printf("tessref stats --image %s: %s -> %s (%dx%d), scheme %s: %zu pixels covered (%zu without a "
              "tangent plane); mesh radius %.6g\n",
              a.kind.c_str(), scene.source.c_str(), a.output.c_str(), scene.width, scene.height,
              to_string(scene.tessellation.scheme), img.covered, img.no_normal, samples.radius);
  if (o.kind == stats::SurfaceImageKind::GaussianCurvature)
    std::printf("  colour: K = -%.6g full blue, 0 white, +%.6g full red (linear, clamped), times a headlight "
                "shade 0.55..1\n", img.curvature_range, img.curvature_range);
  else
    std::printf("  light plane %.6g r towards the eye, lines every %.6g r along the camera's up, %.6g of the "
                "spacing wide (r = mesh radius)\n",
                o.highlight.plane_distance, o.highlight.spacing, o.highlight.width);
  std::printf("  K over the pixels: mean %.6g, min %.6g, max %.6g; surface vs fragment position: max %.3g "
              "(the tessellation's chord error)\n",
              img.mean_curvature, img.min_curvature, img.max_curvature, img.max_position_deviation);
  return {{"image", a.kind}, {"scene", scene.source}, {"scheme", to_string(scene.tessellation.scheme)},
          {"width", scene.width}, {"height", scene.height}, {"covered", img.covered},
          {"no_tangent_plane", img.no_normal}, {"mesh_radius", samples.radius},
          {"curvature_range", img.curvature_range}, {"mean_curvature", img.mean_curvature},
          {"min_curvature", img.min_curvature}, {"max_curvature", img.max_curvature},
          {"max_position_deviation", img.max_position_deviation}};
}

nlohmann::json normal_modes(const Scene& scene, const Mesh& mesh, const StatsImageArgs& a,
                            const Parallel& parallel, const std::filesystem::path& temp) {
  const stats::NormalModeDifference d = stats::compare_normal_modes(
      scene, mesh, NormalMode::Quadratic, NormalMode::Analytic, a.difference_scale, parallel, "--image");
  write_rgb8_image(d.image, temp);
  const double share = d.covered ? double(d.differing) / double(d.covered) : 0.0;
  std::printf("tessref stats --image normal_mode_difference: %s -> %s (%dx%d), scheme %s, quadratic ('fake') vs "
              "analytic ('real') normals\n"
              "  normals: max angle %.4g deg, mean %.4g deg over %zu pixels drawn by the same patch in both; "
              "%zu over 1 deg\n"
              "  colours: %zu of %zu covered pixels differ (%.2f%%), by up to %d/255; image = |difference| x %g\n",
              scene.source.c_str(), a.output.c_str(), scene.width, scene.height,
              to_string(scene.tessellation.scheme), d.max_angle_deg, d.mean_angle_deg, d.same_patch,
              d.angle_over_1deg, d.differing, d.covered, 100.0 * share, d.max_channel_difference,
              a.difference_scale);
  return {{"image", a.kind}, {"scene", scene.source}, {"scheme", to_string(scene.tessellation.scheme)},
          {"width", scene.width}, {"height", scene.height}, {"covered", d.covered},
          {"same_patch", d.same_patch}, {"max_angle_deg", d.max_angle_deg},
          {"mean_angle_deg", d.mean_angle_deg}, {"angle_over_1deg", d.angle_over_1deg},
          {"differing_pixels", d.differing}, {"differing_share", share},
          {"max_channel_difference", d.max_channel_difference}, {"difference_scale", a.difference_scale}};
}

}  // namespace

// The numbers are checked where they are used (stats/surface_images.cpp,
// stats/normal_mode_difference.cpp): InputError with the rule, exit 2.
void add_stats_image_options(CLI::App* cmd, StatsImageArgs& a) {
  cmd->add_option("--image", a.kind,
                  "draw the scene and write an image of its exact surface instead of tables: highlight_lines, "
                  "gaussian_curvature (false colour), or normal_mode_difference (quadratic vs analytic normals, "
                  "seed 000 Fig. 13); docs/gallery.md")
      ->check(CLI::IsMember({"highlight_lines", "gaussian_curvature", "normal_mode_difference"}));
  cmd->add_option("-o,--output", a.output, "--image: the image file (8-bit RGB, e.g. .png)");
  cmd->add_option("--curvature-range", a.curvature_range,
                  "--image gaussian_curvature: |K| shown at full red/blue (0: 2/r^2, r the mesh's radius)");
  cmd->add_option("--highlight-spacing", a.highlight_spacing,
                  "--image highlight_lines: light lines' spacing, in mesh radii")
      ->capture_default_str();
  cmd->add_option("--highlight-width", a.highlight_width,
                  "--image highlight_lines: a line's width, a fraction of the spacing")
      ->capture_default_str();
  cmd->add_option("--difference-scale", a.difference_scale,
                  "--image normal_mode_difference: the colour difference is multiplied by this")
      ->capture_default_str();
}

void check_stats_image_args(const StatsImageArgs& a, bool has_table) {
  if (a.kind.empty()) {
    if (!a.output.empty()) throw InputError("-o: writes the image of --image; give --image KIND too");
    return;
  }
  if (a.output.empty()) throw InputError("--image: needs -o FILE, the image to write");
  if (has_table) throw InputError("--image draws a scene; it does not combine with --table");
}

nlohmann::json run_stats_image(const std::string& scene_path, const std::vector<std::string>& sets,
                               const StatsImageArgs& a, const Parallel& parallel,
                               const std::filesystem::path& temp) {
  check_image_path(a.output, ImageKind::Color);
  Scene scene = load_scene(scene_path, sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
  scene.camera = fitted_camera(scene, mesh);
  return a.kind == "normal_mode_difference" ? normal_modes(scene, mesh, a, parallel, temp)
                                            : surface(scene, mesh, a, parallel, temp);
}

}  // namespace tessref::cli
