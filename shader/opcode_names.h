#pragma once
// SPIR-V opcode names (generated from the SPIR-V headers by shader/CMakeLists.txt).
namespace tessref::shader {

// "OpImageGather" for its number; nullptr for a number the headers do not name.
const char* opcode_name(unsigned opcode);

}  // namespace tessref::shader
