#pragma once
// Debug shading (GLSL twin: normals.frag): the normalized interpolated world normal as a color,
// n * 0.5 + 0.5. Not flipped on back faces.
#include "raster/rasterizer.h"
// Reads the varyings at kVaryingPosition and kVaryingNormal (stages/tess_stage.h).

namespace tessref::programs {

struct NormalsShader final : FragmentProgram {
  // out_color: (n * 0.5 + 0.5, 1); out_normal (aux): (n, 1).
  FragmentOutput shade(const FragmentInput& in) const override;
  void shade_batch(FragmentBatch& batch) const override;  // same bits as shade()
};

}  // namespace tessref::programs
