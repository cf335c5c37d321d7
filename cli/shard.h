#pragma once
// Campaigns over a folder of scenes, split into shards that run anywhere (Slurm job arrays,
// Kubernetes Indexed Jobs, a loop in a shell): shard I of N (0-based, like SLURM_ARRAY_TASK_ID and
// JOB_COMPLETION_INDEX) takes the scenes whose index in the name-sorted list is I modulo N.
#include <filesystem>
#include <string>
#include <vector>

namespace tessref::cli {

struct Shard {
  int index = 0;  // 0-based
  int count = 1;
  bool holds(std::size_t scene_index) const { return int(scene_index % std::size_t(count)) == index; }
};

// "I/N" with 0 <= I < N; "auto" or "auto/N": I (and N) from the environment: SLURM_ARRAY_TASK_ID
// (minus SLURM_ARRAY_TASK_MIN) and SLURM_ARRAY_TASK_COUNT, else JOB_COMPLETION_INDEX (Kubernetes;
// N must then be given, as auto/N, or in TESSREF_SHARD_COUNT). InputError naming `option` otherwise.
Shard parse_shard(const std::string& text, const std::string& option = "--shard");

struct CampaignScene {
  std::size_t index = 0;  // in the whole sorted folder, not the shard
  std::string stem;       // the file name without .json: names the capture and report folders
  std::filesystem::path path;
};

// SCENES_DIR/*.json sorted by name, those of `shard`. InputError when the folder has none.
std::vector<CampaignScene> campaign_scenes(const std::filesystem::path& folder, const Shard& shard);

}  // namespace tessref::cli
