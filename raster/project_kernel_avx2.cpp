// The AVX2 + FMA build of the projection kernel (this file alone is compiled with -mavx2 -mfma;
// no glm and no std inline functions, for the reason pn_batch_kernel.inc gives). Mirrors
// clip_outcode (clip.h) and to_window (setup.cpp) operation for operation.
#include "raster/project_kernel.h"

namespace tessref::raster {

bool project_kernel_available() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

void project_vertices_avx2(const float* clip, std::size_t stride, std::size_t count,
                           const ProjectParams& p, ProjectedVertex* out) {
  using namespace outcode;
  for (std::size_t i = 0; i < count; ++i) {
    const float* v = clip + i * stride;
    const float x = v[0], y = v[1], z = v[2], w = v[3];
    ProjectedVertex& o = out[i];
    if (!__builtin_isfinite(x) || !__builtin_isfinite(y) || !__builtin_isfinite(z) ||
        !__builtin_isfinite(w)) {
      o.code = kNonFinite;
      continue;
    }
    std::uint32_t code = 0;
    if (p.guard_x * w - x < 0.0f) code |= kGuardRight;
    if (x + p.guard_x * w < 0.0f) code |= kGuardLeft;
    if (p.guard_y * w - y < 0.0f) code |= kGuardTop;
    if (y + p.guard_y * w < 0.0f) code |= kGuardBottom;
    if (z + w < 0.0f) code |= kNear;
    if (w - z < 0.0f) code |= kFar;
    if (x < -w) code |= kLeft;
    if (x > w) code |= kRight;
    if (y < -w) code |= kBottom;
    if (y > w) code |= kTop;
    if (!(w > 0.0f)) code |= kNonPositiveW;
    code &= p.code_mask;
    o.code = code;
    if (code & (kNonFinite | kNonPositiveW | kClipPlanes)) continue;
    const float inv_w = 1.0f / w;
    const float x_ndc = x * inv_w, y_ndc = y * inv_w, z_ndc = z * inv_w;
    o.xf = __builtin_fmaf(x_ndc, p.scale_x, p.translate_x);
    o.yf = __builtin_fmaf(y_ndc, p.scale_y, p.translate_y);
    o.x = static_cast<std::int32_t>(__builtin_nearbyintf(o.xf * 256.0f));
    o.y = static_cast<std::int32_t>(__builtin_nearbyintf(o.yf * 256.0f));
    const float zw = __builtin_fmaf(z_ndc, p.scale_z, p.translate_z);
    o.z = zw < p.depth_lo ? p.depth_lo : (p.depth_hi < zw ? p.depth_hi : zw);
    o.inv_w = inv_w;
  }
}

}  // namespace tessref::raster
