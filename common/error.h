#pragma once
// Errors at the boundary of the program (files, keys, levels) carry where they came from.
#include <stdexcept>
#include <string>

namespace tessref {

// A user-facing error: bad input, never a bug. The CLI prints what() and exits non-zero.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace tessref
