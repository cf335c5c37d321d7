#pragma once
// Transform feedback against a capture: the buffers the driver wrote over each draw with
// draws[].transform_feedback (the capture's feedback.drawD.bufferB.bin, listed in its manifest)
// and tessref's (render/transform_feedback.h), byte for byte.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/transform_feedback.h"

namespace tessref {

struct FeedbackComparison {
  // One entry per buffer: draw, buffer, bytes on each side, identical, and where they first differ.
  nlohmann::json report = nlohmann::json::array();
  std::vector<std::string> failures;  // one line per buffer (or draw) that differs
};

// InputError when a file the manifest lists is missing or cannot be read.
FeedbackComparison compare_feedback(const std::filesystem::path& capture, const nlohmann::json& manifest,
                                    const std::vector<FeedbackBuffers>& mine);

}  // namespace tessref
