#pragma once
// `tessref verify SCENE --gpu DIR`: an imported frame's tessref image against the GPU's image of it
// (cli/verify_gpu.cpp). Returns the exit status: 0 when every pixel is within 1/255, 1 when not.
#include <string>
#include <vector>

namespace tessref::cli {

int run_verify_gpu(const std::string& scene, const std::vector<std::string>& sets, const std::string& gpu, int threads);

// A campaign: every folder under `folder` that holds a scene.json (tessref import of a folder of
// captures), those of the shard, each against its own gpu.png. 0 when all pass, 1 when not.
int run_verify_gpu_folder(const std::string& folder, const std::string& shard, int threads);

}  // namespace tessref::cli
