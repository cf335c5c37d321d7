#pragma once
// `tessref verify SCENE --gpu DIR`: an imported frame's tessref image against the GPU's image of it
// (cli/verify_gpu.cpp). Returns the exit status: 0 when every pixel is within 1/255, 1 when not.
#include <string>
#include <vector>

namespace tessref::cli {

int run_verify_gpu(const std::string& scene, const std::vector<std::string>& sets, const std::string& gpu, int threads);

}  // namespace tessref::cli
