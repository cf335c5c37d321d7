// The AVX2 build of the PN batch kernel (this file alone is compiled with -mavx2; see the
// warning at the top of pn_batch_kernel.inc).
#include "stages/schemes/pn_batch.h"

namespace tessref {
#define PN_BATCH_NAME pn_batch_avx2
#include "stages/schemes/pn_batch_kernel.inc"
#undef PN_BATCH_NAME
}  // namespace tessref
