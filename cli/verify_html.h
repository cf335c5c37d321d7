#pragma once
// `tessref verify`'s report as HTML a person can look at: one page per scene (the driver's image,
// tessref's, their difference and the silhouette heat map side by side, the verdict, the failures,
// the figures, the worst patches and pixels) and an index of a campaign's scenes, worst first.
// Plain HTML and CSS: no script, no network; images are embedded as PNG data URIs.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tessref::cli {

// The four images of a scene, as verify --images writes them into one folder.
inline constexpr const char* kVerifyImageFiles[4] = {"tessref.png", "reference.png", "difference.png", "heat.png"};

// The PNG files of a scene, in kVerifyImageFiles' order.
using VerifyImages = std::array<std::filesystem::path, 4>;
VerifyImages verify_images_in(const std::filesystem::path& folder);

// One scene's page (a missing image is shown as missing); index_href links back to a campaign's
// index ("" for none).
std::string verify_scene_page(const nlohmann::json& report, const VerifyImages& images, const std::string& index_href);

struct SiteScene {
  std::string stem;                     // names the page: <stem>.html
  nlohmann::json report;                // verify's report
  std::filesystem::path image_folder;  // its images
};

// The campaign's index: a summary and every scene, sorted by severity (worst first; ties by name),
// each linking to <stem>.html.
std::string verify_index_page(const std::vector<SiteScene>& scenes);

// Writes site_folder/index.html and one <stem>.html per scene (the folder is created).
// InputError if it cannot, or for a scene named "index" (its page would be the index).
void write_verify_site(const std::filesystem::path& site_folder, const std::vector<SiteScene>& scenes);

}  // namespace tessref::cli
