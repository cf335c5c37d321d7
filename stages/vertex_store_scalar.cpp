// The scalar build of the vertex store kernel.
#include "stages/vertex_store.h"

namespace tessref {
#define STORE_NAME store_vertices_scalar
#include "stages/vertex_store_kernel.inc"
#undef STORE_NAME
}  // namespace tessref
