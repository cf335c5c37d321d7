#include "stages/draw_program.h"

#include <algorithm>

namespace tessref {

void DrawProgram::rasterizer_vertex(const StageVertex& shaded, ClipVertex* records) const {
  // I/O slot words (stages/glsl/glsl_interface.h): gl_Position, then location L at 4 + 4L, which
  // is varying 4L of the rasterizer's vertex.
  const auto* src = reinterpret_cast<const float*>(shaded.attr.data());
  auto* dst = reinterpret_cast<float*>(records);
  std::copy_n(src, 4 + std::min(varyings(), 4 * kMaxStageLocations), dst);
}

std::vector<CheckedOutput> DrawProgram::checked_outputs() const {
  std::vector<CheckedOutput> out;
  for (int s = 0; s <= kMaxStageLocations; ++s)
    out.push_back({s, s == 0 ? "gl_Position" : "location " + std::to_string(s - 1), 4});
  return out;
}

}  // namespace tessref
