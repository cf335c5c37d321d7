#include "shader/buffer_layout.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace tessref::shader {
namespace {

// How a matrix (or an array of matrices) is laid out: from the struct member that holds it.
struct MatrixLayout {
  std::uint32_t stride = 0;
  bool row_major = false;
};

std::uint32_t scalar_bytes(Scalar s) { return s == Scalar::F64 ? 8 : 4; }

std::uint32_t array_stride(const Module& m, std::uint32_t type) {
  const auto it = m.type_decorations.find(type);
  if (it == m.type_decorations.end() || !it->second.array_stride)
    throw SpirvError("SPIR-V: array type " + m.name_of(type) + " in a uniform block has no ArrayStride");
  return *it->second.array_stride;
}

const Decorations& member_layout(const Module& m, std::uint32_t type, std::uint32_t k) {
  const auto it = m.member_decorations.find({type, k});
  if (it == m.member_decorations.end() || !it->second.offset)
    throw SpirvError("SPIR-V: member " + std::to_string(k) + " of " + m.name_of(type) +
                     " in a uniform block has no Offset");
  return it->second;
}

// Calls visit(byte, word, scalar) for every scalar of `type` at byte offset `byte` and word
// offset `word`.
template <class Visit>
void walk(const Module& m, std::uint32_t type, std::size_t byte, std::uint32_t word, MatrixLayout ml,
          const Visit& visit) {
  const Type& t = m.type(type);
  switch (t.kind) {
    case TypeKind::Bool:
    case TypeKind::Int:
    case TypeKind::Float: visit(byte, word, t.scalar); return;
    case TypeKind::Vector: {
      const std::uint32_t sb = scalar_bytes(t.scalar), sw = std::uint32_t(scalar_words(t.scalar));
      for (std::uint32_t i = 0; i < t.count; ++i) visit(byte + i * sb, word + i * sw, t.scalar);
      return;
    }
    case TypeKind::Matrix: {
      const Type& column = m.type(t.element);
      const std::uint32_t sb = scalar_bytes(column.scalar), sw = std::uint32_t(scalar_words(column.scalar));
      if (ml.stride == 0)
        throw SpirvError("SPIR-V: a matrix in a uniform block has no MatrixStride");
      for (std::uint32_t c = 0; c < t.count; ++c)
        for (std::uint32_t r = 0; r < column.count; ++r) {
          // Column-major: column c is a vector at c * stride; row-major: row r is one at r * stride.
          const std::size_t at = ml.row_major ? byte + r * ml.stride + c * sb : byte + c * ml.stride + r * sb;
          visit(at, word + c * column.words + r * sw, column.scalar);
        }
      return;
    }
    case TypeKind::Array: {
      const std::uint32_t stride = array_stride(m, type);
      const std::uint32_t ew = m.type(t.element).words;
      for (std::uint32_t e = 0; e < t.count; ++e) walk(m, t.element, byte + std::size_t(e) * stride, word + e * ew, ml, visit);
      return;
    }
    case TypeKind::Struct:
      for (std::uint32_t k = 0; k < t.members.size(); ++k) {
        const Decorations& d = member_layout(m, type, k);
        walk(m, t.members[k], byte + *d.offset, word + t.member_word[k],
             MatrixLayout{d.matrix_stride.value_or(0), d.row_major}, visit);
      }
      return;
    default:
      throw SpirvError("SPIR-V: " + m.name_of(type) + " cannot be read from a uniform buffer");
  }
}

}  // namespace

std::size_t explicit_layout_extent(const Module& m, std::uint32_t type) {
  std::size_t end = 0;
  walk(m, type, 0, 0, {}, [&](std::size_t byte, std::uint32_t, Scalar s) { end = std::max(end, byte + scalar_bytes(s)); });
  return end;
}

void read_explicit_layout(const Module& m, std::uint32_t type, std::span<const std::byte> bytes,
                          std::uint32_t* out) {
  walk(m, type, 0, 0, {}, [&](std::size_t byte, std::uint32_t word, Scalar s) {
    if (byte + scalar_bytes(s) > bytes.size())
      throw SpirvError("uniform block read past its buffer range (" + std::to_string(bytes.size()) + " bytes)");
    std::memcpy(out + word, bytes.data() + byte, scalar_bytes(s));
  });
}

void write_explicit_layout(const Module& m, std::uint32_t type, const std::uint32_t* words,
                           const std::uint32_t* original, std::span<std::byte> bytes) {
  walk(m, type, 0, 0, {}, [&](std::size_t byte, std::uint32_t word, Scalar s) {
    const std::uint32_t n = scalar_bytes(s);
    if (byte + n > bytes.size() || std::memcmp(words + word, original + word, n) == 0) return;
    std::memcpy(bytes.data() + byte, words + word, n);
  });
}

}  // namespace tessref::shader
