#pragma once
// The GLSL front-end: a program's shaders (GLSL source, OpenGL semantics) -> one legalized SPIR-V
// module per stage, ready for the executor. glslang compiles and links (OpenGL SPIR-V 1.0, like
// `glslangValidator -G --auto-map-locations --auto-map-bindings -g`); SPIRV-Tools validates,
// inlines every function into the entry point and promotes locals to SSA, keeping OpName and
// OpLine. What tessref accepts and rewrites is in docs/glsl.md.
#include <cstdint>
#include <string>
#include <vector>

#include "common/error.h"

namespace tessref::shader {

enum class Stage { Vertex, TessControl, TessEval, Geometry, Fragment };

// "vertex shader", "tessellation control shader", ..., as a GL linker names them.
const char* stage_name(Stage stage);

// GL_MAX_PATCH_VERTICES: the largest output patch (layout(vertices = N)) and GL_PATCH_VERTICES
// tessref takes; GL's minimum, and llvmpipe's value. stages/tess_stage.h's kMaxPatchVertices.
inline constexpr int kGlMaxPatchVertices = 32;

struct ShaderSource {
  Stage stage = Stage::Vertex;
  std::string file;    // for messages and OpLine
  int first_line = 1;  // the line of `file` where `text` starts (piglit sections start mid-file)
  std::string text;
  // A compatibility-profile context (piglit's shader_runner without a core requirement): the
  // fixed-function matrices, gl_Vertex and gl_FrontColor/gl_Color become declared variables
  // (glsl_rewrite.h) that the caller feeds. Otherwise they are refused by name.
  bool compatibility = false;
  // With `compatibility`, in the last stage before the rasterizer: GL_CLAMP_VERTEX_COLOR, on by
  // default in that profile, clamps gl_FrontColor and gl_FrontSecondaryColor to [0, 1].
  bool clamp_vertex_color = false;
};

// How the stages are linked (OpenGL 4.5, 7.3 and 7.4; GL_ARB_separate_shader_objects).
enum class Linking {
  Program,           // one program object
  SeparableProgram,  // one program with GL_PROGRAM_SEPARABLE set: its stages are linked together
                     // (GLSL 1.50 and later must redeclare the gl_PerVertex blocks they use)
  SeparatePrograms,  // each stage a separable program of its own, met in a program pipeline:
                     // no link-time check between stages (inputs without a match read undefined values)
};

struct CompiledStage {
  Stage stage = Stage::Vertex;
  std::vector<std::uint32_t> spirv;
  std::vector<std::string> rewrites;  // "FILE:LINE: what was rewritten", one per rewrite applied
};

struct CompiledProgram {
  std::vector<CompiledStage> stages;  // in pipeline order, one per stage present
};

// Compile and link errors, one "FILE:LINE: error: MESSAGE" line each (FILE: error: ... where no
// line applies). Bad input, so an InputError.
class CompileError : public InputError {
 public:
  using InputError::InputError;
};

// Several sources of one stage are compilation units linked into that stage. Interface variables
// without a location get one by name, the same in every stage (docs/glsl.md, "Locations").
CompiledProgram compile_program(const std::vector<ShaderSource>& sources, Linking linking = Linking::Program);

}  // namespace tessref::shader
