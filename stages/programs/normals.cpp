#include "stages/programs/normals.h"

#include "common/simd.h"
#include "stages/programs/shading_lanes.h"
#include "stages/tess_stage.h"

namespace tessref::programs {

FragmentOutput NormalsShader::shade(const FragmentInput& in) const {
  const float* v = in.varyings;
  glm::vec3 v_world_normal(v[kVaryingNormal], v[kVaryingNormal + 1],
                           v[kVaryingNormal + 2]);
  glm::vec3 n = glm::normalize(v_world_normal);
  FragmentOutput out;
  out.color = glm::vec4(n * 0.5f + 0.5f, 1.0f);
  out.aux = glm::vec4(n, 1.0f);
  return out;
}

void NormalsShader::shade_batch(FragmentBatch& batch) const {
  const ShadingLanes io = shading_lanes(batch);
  if (simd_path() == SimdPath::Avx2)
    normals_batch_avx2(io);
  else
    normals_batch_scalar(io);
}

}  // namespace tessref::programs
