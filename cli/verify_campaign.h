#pragma once
// `tessref verify` over a folder of scenes (a campaign, optionally one shard of it) and the merge
// of the reports of its shards into one report and one HTML site.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/shard.h"
#include "common/parallel.h"
#include "verify/verify_scene.h"

namespace tessref::cli {

struct VerifyCampaign {
  std::filesystem::path scenes, captures, reports, html;  // html: "" for none
  std::vector<std::string> sets;                          // --set, applied to every scene
  Shard shard;
  VerifyLimits limits;
};

// Verifies every scene of the shard against captures/<stem>/, writing reports/<stem>.json and the
// images under reports/<stem>/; a progress line per scene on stderr. Every capture is checked
// before the first scene runs (InputError naming the scene without one). Returns the number of
// scenes that failed.
int run_verify_campaign(const VerifyCampaign& campaign, const Parallel& parallel);

// Reads every <stem>.json of the folders (InputError for a malformed report or a stem found twice)
// into the merged report: {"summary": {...}, "scenes": [{"name", "report"}...]} sorted by name, so
// that its bytes do not depend on how the campaign was sharded.
nlohmann::json merge_verify_reports(const std::vector<std::filesystem::path>& folders);

// merge_verify_reports written to json_out (if not "") and as a site into html (if not "").
// Returns the number of scenes that failed.
int run_verify_merge(const std::vector<std::filesystem::path>& folders, const std::filesystem::path& json_out,
                     const std::filesystem::path& html);

}  // namespace tessref::cli
