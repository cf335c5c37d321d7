#pragma once
// A verify report written by hand, with the keys `tessref verify` writes and small images, so
// that --merge and --html can be tested without a GL driver.
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "io/image_output.h"

namespace tessref::test {

// folder/stem.json and folder/stem/{tessref,reference,difference,heat}.png. A failing report has
// severity 2 (a failure), a passing one `severity`.
inline void write_fake_report(const std::filesystem::path& folder, const std::string& stem, bool pass, double severity) {
  std::filesystem::create_directories(folder / stem);
  nlohmann::json j;
  j["scene"] = "scenes/" + stem + ".json";
  j["reference"] = "captures/" + stem;
  j["driver"] = "llvmpipe (LLVM 15.0.6, 256 bits)";
  j["driver_version"] = "4.5 (Core Profile) Mesa 22.3.6";
  j["width"] = 64;
  j["height"] = 64;
  j["pass"] = pass;
  j["severity"] = pass ? severity : 2.0;
  j["failures"] = pass ? nlohmann::json::array() : nlohmann::json::array({"Hausdorff distance 2e-05 of the diagonal "
                                                                          "(limit 1e-05; worst: patch 17)"});
  j["warnings"] = nlohmann::json::array();
  j["diagonal"] = 3.25;
  j["sets"] = nlohmann::json::array({"tessellation.inner=7", "camera.eye=0,1,4"});
  j["tessellation"] = {{"patches", 256}, {"patches_mismatched", 0}, {"emitted_vertices", 194304},
                       {"first_mismatched_patch", -1}};
  j["surface_distance"] = {{"hausdorff_of_diagonal", pass ? 6.25e-8 : 2e-5},
                           {"worst_patches", {{{"patch", 17}, {"distance_of_diagonal", 2e-5}},
                                              {{"patch", 4}, {"distance_of_diagonal", 1e-6}}}}};
  j["silhouette"] = {{"mismatched", 3}, {"beyond_limit", 0}, {"max_distance_px", 0.25},
                     {"worst_pixels", {{12, 40, 0.25}, {13, 40, 0.125}}}};
  j["coverage"] = {{"mismatched", 0}};
  j["cracks"] = {{"shared_edges", 384}, {"rays", 1536}, {"rays_through", 0}, {"cracked_edges", 0},
                 {"max_gap_of_diagonal", 0.0}, {"worst", nlohmann::json::array()}};
  j["color"] = {{"within_1_255", 4096}, {"within_2_255", 4096}, {"pixels", 4096}, {"max_difference_255", 1},
                {"psnr_db", 58.5}};
  j["limits"] = {{"max_distance_of_diagonal", 1e-5}, {"silhouette_px", 0.5}};
  std::ofstream(folder / (stem + ".json")) << j.dump(2) << "\n";
  const char* names[4] = {"tessref.png", "reference.png", "difference.png", "heat.png"};
  for (int k = 0; k < 4; ++k) {
    Rgb8Image img{64, 64, std::vector<std::uint8_t>(64 * 64 * 3)};
    for (int i = 0; i < 64 * 64; ++i) {  // a different gradient per image: never blank
      img.pixels[3 * i + 0] = std::uint8_t(i % 64 * 4);
      img.pixels[3 * i + 1] = std::uint8_t(i / 64 * 4);
      img.pixels[3 * i + 2] = std::uint8_t(60 * k);
    }
    write_rgb8_image(img, folder / stem / names[k]);
  }
}

}  // namespace tessref::test
