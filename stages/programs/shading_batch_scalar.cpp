// The scalar build of the shading batch kernels.
#include "stages/programs/shading_batch.h"
#include "stages/programs/specular_pow.h"

namespace tessref::programs {
#define SHADING_SUFFIX scalar
#include "stages/programs/shading_batch_kernel.inc"
#undef SHADING_SUFFIX
}  // namespace tessref::programs
