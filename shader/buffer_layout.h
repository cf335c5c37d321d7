#pragma once
// Uniform and storage block values from buffer bytes (and storage blocks' back into them): a block's members found at the byte offsets the module's
// explicit layout decorations give (Offset on struct members, ArrayStride on arrays, MatrixStride
// and RowMajor on matrix members: glslang writes std140's and std430's rules into them), and
// written in the executor's flattened word layout (Type::flat order).
#include <cstddef>
#include <cstdint>
#include <span>

#include "shader/spirv_module.h"

namespace tessref::shader {

// Bytes of a buffer a value of `type` (a block struct) occupies from its start: the end of its
// last member's last byte. A bound range must hold at least this many.
std::size_t explicit_layout_extent(const Module& m, std::uint32_t type);

// Reads a value of `type` from bytes (bytes.size() >= explicit_layout_extent) into out, which
// holds m.type(type).words words (a block's bool is a uint to glslang: its word as stored).
// Throws SpirvError for a member without the decorations that say where it lies.
void read_explicit_layout(const Module& m, std::uint32_t type, std::span<const std::byte> bytes,
                          std::uint32_t* out);

// The inverse of read_explicit_layout for a storage block's write-back: writes each scalar of
// `words` whose words differ from `original` (the values read at bind time) to its place in bytes,
// so that bytes the shaders did not change keep what another binding of them may have written.
void write_explicit_layout(const Module& m, std::uint32_t type, const std::uint32_t* words,
                           const std::uint32_t* original, std::span<std::byte> bytes);

}  // namespace tessref::shader
