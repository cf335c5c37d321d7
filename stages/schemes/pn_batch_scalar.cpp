// The scalar build of the PN batch kernel (compiled without auto-vectorization).
#include "stages/schemes/pn_batch.h"

namespace tessref {
#define PN_BATCH_NAME pn_batch_scalar
#include "stages/schemes/pn_batch_kernel.inc"
#undef PN_BATCH_NAME
}  // namespace tessref
