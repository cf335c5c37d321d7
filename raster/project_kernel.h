#pragma once
// The per-vertex clip-space work of a batch (outcode, perspective divide, viewport transform,
// snapping) as a plain-float kernel, built for AVX2 + FMA (project_kernel_avx2.cpp, -mavx2 -mfma:
// the viewport transform's fma and the snap's rounding become single instructions instead of libm
// calls). The portable path is project_vertices in setup.cpp (clip_outcode + to_window); both give
// the same bits (tests/raster/indexed_batch_test.cpp compares them).
#include <cstddef>
#include <cstdint>

namespace tessref::raster {

// One vertex after the per-vertex clip-space work, done once per vertex of a batch: its outcode
// (clip.h) and, when the vertex lies inside every clipping plane with w > 0, its window position.
// Triangles whose corners are all inside are set up from these alone.
struct ProjectedVertex {
  std::int32_t x, y;   // window coordinates, 24.8 fixed point
  float xf, yf;        // before snapping
  float z;             // window depth, clamped to the depth range (not with GL_DEPTH_CLAMP)
  float inv_w;
  std::uint32_t code;  // clip_outcode(); window fields are valid only if outcode_projectable(code)
};

// Outcode bits: planes that clip (the guard band sides, near, far; bits 0-5 in the order Mesa's
// draw module clips in: x <= w first, then x >= -w, y <= w, y >= -w, near, far; then the user
// planes, bits 12-19), the viewport sides, which only reject, and two bits that make a vertex
// unusable.
namespace outcode {
enum : std::uint32_t {
  kGuardRight = 1u << 0,
  kGuardLeft = 1u << 1,
  kGuardTop = 1u << 2,
  kGuardBottom = 1u << 3,
  kNear = 1u << 4,
  kFar = 1u << 5,
  kLeft = 1u << 6,
  kRight = 1u << 7,
  kBottom = 1u << 8,
  kTop = 1u << 9,
  kNonFinite = 1u << 10,  // some coordinate is NaN or infinite (no other bit is then set)
  kNonPositiveW = 1u << 11,
  // gl_ClipDistance[i] < 0 (or not finite) with GL_CLIP_DISTANCEi enabled: bit 12 + i. Mesa's draw
  // module clips against these after the six planes above (its plane indices 6 + i).
  kUserPlane0 = 1u << 12,
  kUserPlanes = 0xffu << 12,
  kClipPlanes = ((1u << 6) - 1) | kUserPlanes,
};
}  // namespace outcode

struct ProjectParams {
  float guard_x, guard_y;
  float scale_x, translate_x, scale_y, translate_y, scale_z, translate_z;  // x_w = fma(x_ndc, scale_x, translate_x), ...
  float depth_lo, depth_hi;  // window z is clamped to these (infinite with GL_DEPTH_CLAMP)
  std::uint32_t code_mask;   // the outcode bits that apply (without kNear and kFar with GL_DEPTH_CLAMP)
};

// clip: `count` vertices, `stride` floats apart, gl_Position first (a ClipVertex array).
// Needs a CPU with AVX2 and FMA (project_kernel_available()).
void project_vertices_avx2(const float* clip, std::size_t stride, std::size_t count,
                           const ProjectParams& params, ProjectedVertex* out);
bool project_kernel_available();

}  // namespace tessref::raster
