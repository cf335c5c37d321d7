#pragma once
// Which vector width the batched kernels use. Every kernel has a scalar build and an AVX2 build of
// the same source (same operations in the same order, no contraction), so the choice changes speed
// only, never a bit of output; tests run both and compare.
namespace tessref {

enum class SimdPath { Scalar, Avx2 };

// The path in use: AVX2 where the CPU has it, unless TESSREF_SIMD=scalar is set in the
// environment or set_simd_path() chose otherwise.
SimdPath simd_path();
// For tests and benchmarks; asking for AVX2 on a CPU without it gives Scalar.
void set_simd_path(SimdPath path);
const char* to_string(SimdPath path);
bool cpu_has_avx2();

}  // namespace tessref
