#pragma once
// Triage of filled triangles before setup: what the setup pass can decide from the projected
// corners alone, many triangles at a time and without branches. A finely tessellated surface has
// most triangles far below a pixel (Wuson at level 12: 944,196 triangles of 0.28 px² on average,
// 78% covering no pixel centre); these only count in the statistics and need no setup at all.
#include <cstddef>
#include <cstdint>

#include "raster/project_kernel.h"

namespace tessref::raster {

// Small triangles: a bounding box of at most this many pixels has its covered centres found by
// setup (SetupTriangle::small_mask) and here.
inline constexpr int kSmallTrianglePixels = 8;
// Corners within this many 24.8 units of each other keep every product of the triage in 32 bits
// (differences < 2^12 and < 2^13 + 2^8 to a centre: products < 2^26); farther apart: kSetUp.
inline constexpr std::int32_t kTriageMaxExtent = 4096;

// The verdict for one triangle. kSetUp: setup_triangle decides (clipping, large or covering
// triangles, everything outside the fast path's bounds). The other two are exactly what
// setup_triangle would conclude: kCulled (zero snapped area or a culled face: SetupOutcome::kCulled)
// and kNoFragment (set up and counted as one rasterized piece, but no pixel centre is covered, so
// nothing is stored).
enum class Triage : std::uint8_t { kSetUp = 0, kCulled = 1, kNoFragment = 2 };

// Corners of n triangles as structure of arrays (24.8 window x and y; the corners' outcodes or'ed).
struct TriageCorners {
  static constexpr int kMax = 1024;
  alignas(32) std::int32_t x[3][kMax];
  alignas(32) std::int32_t y[3][kMax];
  alignas(32) std::uint32_t codes[kMax];
};

struct TriageParams {
  std::int32_t width, height;  // the framebuffer: pixel centres outside it do not count
  bool cull_front, cull_back, front_cw;  // FaceRule
};

// Verdicts for triangles first .. first + n - 1 (n <= TriageCorners::kMax) of a batch whose
// vertices were projected into `projected`: corner c of triangle i is projected[indices[3i + c]],
// or projected[3i + c] when indices is null. The same verdicts on every path (integer arithmetic
// only); the AVX2 kernel is used where the CPU has it and simd_path() is AVX2.
void triage_triangles(const ProjectedVertex* projected, const std::uint32_t* indices, std::size_t first,
                      int n, const TriageParams& params, Triage* out);

// The two kernels: the plain one writes out[first .. n), the AVX2 one (CPUs with AVX2 only)
// out[0 .. n).
void triage_kernel_scalar(const TriageCorners& corners, int first, int n, const TriageParams& params,
                          std::uint8_t* out);
void triage_kernel_avx2(const TriageCorners& corners, int n, const TriageParams& params,
                        std::uint8_t* out);

}  // namespace tessref::raster
