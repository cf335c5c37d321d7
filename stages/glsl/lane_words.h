#pragma once
// One scalar (1 word, or 2 for a double) between a plain word array and one lane of a per-lane
// variable: the stage adapters' way in and out of the executor's rows (a double's two rows hold
// the lanes' doubles contiguously, executor.h).
#include <cstdint>

#include "shader/executor.h"

namespace tessref::glsl {

inline void set_lane(shader::Invocations& inv, const shader::VariableSlot& slot, std::uint32_t word, shader::Scalar s,
                     int lane, const std::uint32_t* src) {
  std::uint32_t* row = inv.row(slot, word);
  if (s == shader::Scalar::F64) {
    row[2 * lane] = src[0];
    row[2 * lane + 1] = src[1];
  } else {
    row[lane] = src[0];
  }
}

inline void get_lane(shader::Invocations& inv, const shader::VariableSlot& slot, std::uint32_t word, shader::Scalar s,
                     int lane, std::uint32_t* dst) {
  const std::uint32_t* row = inv.row(slot, word);
  if (s == shader::Scalar::F64) {
    dst[0] = row[2 * lane];
    dst[1] = row[2 * lane + 1];
  } else {
    dst[0] = row[lane];
  }
}

}  // namespace tessref::glsl
