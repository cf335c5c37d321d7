#pragma once
// piglit's .shader_test files (the format of piglit's tests/shaders/shader_runner.c), parsed into
// plain data for `tessref shader-test`. Parsing checks syntax only; whether tessref can run a
// file (its requirements, stages, commands) is the runner's call.
//
// Malformed input throws InputError (common/error.h) whose message is "FILE:LINE: what is wrong".
// Valid piglit syntax that this parser does not model is kept, never rejected: unknown [require]
// lines as raw lines, unmodelled sections as OtherSection, unknown [test] lines as
// CommandKind::Unknown.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tessref {

enum class Comparison { Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual };

// ---- [require] ----

enum class Profile { Any, Core, Compat, Es };

// "GL COMPAT >= 3.2", "GLSL >= 1.50", "GLSL ES >= 3.00". The minor number is normalized to the
// usual digits: GLSL has two ("4.5" -> 4, 50), GL one ("4.00" -> 4, 0).
struct VersionRequirement {
  Profile profile = Profile::Any;
  Comparison comparison = Comparison::GreaterEqual;
  int major = 0;
  int minor = 0;
};

// "GL_ARB_tessellation_shader", or "!GL_ARB_foo": the extension must be absent.
struct ExtensionRequirement {
  std::string name;
  bool negated = false;
};

// "GL_MAX_VARYING_COMPONENTS >= 128" or "INT GL_MAX_TESS_CONTROL_ATOMIC_COUNTER_BUFFERS >= 1".
struct LimitRequirement {
  std::string name;
  Comparison comparison = Comparison::GreaterEqual;
  long long value = 0;
};

struct RawLine {
  int line = 0;  // 1-based line in the file
  std::string text;
};

struct Requirements {
  std::optional<VersionRequirement> gl;
  std::optional<VersionRequirement> glsl;
  std::vector<ExtensionRequirement> extensions;
  std::vector<LimitRequirement> limits;
  std::optional<std::array<int, 2>> size;  // "SIZE w h": the window size
  // Every other line, e.g. "SPIRV YES", "depthbuffer", "SSO ENABLED" (comments are dropped).
  std::vector<RawLine> other;
};

// ---- shader sections ----

enum class ShaderStage { Vertex, TessControl, TessEvaluation, Geometry, Fragment, Compute };

enum class ShaderLanguage {
  Glsl,
  Passthrough,  // [vertex shader passthrough]: piglit's own `gl_Position = piglit_vertex`
  Spirv,        // [... shader spirv]: SPIR-V assembly
  ArbAssembly,  // [vertex program], [fragment program]: ARB_vertex/fragment_program
};

// One [... shader] section. A file may have several sections of one stage: they are linked
// together into that stage.
struct ShaderSection {
  ShaderStage stage = ShaderStage::Vertex;
  ShaderLanguage language = ShaderLanguage::Glsl;
  std::string source;  // verbatim: every line after the header up to the next section
  int first_line = 0;  // 1-based file line of the source's first line (the header's line + 1)
};

// A section that piglit knows and tessref does not model: [geometry layout], [shader include],
// [shader include paths], [... shader specializations].
struct OtherSection {
  std::string header;  // "[shader include]"
  std::string text;    // verbatim, as ShaderSection::source
  int first_line = 0;
};

// ---- types and [vertex data] ----

enum class ScalarType { Float, Double, Int, Uint, Bool };

// A GLSL scalar, vector or matrix type: vec3 = {Float, 1, 3}; mat2x3 = {Float, 2, 3} (2 columns
// of 3 rows, GLSL's matCxR).
struct GlslType {
  ScalarType scalar = ScalarType::Float;
  int columns = 1;
  int rows = 1;
};

// The data type of a [vertex data] column: how its numbers are stored in the buffer.
enum class DataType { Byte, Ubyte, Short, Ushort, Int, Uint, Float, Double };

// A column header "name[array_index]/data_type/glsl_type[/matrix_column]", where glsl_type is a
// type name (vec4, dmat3x2, int) or a component count (the older form "vertex/float/2", whose
// GLSL type is then a vector of the data type's kind).
struct VertexColumn {
  std::string name;  // the attribute, without "[array_index]"
  int array_index = 0;
  DataType data_type = DataType::Float;
  GlslType glsl_type;
  int matrix_column = 0;  // which column of a matrix attribute this column feeds
  // glsl_type.rows values per vertex, vertex after vertex. Float columns hold float-rounded
  // values; "0x..." numbers are bit patterns for float and double and two's complement for ints.
  std::vector<double> values;
};

struct VertexData {
  int first_line = 0;  // of the section's text
  int vertex_count = 0;
  std::vector<VertexColumn> columns;
};

// ---- [test] ----

// One kind per command: piglit's syntax, then where its arguments go in TestCommand (numbers in
// the order written, words).
enum class CommandKind {
  Unknown,                 // any other line; text keeps it for the runner to report
  Clear,                   // clear
  ClearColor,              // clear color R G B A: numbers r, g, b, a
  PatchVertices,           // patch parameter vertices N: numbers n
  PatchDefaultOuterLevel,  // patch parameter default level outer A B C D: numbers, 4 levels
  PatchDefaultInnerLevel,  // patch parameter default level inner A B: numbers, 2 levels
  // draw arrays MODE FIRST COUNT | draw arrays instanced MODE FIRST COUNT INSTANCES:
  //   words MODE (GL_PATCHES, GL_TRIANGLES...); numbers first, count, instances (1 if plain)
  DrawArrays,
  // draw rect [ortho] [patch] X Y W H | draw instanced rect [ortho] [patch] INSTANCES X Y W H:
  //   numbers x, y, w, h, instances (1 if plain); ortho: in window pixels instead of NDC;
  //   patch: one 4-vertex GL_PATCHES patch instead of a triangle strip. piglit feeds
  //   "draw instanced rect" without ortho or patch through gl_Vertex, the others through
  //   the piglit_vertex attribute.
  DrawRect,
  // uniform TYPE NAME VALUES...: words TYPE, NAME (may be "a[2]" or a location number);
  //   type; numbers, the values, a matrix column after column. Other types (int64_t,
  //   handle) are Unknown.
  Uniform,
  ProbeAll,  // probe all rgb|rgba COLOR: numbers, the colour (3 or 4)
  // probe rgb|rgba X Y COLOR | relative probe rgb|rgba (X, Y) (COLOR):
  //   numbers x, y, colour (3 or 4); relative: x, y are fractions of the window size
  Probe,
  // probe rect rgb|rgba (X, Y, W, H) (COLOR) | relative probe rect rgb|rgba (...) (...):
  //   numbers x, y, w, h, colour (3 or 4); relative as for Probe
  ProbeRect,
  Tolerance,            // tolerance T | tolerance R G B A: numbers as written
  AtomicCounters,       // atomic counters N: numbers n (zeroed counters in binding 0)
  AtomicCounterBuffer,  // atomic counter buffer B N: numbers binding, count
  AtomicCounterSet,     // atomic counter B I V: numbers binding, index, value
  // probe atomic counter I OP V: numbers index (in binding 0), value; comparison OP
  ProbeAtomicCounter,
  // probe atomic counter buffer B OFFSET OP V: numbers binding, byte offset, value; comparison
  ProbeAtomicCounterBuffer,
  SsboSize,     // ssbo B SIZE: numbers binding, bytes (a zeroed buffer bound at B)
  // ssbo B subdata TYPE OFFSET VALUES...: numbers binding, byte offset, values; type TYPE
  SsboSubData,
  // probe ssbo TYPE B OFFSET OP VALUE: numbers binding, byte offset, value; type; comparison
  ProbeSsbo,
  // texture checkerboard UNIT LEVEL (W, H) (COLOR0) (COLOR1):
  //   numbers unit, level, w, h, colour0 (4), colour1 (4)
  TextureCheckerboard,
  TextureRgbw,   // texture rgbw UNIT (W, H) [FORMAT]: numbers unit, w, h; words FORMAT if given
  TexParameter,  // texparameter TARGET NAME VALUE...: words, all ("2D", "min", "nearest")
  Enable,        // enable CAP: words CAP (GL_CLIP_PLANE0...)
  Disable,       // disable CAP: words CAP
  ClipPlane,     // clip plane I A B C D: numbers i, a, b, c, d
  Ortho,         // ortho (window-pixel projection) | ortho L R B T: numbers none | l, r, b, t
  NewList,       // newlist MODE (starts a display list): words MODE (GL_COMPILE...)
  EndList,       // endlist
  CallList,      // calllist
  DeleteList,    // deletelist
  LinkError,     // link error: the program must fail to link
  LinkSuccess,   // link success
};

struct TestCommand {
  CommandKind kind = CommandKind::Unknown;
  int line = 0;      // 1-based line in the file
  std::string text;  // the line without its comment, trimmed
  std::vector<double> numbers;
  std::vector<std::string> words;
  GlslType type;                              // Uniform, SsboSubData, ProbeSsbo
  Comparison comparison = Comparison::Equal;  // ProbeAtomicCounter*, ProbeSsbo
  bool relative = false;                      // Probe, ProbeRect
  bool ortho = false;                         // DrawRect
  bool patch = false;                         // DrawRect
};

struct ShaderTestFile {
  std::string file_name;
  Requirements requirements;
  std::vector<ShaderSection> shaders;  // in file order
  std::vector<OtherSection> other_sections;
  std::optional<VertexData> vertex_data;
  std::vector<TestCommand> commands;  // [test]; comment and blank lines left out
};

// file_name names the file in error messages and in ShaderTestFile::file_name; nothing is read.
ShaderTestFile parse_shader_test(const std::string& text, const std::string& file_name);
// Reads and parses a file; throws InputError if it cannot be read.
ShaderTestFile load_shader_test(const std::string& path);

}  // namespace tessref
