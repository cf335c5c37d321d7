// The avx2 build of the vertex store kernel (compiled with -mavx2).
#include "stages/vertex_store.h"

namespace tessref {
#define STORE_NAME store_vertices_avx2
#include "stages/vertex_store_kernel.inc"
#undef STORE_NAME
}  // namespace tessref
