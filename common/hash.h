#pragma once
// FNV-1a, 64 bits: the hash of tessref's hash tables (welding, the pattern cache) and of the
// scene a capture names. mix() takes one value a step: a byte for a byte-wise FNV-1a, a whole
// word where only the spread matters.
#include <cstdint>

namespace tessref {

struct Fnv1a {
  std::uint64_t h = 1469598103934665603ull;
  void mix(std::uint64_t v) { h = (h ^ v) * 1099511628211ull; }
};

}  // namespace tessref
