#include "stages/vertex_store.h"

#include "common/simd.h"

namespace tessref {

StoreVerticesKernel store_vertices_kernel() {
  return simd_path() == SimdPath::Avx2 ? store_vertices_avx2 : store_vertices_scalar;
}

}  // namespace tessref
