#pragma once
// `tessref stats [SCENE] [--set ...] --image KIND -o FILE`: seed 004's surface interrogation
// images (highlight lines, Gaussian curvature) and seed 000's fake-versus-real normals difference
// (stats/surface_images.h, stats/normal_mode_difference.h; docs/gallery.md).
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/parallel.h"

namespace tessref::cli {

struct StatsImageArgs {
  std::string kind;    // highlight_lines | gaussian_curvature | normal_mode_difference; empty: none
  std::string output;  // -o
  double curvature_range = 0.0;  // 0: 2 / r^2
  double highlight_spacing = 0.5, highlight_width = 0.3;
  double difference_scale = 16.0;
};

void add_stats_image_options(CLI::App* cmd, StatsImageArgs& args);

// The checks between options (InputError naming them); has_table: --table was given.
void check_stats_image_args(const StatsImageArgs& args, bool has_table);

// Draws the scene, writes the image to `temp` (the caller's OutputFiles entry for -o), prints a
// summary and returns it as JSON.
nlohmann::json run_stats_image(const std::string& scene, const std::vector<std::string>& sets,
                               const StatsImageArgs& args, const Parallel& parallel,
                               const std::filesystem::path& temp);

}  // namespace tessref::cli
