#pragma once
// Errors from the real-GL runner: which EGL/GL call failed and the driver's code, or the info log.
#include <stdexcept>
#include <string>

namespace tessref::glref {

class GlError : public std::runtime_error {
 public:
  explicit GlError(const std::string& what) : std::runtime_error(what) {}
};

// Throws GlError naming `what` if glGetError() reports an error (drains all pending codes).
void check_gl(const char* what);
// "GL_INVALID_OPERATION (0x502)"
std::string gl_error_name(unsigned code);

}  // namespace tessref::glref
