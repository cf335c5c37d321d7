#pragma once
// One scene verified against one capture: tessref renders the scene, keeps its tessellated
// surface, and every comparison runs (verify/compare.h, silhouette.h, surface_distance.h,
// cracks.h). The result is a JSON report (deterministic: no times, no dates, so that sharded and
// unsharded campaigns give the same bytes) and the images a person looks at.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/parallel.h"
#include "io/image_output.h"

namespace tessref {

struct VerifyLimits {
  double max_distance = 1e-5;   // Hausdorff distance and position differences, share of the diagonal
  // Normals (mesh scenes): |n_driver - n_tessref| / max(|n_driver|, |n_tessref|) at the same patch
  // and gl_TessCoord. Measured on llvmpipe: 1.7e-7 with the built-in programs, 4.8e-4 for a user
  // shader that differentiates numerically (scenes/displacement.json); another normal formula
  // differs by 0.07 (docs/verification.md).
  double max_normal = 2e-3;
  double silhouette_px = 0.5;   // a coverage mismatch farther than this from the silhouette fails
  double color_share = 99.99;   // percent of pixels within 2/255 required
  bool cracks_fail = true;      // a ray through a shared edge fails the scene
};

struct VerifyResult {
  nlohmann::json report;
  // For a person: tessref's image, the driver's, their difference (x8) and the coverage heat map
  // (grey: covered by both; yellow: a mismatch within the limit of the silhouette; red: beyond).
  Rgb8Image tessref, reference, difference, heat;
  bool pass() const { return report.value("pass", false); }
};

// scene: a scene file ("" for the built-in default) with --set overrides; reference: a capture
// folder (tessref capture). InputError for bad input.
VerifyResult verify_scene(const std::string& scene, const std::vector<std::string>& sets,
                          const std::string& reference, const VerifyLimits& limits, const Parallel& parallel);

// The report as a few lines of text, for a terminal.
std::string verify_summary(const nlohmann::json& report);

}  // namespace tessref
