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
                    PointSize, ClipDistance, CullDistance, FragDepth, SampleMaskIn, Other };

// gl_ClipDistance[i], gl_CullDistance[i] and gl_PointSize as I/O words: past the 32 locations, so
// that they travel between stages (StageVertex) as the other outputs do. 8 distances each:
// GL_MAX_CLIP_DISTANCES and GL_MAX_CULL_DISTANCES.
inline constexpr std::uint32_t kMaxDistances = 8;
inline constexpr std::uint32_t kClipDistanceWord = 4 + 4 * 32;
inline constexpr std::uint32_t kCullDistanceWord = kClipDistanceWord + kMaxDistances;
inline constexpr std::uint32_t kPointSizeWord = kCullDistanceWord + kMaxDistances;

// Where a stage's outputs sit in the rasterizer's vertex (gl_Position, then varyings): the user
// varyings at their I/O words, then the clip distances, the cull distances and gl_PointSize the
// stage writes (the point size for a geometry shader's gl_in[]; the rasterizer draws 1-pixel points).
// Where the rasterizer's vertex (gl_Position, then the outputs as VaryingLayout places them)
// holds each 32-bit word of an output, in the order transform feedback records them (a double as
// two words, low first); -1 for a word the stage leaves unwritten. With the geometry shader's
// vertex stream it is emitted on (layout(stream = N), 0 without one).
struct OutputWords {
  std::vector<int> floats;
  int stream = 0;
};

struct VaryingLayout {
  int user = 0;            // varyings up to the last location written
  int clip = 0, cull = 0;  // gl_ClipDistance and gl_CullDistance elements written
  int point_size = 0;      // 1: gl_PointSize written
  int total() const { return user + clip + cull + point_size; }
  // The vertex float holding I/O word io; -1 when the vertex does not carry it.
  int float_of(std::uint32_t io) const {
    if (io < 4 + std::uint32_t(user)) return int(io);
    if (io >= kClipDistanceWord && io < kClipDistanceWord + std::uint32_t(clip)) return 4 + user + int(io - kClipDistanceWord);
    if (io >= kCullDistanceWord && io < kCullDistanceWord + std::uint32_t(cull))
      return 4 + user + clip + int(io - kCullDistanceWord);
    if (io == kPointSizeWord && point_size) return 4 + user + clip + cull;
    return -1;
  }
};

// A variable's I/O words: User, Position (gl_PerVertex blocks, whose gl_ClipDistance and
// gl_CullDistance members are carried with gl_Position) and the stand-alone distance arrays.
struct IoVariable {
  const shader::Variable* variable = nullptr;
  const shader::VariableSlot* slot = nullptr;
  IoKind kind = IoKind::User;
  bool arrayed = false;      // one element per patch vertex (gl_in[], gl_out[], tcs/tes arrays)
  bool patch = false;        // 'patch in' / 'patch out'
  std::uint32_t elements = 1;         // arrayed: the array length
  std::uint32_t element_words = 0;    // arrayed: words per element
  std::vector<IoWord> words;          // User, Position and distance words (per element)
  bool carries_words() const {
    return kind == IoKind::User || kind == IoKind::Position || kind == IoKind::ClipDistance ||
           kind == IoKind::CullDistance;
  }
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
