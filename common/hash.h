#pragma once
// FNV-1a, 64 bits: the hash of tessref's hash tables (welding, the pattern cache) and of the
// scene a capture names. mix() takes one value a step: a byte for a byte-wise FNV-1a, a whole
// word where only the spread matters.
#include <cstdint>
#include <cstring>

namespace tessref {

struct Fnv1a {
  std::uint64_t h = 1469598103934665603ull;
  void mix(std::uint64_t v) { h = (h ^ v) * 1099511628211ull; }
};

// Three floats by their bits, as a hash-table key: positions are joined only when bit-identical.
struct FloatBits3 {
  std::uint32_t bits[3];
  explicit FloatBits3(const float* f) { std::memcpy(bits, f, sizeof bits); }
  bool operator==(const FloatBits3& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
  struct Hash {
    std::size_t operator()(const FloatBits3& k) const {
      Fnv1a f;
      for (std::uint32_t b : k.bits) f.mix(b);
      return std::size_t(f.h);
    }
  };
};

}  // namespace tessref
