#pragma once
// The PN evaluation program over a batch of domain points (structure of arrays), the hot loop of
// PnTes::evaluate_batch. Plain floats only: the kernel is compiled twice from one source
// (pn_batch_kernel.inc), once for AVX2 (8 points per instruction) and once scalar, and both give
// the bits of PnTes::evaluate point by point (same operations in the same order; no contraction).
namespace tessref {

// One patch's control net in the canonical corner order x, y, z (see canonical.h): everything
// the evaluation reads, as PnTes::evaluate reads it.
struct PnBatchPatch {
  float p[3][3];        // corners P_x, P_y, P_z
  float t[6][3];        // tangent coefficients: xy, yx, yz, zy, xz, zx (b_rs next to r towards s)
  float center[3];      // b111
  float n[3][3];        // unit corner normals N_x, N_y, N_z
  float mid[3][3];      // mid-edge normals: xy, yz, xz
  float view_proj[16];  // column-major, as glm
  int quadratic;        // 1: quadratic normal field (both quadratic modes), 0: linear
};

// Evaluates `count` points. a, b, c: gl_TessCoord components weighting corners x, y, z. Writes
// gl_Position to clip[0..3][i] and the varyings (world position, world normal) to var[0..5][i].
using PnBatchKernel = void (*)(const PnBatchPatch& patch, int count, const float* a,
                               const float* b, const float* c, float* const clip[4],
                               float* const var[6]);

void pn_batch_scalar(const PnBatchPatch& patch, int count, const float* a, const float* b,
                     const float* c, float* const clip[4], float* const var[6]);
// Only on a CPU with AVX2 (cpu_has_avx2()).
void pn_batch_avx2(const PnBatchPatch& patch, int count, const float* a, const float* b,
                   const float* c, float* const clip[4], float* const var[6]);

// The kernel for the current simd_path().
PnBatchKernel pn_batch_kernel();

}  // namespace tessref
