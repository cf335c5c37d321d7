#include "glref/capture_wrap.h"

#include "glref/gl_error.h"
#include "glref/shader_source.h"

namespace tessref::glref {
namespace {

// The position just past the last line that starts with #version or #extension: declarations
// may not come before an #extension directive.
std::size_t after_directives(const std::string& source) {
  std::size_t pos = 0, after = std::string::npos;
  while (pos < source.size()) {
    std::size_t eol = source.find('\n', pos);
    if (eol == std::string::npos) eol = source.size();
    const std::size_t first = source.find_first_not_of(" \t", pos);
    if (first < eol && (source.compare(first, 8, "#version") == 0 || source.compare(first, 10, "#extension") == 0))
      after = std::min(eol + 1, source.size());
    pos = eol + 1;
  }
  if (after == std::string::npos) throw GlError("shader source has no #version line");
  return after;
}

}  // namespace

std::string wrap_main(const std::string& source, const std::string& wrapper) {
  std::string out = inject_after_version(source, "#define main tessref_user_main\n");
  if (!out.empty() && out.back() != '\n') out += '\n';
  return out + "#undef main\n" + wrapper;
}

std::string capture_evaluation_shader(const std::string& source) {
  return wrap_main(source, std::string("out vec3 ") + kCaptureTessCoord + ";\nout int " + kCapturePrimitive +
                               ";\nvoid main() {\n  tessref_user_main();\n  " + kCaptureTessCoord +
                               " = gl_TessCoord;\n  " + kCapturePrimitive + " = gl_PrimitiveID;\n}\n");
}

std::string capture_vertex_shader(const std::string& source) {
  std::string out = source;
  const std::size_t at = after_directives(out);
  // A function-like use of the name is not possible (it is a variable), so an object-like macro
  // catches every read; the macro's own gl_InstanceID is not expanded again.
  out.insert(at, std::string("uniform int ") + kCaptureInstanceOffset + ";\n#define gl_InstanceID (gl_InstanceID + " +
                     kCaptureInstanceOffset + ")\n");
  return out;
}

}  // namespace tessref::glref
