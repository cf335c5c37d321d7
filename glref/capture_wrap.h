#pragma once
// A user's program made ready for transform feedback capture without reading its source: no
// pattern over the GLSL, no assumption about how main() is spelled or what the outputs mean.
// `main` is renamed by a macro defined after the #version line, and a main of tessref's appended
// that calls it and then records what the capture needs. Only the vertex and evaluation stages
// are wrapped (a control shader's barrier() must stay in its own main).
#include <string>

namespace tessref::glref {

// The capture's outputs from the evaluation shader, besides gl_Position.
inline constexpr const char* kCaptureTessCoord = "tessref_tess_coord";  // vec3 gl_TessCoord
inline constexpr const char* kCapturePrimitive = "tessref_primitive";   // int gl_PrimitiveID
// The vertex shader's uniform that is added to gl_InstanceID (instances drawn one at a time).
inline constexpr const char* kCaptureInstanceOffset = "tessref_instance_offset";

// Renames main (#define main tessref_user_main after #version) and appends `wrapper`, a
// definition of main that calls tessref_user_main() (after #undef main). GlError without #version.
std::string wrap_main(const std::string& source, const std::string& wrapper);

// The evaluation shader also writes gl_TessCoord and gl_PrimitiveID to kCaptureTessCoord and
// kCapturePrimitive.
std::string capture_evaluation_shader(const std::string& source);

// The vertex shader reads gl_InstanceID + kCaptureInstanceOffset wherever it reads gl_InstanceID,
// so that instance k drawn alone (instance count 1) sees k. The uniform is declared after the
// #version and #extension lines.
std::string capture_vertex_shader(const std::string& source);

}  // namespace tessref::glref
