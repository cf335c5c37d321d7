#include "stages/schemes/pn_batch.h"

#include "common/simd.h"

namespace tessref {

PnBatchKernel pn_batch_kernel() {
  return simd_path() == SimdPath::Avx2 ? pn_batch_avx2 : pn_batch_scalar;
}

}  // namespace tessref
