#pragma once

namespace tessref {

// Both renderers allocate multi-megabyte buffers per draw (llvmpipe its per-draw buffers, tessref
// its tessellated chunks and setup scratch). With glibc's default thresholds these are mmapped and
// unmapped every draw, and every frame pays their page faults again (llvmpipe's level-64 work 3x
// slower, glref/README.md; tessref's Wuson level-12 tessellation 2.5x). Call first thing in main,
// before anything allocates: freed buffers then stay in the heap for the next draw.
void keep_draw_buffers_off_mmap();

}  // namespace tessref
