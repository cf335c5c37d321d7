#pragma once
// The TES batch's columns into the vertex array: rows[16] are a ClipVertex's 16 floats in memory
// order (gl_Position x, y, z, w, then varyings 0..11; a zero row where a program writes none),
// `count` values each; vertex i is written to dst[16 i .. 16 i + 15]. A copy, so both builds
// (AVX2 and scalar, from vertex_store_kernel.inc) give the same bytes.
namespace tessref {

void store_vertices_scalar(const float* const rows[16], int count, float* dst);
void store_vertices_avx2(const float* const rows[16], int count, float* dst);
using StoreVerticesKernel = void (*)(const float* const rows[16], int count, float* dst);
StoreVerticesKernel store_vertices_kernel();  // for the current simd_path()

}  // namespace tessref
