#pragma once
// The built-in fragment programs over a FragmentBatch (structure of arrays), the hot loops of
// PhongShader::shade_batch and NormalsShader::shade_batch. Plain floats only: compiled twice from
// shading_batch_kernel.inc, for AVX2 and scalar, both giving the bits of shade() lane by lane.

namespace tessref::programs {

inline constexpr int kMaxBatchLights = 8;  // = kMaxLights (phong.h)

struct PhongBatchUniforms {
  float eye[3];
  int num_lights;
  float light_position[kMaxBatchLights][3];
  float light_intensity[kMaxBatchLights][3];
  float ka, kd, ks, shininess;
  float color[3];
};

// lanes: columns of the arrays; pos and nrm: world position and normal (3 rows each); writes
// color (4 rows) and aux (4 rows) for every lane, live or not.
struct ShadingLanes {
  int lanes;
  const float* pos[3];
  const float* nrm[3];
  float* color[4];
  float* aux[4];
};

void phong_batch_scalar(const PhongBatchUniforms& u, const ShadingLanes& io);
void phong_batch_avx2(const PhongBatchUniforms& u, const ShadingLanes& io);
void normals_batch_scalar(const ShadingLanes& io);
void normals_batch_avx2(const ShadingLanes& io);

}  // namespace tessref::programs
