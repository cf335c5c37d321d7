#pragma once
// What the benchmarks share on the llvmpipe side: one GL context for the process (null, with the
// reason on stderr, where none can be made; the llvmpipe benchmarks then skip).
#ifdef TESSREF_HAVE_GLREF
#include <cstdio>
#include <memory>

#include "glref/gl_context.h"

namespace tessref::bench {

inline glref::GlContext* gl_context() {
  static std::unique_ptr<glref::GlContext> ctx = [] {
    try {
      return std::make_unique<glref::GlContext>();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "llvmpipe baseline unavailable: %s\n", e.what());
      return std::unique_ptr<glref::GlContext>();
    }
  }();
  return ctx.get();
}

}  // namespace tessref::bench
#endif
