#pragma once
// A SPIR-V module read into plain tables: types with their flattened layout, constants, variables
// with their decorations, the entry point's execution modes and the body of its (only) function.
// The executor (executor.h) runs what this describes. Only logical addressing (OpenGL SPIR-V) is
// read; anything else is refused by name.
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace tessref::shader {

// Refused or malformed SPIR-V: what() names the construct.
class SpirvError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The most 32-bit words one value (a variable, a block) may hold: 16 MiB, GL's minimum
// GL_MAX_SHADER_STORAGE_BLOCK_SIZE. A larger type is kept without its layout and a variable of it
// is refused by name: the flattened layout below has an entry per scalar, so `float a[100000000]`
// would take gigabytes before the executor could say no.
inline constexpr std::uint64_t kMaxValueWords = std::uint64_t(1) << 22;

enum class Scalar : std::uint8_t { None, Bool, I32, U32, F32, F64 };
inline int scalar_words(Scalar s) { return s == Scalar::F64 ? 2 : 1; }

enum class TypeKind : std::uint8_t {
  Void, Bool, Int, Float, Vector, Matrix, Array, Struct, Pointer, Function, Image, Sampler,
  SampledImage, RuntimeArray
};

// One scalar of a type flattened into 32-bit words: values live at word offset `word` (a double
// takes two words, the low one first).
struct FlatComponent {
  std::uint32_t word = 0;
  Scalar scalar = Scalar::None;
};

struct Type {
  TypeKind kind = TypeKind::Void;
  Scalar scalar = Scalar::None;          // Bool/Int/Float, and the component of Vector/Matrix
  std::uint32_t element = 0;             // Vector/Matrix/Array/Pointer: element (column, pointee)
  std::uint32_t count = 0;               // Vector size, Matrix columns, Array length
  std::vector<std::uint32_t> members;    // Struct member type ids
  std::vector<std::uint32_t> member_word;  // Struct: word offset of each member
  std::uint32_t storage = 0;             // Pointer: storage class
  std::uint32_t words = 0;               // flattened size in 32-bit words
  std::vector<FlatComponent> flat;       // every scalar, in order
  std::uint32_t image_dim = 0;           // Image: Dim
  bool image_arrayed = false;
  bool image_depth = false;  // a shadow sampler's image (Depth 1)
  bool image_ms = false;
  std::uint32_t image_sampled_type = 0;
  bool image_storage = false;     // Sampled 2: a storage image (GLSL image2D ...), not a sampler's
  std::uint32_t image_format = 0; // a storage image's spv::ImageFormat (its layout(rgba32f) ...)
  bool runtime = false;  // Array: an OpTypeRuntimeArray (count set from the bound buffer, else 0)
  // Words of a type above kMaxValueWords (saturated), whose `words` and `flat` are then empty;
  // 0 for every type that fits.
  std::uint64_t oversized_words = 0;
};

struct Decorations {
  std::optional<std::uint32_t> location, component, binding, builtin, offset;
  std::optional<std::uint32_t> stream;  // a geometry shader output's vertex stream
  // Explicit layout (uniform blocks): ArrayStride on array types, MatrixStride and RowMajor on the
  // struct members that hold matrices.
  std::optional<std::uint32_t> array_stride, matrix_stride;
  bool row_major = false;
  bool patch = false, flat = false, noperspective = false, block = false, buffer_block = false;
};

struct Variable {
  std::uint32_t id = 0;
  std::uint32_t type = 0;     // the pointee type (not the pointer type)
  std::uint32_t storage = 0;  // spv::StorageClass
  std::string name;
  Decorations decorations;
  std::vector<Decorations> member_decorations;  // when the pointee (or its element) is a block
  std::optional<std::uint32_t> initializer;     // constant id
};

struct Instruction {
  std::uint16_t opcode = 0;
  std::uint32_t type = 0;    // result type id, 0 when none
  std::uint32_t result = 0;  // result id, 0 when none
  std::vector<std::uint32_t> operands;  // the words after type and result
  int line = 0;                         // from the last OpLine (0: none)
};

struct Block {
  std::uint32_t label = 0;
  std::vector<Instruction> body;  // phis first, the terminator last
};

enum class ExecutionModel { Vertex, TessControl, TessEval, Geometry, Fragment, Other };

struct ExecutionModes {
  int output_vertices = 0;               // TCS layout(vertices = N)
  std::uint32_t primitive = 0;           // TES: spv::ExecutionModeTriangles, Quads or Isolines
  std::uint32_t spacing = 0;             // TES: SpacingEqual, SpacingFractionalEven/Odd
  std::uint32_t order = 0;               // TES: VertexOrderCw / VertexOrderCcw
  bool point_mode = false;
  // Geometry shader: its input primitive's vertices (1 points, 2 lines, 3 triangles, 4 lines and
  // 6 triangles with adjacency), its output (spv::ExecutionModeOutputPoints, OutputLineStrip or
  // OutputTriangleStrip), max_vertices (output_vertices above) and invocations.
  int input_vertices = 0;
  std::uint32_t output_primitive = 0;
  int invocations = 1;
  bool origin_upper_left = false;
  // Fragment: layout(early_fragment_tests) in; the depth test runs before the shader, so fragments
  // that fail it run no invocation and make no side effects (GL 4.6 14.9).
  bool early_fragment_tests = false;
};

struct Module {
  ExecutionModel model = ExecutionModel::Other;
  std::string entry_name;
  ExecutionModes modes;
  std::uint32_t bound = 0;
  std::map<std::uint32_t, Type> types;
  std::map<std::uint32_t, std::vector<std::uint32_t>> constants;  // id -> flattened words
  std::map<std::uint32_t, std::uint32_t> constant_types;
  std::vector<Variable> variables;                                 // every OpVariable
  std::map<std::uint32_t, std::string> names;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> member_names;  // (struct, member)
  std::map<std::uint32_t, Decorations> type_decorations;  // OpDecorate on types (ArrayStride, Block)
  std::map<std::pair<std::uint32_t, std::uint32_t>, Decorations> member_decorations;  // (struct, member)
  std::map<std::uint32_t, std::string> files;                      // OpString id -> file name
  std::uint32_t glsl_std450 = 0;                                   // OpExtInstImport id, 0 if none
  std::vector<Block> blocks;                                       // the entry function, in order
  std::vector<Variable> function_variables;                        // OpVariable Function
  std::uint32_t entry_function = 0;

  const Type& type(std::uint32_t id) const;
  const Variable* variable(std::uint32_t id) const;
  std::string name_of(std::uint32_t id) const;  // OpName, or "%id"
};

// The bytes bound to each shader storage block binding (glBindBufferRange(GL_SHADER_STORAGE_BUFFER)):
// a block's runtime-sized last member gets (bytes - its Offset) / ArrayStride elements.
using StorageBufferSizes = std::map<std::uint32_t, std::size_t>;

// Reads a binary module. Throws SpirvError for malformed words, more than one function (the front
// end inlines everything) or constructs outside the executor's scope, naming the construct; and
// for a shader storage block with a runtime-sized array whose binding `storage` does not size;
// and for a variable larger than kMaxValueWords, naming it.
Module read_module(std::span<const std::uint32_t> words, const StorageBufferSizes& storage = {});

// A sampler or image type's GLSL name: "sampler2D", "isampler3D", "samplerCubeShadow",
// "sampler2DMSArray", ...
std::string sampler_glsl_name(const Module& m, const Type& t);

}  // namespace tessref::shader
