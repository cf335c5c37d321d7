#pragma once
// How a GLSL stage's interface variables meet tessref's stage structs. Between stages, values
// travel as words of "I/O slots": slot 0 is gl_Position, slot 1 + L is location L (4 words each,
// a double taking two), as StageVertex::attr (VS -> TCS -> TES) and ClipVertex varyings (TES -> FS,
// location L at varyings[4L]). Per-patch variables use PatchOutput::patch[L].
#include <cstdint>
#include <string>
#include <vector>

#include "shader/executor.h"

namespace tessref::glsl {

// One scalar of a variable: its word in the variable (per element, for arrayed variables) and its
// word in the I/O slot space.
struct IoWord {
  std::uint32_t var_word = 0;
  std::uint32_t io_word = 0;
  shader::Scalar scalar = shader::Scalar::F32;
};

enum class IoKind { User, Position, TessLevelOuter, TessLevelInner, PrimitiveId, InvocationId,
                    PatchVertices, TessCoord, FragCoord, FrontFacing, HelperInvocation, VertexId, InstanceId,
                    PointSize, ClipDistance, FragDepth, Other };

struct IoVariable {
  const shader::Variable* variable = nullptr;
  const shader::VariableSlot* slot = nullptr;
  IoKind kind = IoKind::User;
  bool arrayed = false;      // one element per patch vertex (gl_in[], gl_out[], tcs/tes arrays)
  bool patch = false;        // 'patch in' / 'patch out'
  std::uint32_t elements = 1;         // arrayed: the array length
  std::uint32_t element_words = 0;    // arrayed: words per element
  std::vector<IoWord> words;          // User and Position words (per element)
};

struct StageInterface {
  std::vector<IoVariable> inputs, outputs;
  std::uint32_t io_words_used = 0;  // 1 + the highest I/O word written or read
};

// Locations a 'patch' variable may use (before GlslProgram maps them to PatchOutput slots).
inline constexpr int kMaxPatchLocations = 256;

// The kind of a built-in variable (spv::BuiltIn); IoKind::Other for one the pipeline does not
// carry, which a program may not use (glsl_program.cpp refuses it by name).
IoKind kind_of_builtin(std::uint32_t builtin);

// Reads the interface of an executable. Throws shader::SpirvError naming the variable when a
// location is past tessref's limits (max_slots I/O slots of 4 words, slot 0 being gl_Position).
StageInterface read_interface(const shader::Executable& exe, int max_slots);

}  // namespace tessref::glsl
