#include "common/malloc_tuning.h"

#include <malloc.h>

namespace tessref {

void keep_draw_buffers_off_mmap() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  mallopt(M_TOP_PAD, 64 << 20);
}

}  // namespace tessref
