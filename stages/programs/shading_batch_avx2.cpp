// The avx2 build of the shading batch kernels (this file alone is compiled with -mavx2).
#include "stages/programs/shading_batch.h"
#include "stages/programs/specular_pow.h"

namespace tessref::programs {
#define SHADING_SUFFIX avx2
#include "stages/programs/shading_batch_kernel.inc"
#undef SHADING_SUFFIX
}  // namespace tessref::programs
