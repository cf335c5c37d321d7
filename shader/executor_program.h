#pragma once
// The decoded form of a SPIR-V entry point (internal to the executor): SSA ids become rows of the
// per-lane arena, instructions become fixed-size records with their operands' rows, and access
// chains, phis, terminators and composite copies go to side tables.
#include <cstdint>
#include <vector>

#include "shader/executor.h"
#include "texture/texture.h"

namespace tessref::shader {

inline constexpr std::uint32_t kNone = 0xffffffffu;

enum class XOp : std::uint16_t {
  Nop, Copy, Undef,
  // arithmetic, per component; `s` names the operand scalar
  Neg, Not, LogicalNot, Add, Sub, Mul, Div, Rem, Mod, Shl, Shr, Sar, And, Or, Xor,
  LogicalAnd, LogicalOr, LogicalEq, LogicalNe,
  OrdEq, OrdNe, OrdLt, OrdGt, OrdLe, OrdGe, UnordEq, UnordNe, UnordLt, UnordGt, UnordLe, UnordGe,
  IEq, INe, SLt, SGt, SLe, SGe, ULt, UGt, ULe, UGe,
  Select, IsNan, IsInf, Any, All,
  ConvFToS, ConvFToU, ConvSToF, ConvUToF, FConvert, Bitcast,
  Dot, VecTimesScalar, MatTimesScalar, VecTimesMat, MatTimesVec, MatTimesMat, OuterProduct,
  Transpose,
  Composite,  // construct / extract / insert / shuffle: aux = copy list
  ExtractDyn, InsertDyn,
  Load, Store, AccessChain, CopyMemory,
  Ext,  // GLSL.std.450: aux = instruction number, operands a, b, c
  BitCount, BitReverse, BitFieldInsert, BitFieldSExtract, BitFieldUExtract,
  DPdx, DPdy, Fwidth,
  Texture,  // aux = DecodedProgram::textures index
  // a: the value operand, b: a compare-exchange's comparator
  AtomicInc, AtomicDec, AtomicLoad, AtomicAdd, AtomicSub, AtomicStore, AtomicSMin, AtomicUMin,
  AtomicSMax, AtomicUMax, AtomicAnd, AtomicOr, AtomicXor, AtomicExchange, AtomicCompareExchange,
  Kill,
  Emit,  // EmitVertex / EndPrimitive (and the stream forms): aux = stream, b = 1 for an end
};

struct XIns {
  XOp op = XOp::Nop;
  Scalar s = Scalar::None;   // operand scalar
  std::uint16_t spv = 0;     // SPIR-V opcode, for messages
  std::uint32_t dst = kNone;  // result row
  std::uint32_t a = kNone, b = kNone, c = kNone, d = kNone;
  std::uint32_t n = 0;        // result components (or words, for copies)
  std::uint32_t aux = 0;      // side table index or a literal
  // Copy, Undef, Select of a whole value, InsertDyn, same-width Bitcast: DecodedProgram::doubles
  // index (kNone: none).
  std::uint32_t doubles = kNone;
  std::uint32_t m = 0;        // second dimension: matrix rows, vector size of an operand
  int line = 0;
};

// A texture instruction (OpImageSample*, OpImageFetch, OpImageQuery*): its operands' rows, kNone
// where absent. Constant operands (ConstOffset) are rows like any other.
struct TexOp {
  // ImageRead, ImageWrite, ImageAtomic: a storage image's texel (imageLoad, imageStore, the
  // image atomics); QuerySize of a storage image is imageSize.
  enum class Kind : std::uint8_t { Sample, Gather, Fetch, QuerySize, QueryLevels, QueryLod, ImageRead, ImageWrite, ImageAtomic };
  Kind kind = Kind::Sample;
  bool storage = false;         // `image` is an image unit (Invocations::bind_image), not a texture unit
  std::uint32_t texel = kNone;  // ImageWrite: the value; ImageAtomic: the operand
  std::uint32_t comparator = kNone;  // ImageAtomic, atomicCompSwap's
  XOp atomic = XOp::Nop;        // ImageAtomic: the operation (XOp::Atomic*)
  std::uint32_t image = kNone;  // the sampler's texture unit (one U32 row)
  std::uint32_t coord = kNone;  // float coordinates (Fetch: integer texel indices)
  std::uint32_t coord_comps = 0;
  bool proj = false;            // divide s and t by the coordinate's last component
  // The sampler's target: arrays take their layer from the coordinate component after s (1D) or
  // s and t (2D); buffer textures are read by texelFetch and textureSize alone.
  texture::Target target = texture::Target::k2D;
  // Sample without Lod or Grad: the LOD comes from the quad's derivatives of the coordinate in a
  // fragment shader, and is 0 in other stages (GLSL 4.60 8.9).
  bool implicit_lod = false;
  std::uint32_t bias = kNone, lod = kNone, grad_x = kNone, grad_y = kNone, offset = kNone;
  std::uint32_t dref = kNone;       // a shadow lookup's reference depth (divided by q for Proj)
  std::uint32_t component = kNone;  // Gather without a comparison: which component (an int)
  std::uint32_t offsets = kNone;    // textureGatherOffsets: four ivec2 constants, eight rows
};

// dst word w := src row's word sw, `words` rows in a row. doubles: index into
// DecodedProgram::doubles of the words where a double starts (kNone: none).
struct WordCopy {
  std::uint32_t dst_word, src, src_word, words;
  std::uint32_t doubles = kNone;
};

struct ChainStep {
  std::uint32_t index_reg = kNone;  // kNone: a constant index folded into `offset`
  Scalar index_scalar = Scalar::I32;
  std::uint32_t offset = 0;         // words added (constant steps)
  std::uint32_t stride = 0;         // words per element (dynamic steps)
  std::uint32_t length = 0;         // elements, for clamping (dynamic steps)
};

struct Chain {
  std::vector<ChainStep> steps;
};

// A memory access: the variable's slot, a per-lane offset register (or none) and a constant offset
// (access chains with constant indices are folded into it when decoding).
struct Access {
  std::uint32_t slot = 0;           // index into DecodedProgram::slots
  std::uint32_t offset_reg = kNone;
  std::uint32_t offset = 0;         // words
  std::vector<FlatComponent> flat;  // the accessed value's components
  std::uint32_t words = 0;
  std::uint32_t doubles = kNone;    // DecodedProgram::doubles of the value
};

struct Phi {
  std::uint32_t dst = 0;
  std::vector<FlatComponent> flat;
  std::uint32_t words = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> incoming;  // (value row, predecessor block)
};

enum class TermKind : std::uint8_t { Branch, Cond, Switch, Return, Kill, Unreachable };
struct Terminator {
  TermKind kind = TermKind::Return;
  std::uint32_t reg = kNone;  // condition or selector row
  std::uint32_t target = 0, other = 0;  // Branch/Cond targets (block indices); Switch default
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cases;  // (literal, block index)
  int line = 0;
};

struct XBlock {
  std::vector<Phi> phis;
  bool phis_overlap = false;  // a phi reads another phi's rows of this block: stage the copies
  std::uint32_t first = 0, count = 0;  // instructions in DecodedProgram::code
  Terminator term;
  // The merge block of a selection (`c ? a : b`, `a || b`, an if) with phis: the line of the
  // selection's branch, to which the source trace gives the values the phis take (the variables'
  // values where the paths meet: mem2reg leaves no store to show them). 0 otherwise.
  int join_line = 0;
};

struct DecodedProgram {
  std::vector<XIns> code;
  std::vector<XBlock> blocks;
  std::vector<VariableSlot> slots;  // every variable (module-level, then Function)
  std::vector<std::uint32_t> slot_of_id;  // id -> slot index, kNone if not a variable
  std::vector<std::vector<WordCopy>> copies;
  // Word offsets (within a copied value) where a double starts: its two rows hold the lanes
  // interleaved, so a masked copy must move whole doubles (Runner::copy_rows).
  std::vector<std::vector<std::uint32_t>> doubles;
  std::vector<Chain> chains;
  std::vector<Access> accesses;
  std::vector<TexOp> textures;
  bool fragment = false;  // a fragment shader: lanes are 2x2 quads
  // Arena layout: rows [0, constant_rows) hold constants, set once per Invocations; then SSA
  // registers; then per-lane variables.
  std::uint32_t arena_rows = 0;
  std::uint32_t shared_words = 0;  // common
  std::uint32_t group_words = 0;   // one group's block
  std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> constant_init;  // row, words
  std::vector<std::pair<std::uint32_t, Scalar>> constant_scalars;  // per constant word: its scalar
  // Per-lane variables to reset at begin(): (slot index, initializer words or empty for zero).
  std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> lane_resets;
  std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> shared_inits;  // initializers
  // For the traces (shader/nan_trace.h, shader/source_trace.h) only: the words of the SSA value or
  // constant that starts at each row (0 elsewhere), and each row's scalar (a double's second row,
  // and rows of no value: None).
  std::vector<std::uint32_t> value_words;
  std::vector<Scalar> row_scalar;
};

}  // namespace tessref::shader
