#pragma once

namespace tessref::glref {

// llvmpipe allocates multi-megabyte buffers per draw; with glibc's default thresholds they are
// mmapped and unmapped every draw, which makes level-64 work 3x slower (glref/README.md). Call
// first thing in main, before anything allocates.
void keep_draw_buffers_off_mmap();

}  // namespace tessref::glref
