// Decoding a Module into the executor's program (executor_program.h).
#include <algorithm>
#include <map>
#include <string>

#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/GLSL.std.450.h>
#include <spirv/unified1/spirv.hpp>

#include "shader/executor_program.h"
#include "shader/opcode_names.h"

namespace tessref::shader {
namespace {

// The samplers the executor reads, for messages.
const std::string kSamplers =
    "sampler1D, sampler2D, samplerCube, their Array and Shadow forms, sampler3D, sampler2DRect and "
    "sampler2DRectShadow, samplerBuffer, and the isampler and usampler forms of each";

[[noreturn]] void unsupported(const Module& m, const Instruction& ins, const std::string& what) {
  std::string where = ins.line > 0 ? " (line " + std::to_string(ins.line) + ")" : "";
  const char* name = opcode_name(ins.opcode);
  throw SpirvError("unsupported construct" + where + ": " + what + " (" +
                   (name ? std::string(name) : "SPIR-V opcode " + std::to_string(ins.opcode)) + ")");
}

bool is_shared(const Module& m, const Variable& v) {
  switch (spv::StorageClass(v.storage)) {
    case spv::StorageClassUniform:
    case spv::StorageClassUniformConstant:
    case spv::StorageClassAtomicCounter:
    case spv::StorageClassWorkgroup:
      return true;
    case spv::StorageClassInput:
    case spv::StorageClassOutput: {
      const bool per_invocation_builtin =
          v.decorations.builtin && (*v.decorations.builtin == spv::BuiltInInvocationId ||
                                    *v.decorations.builtin == spv::BuiltInTessCoord);
      if (per_invocation_builtin) return false;
      if (m.model == ExecutionModel::TessControl) return true;
      if (m.model == ExecutionModel::TessEval) return v.storage == spv::StorageClassInput;
      return false;
    }
    default:
      return false;
  }
}

struct Decoder {
  const Module& m;
  DecodedProgram& p;
  std::vector<std::uint32_t> reg;        // id -> row, kNone
  std::vector<std::uint32_t> block_of;   // label id -> block index
  std::vector<std::uint32_t> chain_of;   // pointer id -> (chain's access: slot, offset reg)
  std::vector<std::uint32_t> chain_slot; // pointer id -> slot of its variable

  Decoder(const Module& mod, DecodedProgram& prog) : m(mod), p(prog) {
    reg.assign(m.bound, kNone);
    block_of.assign(m.bound, kNone);
    chain_of.assign(m.bound, kNone);
    chain_slot.assign(m.bound, kNone);
    p.slot_of_id.assign(m.bound, kNone);
  }

  std::uint32_t alloc_rows(std::uint32_t words) {
    // Far above ExecLimits::max_private_bytes (checked once the program is decoded): only keeps
    // the row count from wrapping around before that check.
    constexpr std::uint32_t kMaxRows = std::uint32_t(1) << 30;
    if (words > kMaxRows - p.arena_rows)
      throw SpirvError("an invocation needs more than " + std::to_string(std::uint64_t(kMaxRows) * 4 >> 30) +
                       " GiB of private memory");
    const std::uint32_t r = p.arena_rows;
    p.arena_rows += words;
    return r;
  }

  // For the traces (nan_trace.h, source_trace.h): which rows a value spans and each row's scalar.
  void describe_rows(std::uint32_t row, const Type& t) {
    if (p.value_words.size() < p.arena_rows) {
      p.value_words.resize(p.arena_rows, 0);
      p.row_scalar.resize(p.arena_rows, Scalar::None);
    }
    if (t.kind == TypeKind::Pointer) return;
    p.value_words[row] = t.words;
    for (const FlatComponent& c : t.flat) p.row_scalar[row + c.word] = c.scalar;
  }

  std::uint32_t value(const Instruction& ins, std::uint32_t id) {
    if (id >= reg.size() || reg[id] == kNone) unsupported(m, ins, "operand %" + std::to_string(id) + " has no value");
    return reg[id];
  }

  void add_variables() {
    auto add = [&](const Variable& v) {
      VariableSlot s;
      s.id = v.id;
      s.words = m.type(v.type).words;
      s.per_lane = !is_shared(m, v);
      s.per_group = !s.per_lane && (v.storage == spv::StorageClassInput || v.storage == spv::StorageClassOutput);
      s.storage = v.storage == spv::StorageClassUniform && v.decorations.buffer_block;
      if (s.per_lane) {
        s.base = alloc_rows(s.words);
      } else if (s.per_group) {
        s.base = p.group_words;
        p.group_words += s.words;
      } else {
        s.base = p.shared_words;
        p.shared_words += s.words;
      }
      const std::uint32_t index = std::uint32_t(p.slots.size());
      p.slots.push_back(s);
      p.slot_of_id[v.id] = index;
      chain_slot[v.id] = index;
      std::vector<std::uint32_t> init;
      if (v.initializer) {
        auto c = m.constants.find(*v.initializer);
        if (c == m.constants.end()) throw SpirvError("SPIR-V: variable initializer is not a constant");
        init = c->second;
      }
      const bool resets = v.storage == spv::StorageClassFunction ||
                          v.storage == spv::StorageClassPrivate ||
                          v.storage == spv::StorageClassOutput;
      if (s.per_lane && resets) p.lane_resets.push_back({index, init});
      if (!s.per_lane && !s.per_group && !init.empty()) p.shared_inits.push_back({index, init});
    };
    for (const Variable& v : m.variables) add(v);
    for (const Variable& v : m.function_variables) add(v);
  }

  void add_constants() {
    for (const auto& [id, words] : m.constants) {
      const std::uint32_t row = alloc_rows(std::uint32_t(words.size()));
      reg[id] = row;
      p.constant_init.push_back({row, words});
      const Type& t = m.type(m.constant_types.at(id));
      for (const FlatComponent& c : t.flat) p.constant_scalars.push_back({row + c.word, c.scalar});
      describe_rows(row, t);
    }
  }


  // Composite helpers: the type of a value id (result types are recorded while decoding).
  std::vector<std::uint32_t> value_type;

  std::uint32_t chain_access(const Instruction& ins, std::uint32_t pointer, const Type& pointee) {
    Access a;
    if (pointer >= chain_slot.size() || chain_slot[pointer] == kNone)
      unsupported(m, ins, "a pointer that is not a variable or an access chain");
    a.slot = chain_slot[pointer];
    a.offset_reg = chain_of[pointer];
    if (a.offset_reg == kNone) a.offset = static_offset[pointer];
    a.flat = pointee.flat;
    a.words = pointee.words;
    std::vector<std::uint32_t> starts;
    for (const FlatComponent& c : pointee.flat)
      if (c.scalar == Scalar::F64) starts.push_back(c.word);
    if (!starts.empty()) {
      p.doubles.push_back(std::move(starts));
      a.doubles = std::uint32_t(p.doubles.size() - 1);
    }
    p.accesses.push_back(std::move(a));
    return std::uint32_t(p.accesses.size() - 1);
  }

  void decode_block(const Block& b, XBlock& xb) {
    xb.first = std::uint32_t(p.code.size());
    for (std::size_t k = 0; k < b.body.size(); ++k) {
      const Instruction& ins = b.body[k];
      if (ins.opcode == spv::OpPhi) {
        Phi phi;
        const Type& t = m.type(ins.type);
        phi.dst = reg[ins.result];
        phi.flat = t.flat;
        phi.words = t.words;
        for (std::size_t i = 0; i + 1 < ins.operands.size(); i += 2)
          phi.incoming.push_back({value(ins, ins.operands[i]), block_index(ins, ins.operands[i + 1])});
        xb.phis.push_back(std::move(phi));
        continue;
      }
      if (k + 1 == b.body.size()) {
        decode_terminator(ins, xb.term);
        // A branch often has no line of its own: the block's last statement names the spot.
        for (std::size_t j = k; xb.term.line == 0 && j-- > 0;) xb.term.line = b.body[j].line;
        break;
      }
      decode(ins);
    }
    xb.count = std::uint32_t(p.code.size()) - xb.first;
    for (const Phi& a : xb.phis)
      for (const Phi& b : xb.phis)
        for (const auto& [value, pred] : b.incoming)
          if (value < a.dst + a.words && a.dst < value + b.words) xb.phis_overlap = true;
  }

  std::uint32_t block_index(const Instruction& ins, std::uint32_t label) {
    if (label >= block_of.size() || block_of[label] == kNone) unsupported(m, ins, "branch to an unknown block");
    return block_of[label];
  }

  void decode_terminator(const Instruction& ins, Terminator& t) {
    t.line = ins.line;
    const auto& o = ins.operands;
    switch (spv::Op(ins.opcode)) {
      case spv::OpBranch: t.kind = TermKind::Branch; t.target = block_index(ins, o.at(0)); break;
      case spv::OpBranchConditional:
        t.kind = TermKind::Cond;
        t.reg = value(ins, o.at(0));
        t.target = block_index(ins, o.at(1));
        t.other = block_index(ins, o.at(2));
        break;
      case spv::OpSwitch:
        t.kind = TermKind::Switch;
        t.reg = value(ins, o.at(0));
        t.other = block_index(ins, o.at(1));
        for (std::size_t i = 2; i + 1 < o.size(); i += 2) t.cases.push_back({o[i], block_index(ins, o[i + 1])});
        break;
      case spv::OpReturn:
      case spv::OpReturnValue: t.kind = TermKind::Return; break;
      case spv::OpKill:
      case spv::OpTerminateInvocation: t.kind = TermKind::Kill; break;
      case spv::OpUnreachable: t.kind = TermKind::Unreachable; break;
      default: unsupported(m, ins, "a block that does not end in a branch or return");
    }
  }

  XIns base(const Instruction& ins, XOp op) {
    XIns x;
    x.op = op;
    x.spv = ins.opcode;
    x.line = ins.line;
    if (ins.result) x.dst = reg[ins.result];
    if (ins.type) {
      const Type& t = m.type(ins.type);
      x.n = t.kind == TypeKind::Matrix ? t.count * m.type(t.element).count
            : t.kind == TypeKind::Vector ? t.count : 1;
      x.s = t.scalar;
    }
    return x;
  }

  Scalar scalar_of(std::uint32_t id) const {
    const Type& t = m.type(value_type.at(id));
    return t.scalar;
  }
  std::uint32_t comps_of(std::uint32_t id) const {
    const Type& t = m.type(value_type.at(id));
    return t.kind == TypeKind::Vector ? t.count : t.kind == TypeKind::Matrix ? t.count * m.type(t.element).count : 1;
  }

  void emit(XIns x) { p.code.push_back(x); }

  // OpImageSample*, OpImage*Gather, OpImageFetch and OpImageQuery* on a sampler of a target
  // tessref samples (kSamplers), any sampled type, or their shadow forms: one TexOp each.
  // The texture target an image type reads (refused: multisample images).
  texture::Target target_of(const Instruction& ins, const Type& image) {
    const bool arrayed = image.image_arrayed != 0;
    switch (image.image_ms ? spv::DimMax : spv::Dim(image.image_dim)) {
      case spv::Dim1D: return arrayed ? texture::Target::k1DArray : texture::Target::k1D;
      case spv::Dim2D: return arrayed ? texture::Target::k2DArray : texture::Target::k2D;
      case spv::Dim3D: return texture::Target::k3D;
      case spv::DimRect: return texture::Target::kRectangle;
      case spv::DimBuffer: return texture::Target::kBuffer;
      case spv::DimCube: return arrayed ? texture::Target::kCubeArray : texture::Target::kCube;
      default: break;
    }
    const std::string name = sampler_glsl_name(m, image);
    unsupported(m, ins, (name[0] == 'i' ? "an " : "a ") + name + " (tessref reads " + kSamplers +
                            ", and the image forms of the same targets)");
  }

  // imageLoad (OpImageRead) and imageStore (OpImageWrite) on a storage image.
  void image_access(const Instruction& ins, const std::vector<std::uint32_t>& o) {
    const Type& image = m.type(value_type.at(o.at(0)));
    TexOp t;
    t.storage = true;
    t.target = target_of(ins, image);
    if (texture::is_cube(t.target)) unsupported(m, ins, "a cube map image");
    t.image = value(ins, o[0]);
    t.coord = value(ins, o.at(1));
    t.coord_comps = comps_of(o[1]);
    XIns x = base(ins, XOp::Texture);
    if (ins.opcode == spv::OpImageRead) {
      t.kind = TexOp::Kind::ImageRead;
    } else {
      t.kind = TexOp::Kind::ImageWrite;
      t.texel = value(ins, o.at(2));
    }
    x.aux = std::uint32_t(p.textures.size());
    p.textures.push_back(t);
    emit(x);
  }

  // OpImageTexelPointer: the image's unit is loaded here, and the atomic that uses the pointer
  // becomes an ImageAtomic (texel_pointer).
  void image_texel_pointer(const Instruction& ins, const std::vector<std::uint32_t>& o) {
    const Type& image = m.type(pointee(o.at(0)));
    if (image.image_format != spv::ImageFormatR32i && image.image_format != spv::ImageFormatR32ui)
      unsupported(m, ins, "an atomic on an image that is not r32i or r32ui (GL 4.5's image atomics)");
    XIns load = base(ins, XOp::Load);
    load.dst = alloc_rows(1);
    load.n = 1;
    load.s = Scalar::U32;
    load.aux = chain_access(ins, o[0], image);
    emit(load);
    TexOp t;
    t.storage = true;
    t.kind = TexOp::Kind::ImageAtomic;
    t.target = target_of(ins, image);
    t.image = load.dst;
    t.coord = value(ins, o.at(1));
    t.coord_comps = comps_of(o[1]);
    texel_pointer[ins.result] = t;
  }
  std::map<std::uint32_t, TexOp> texel_pointer;  // OpImageTexelPointer result -> its image texel

  void texture(const Instruction& ins, const std::vector<std::uint32_t>& o) {
    const spv::Op op = spv::Op(ins.opcode);
    const Type& image = m.type(value_type.at(o.at(0)));
    TexOp t;
    t.target = target_of(ins, image);
    t.storage = image.image_storage;
    t.image = value(ins, o[0]);
    XIns x = base(ins, XOp::Texture);
    switch (op) {
      case spv::OpImageQuerySizeLod: case spv::OpImageQuerySize:
        t.kind = TexOp::Kind::QuerySize;
        if (o.size() > 1) t.lod = value(ins, o[1]);
        break;
      case spv::OpImageQueryLevels: t.kind = TexOp::Kind::QueryLevels; break;
      case spv::OpImageQueryLod:
        t.kind = TexOp::Kind::QueryLod;
        t.coord = value(ins, o.at(1));
        t.coord_comps = comps_of(o[1]);
        break;
      default: {
        const bool gather = op == spv::OpImageGather || op == spv::OpImageDrefGather;
        t.kind = op == spv::OpImageFetch ? TexOp::Kind::Fetch : gather ? TexOp::Kind::Gather : TexOp::Kind::Sample;
        t.proj = op == spv::OpImageSampleProjImplicitLod || op == spv::OpImageSampleProjExplicitLod ||
                 op == spv::OpImageSampleProjDrefImplicitLod || op == spv::OpImageSampleProjDrefExplicitLod;
        t.coord = value(ins, o.at(1));
        t.coord_comps = comps_of(o[1]);
        std::size_t at = 2;  // the image operands' mask, after Dref or the gather component
        switch (op) {
          case spv::OpImageSampleDrefImplicitLod: case spv::OpImageSampleDrefExplicitLod:
          case spv::OpImageSampleProjDrefImplicitLod: case spv::OpImageSampleProjDrefExplicitLod:
          case spv::OpImageDrefGather:
            t.dref = value(ins, o.at(at++));
            break;
          case spv::OpImageGather: t.component = value(ins, o.at(at++)); break;
          default: break;
        }
        const std::uint32_t mask = o.size() > at ? o[at] : 0u;
        const std::uint32_t known = std::uint32_t(spv::ImageOperandsBiasMask) | spv::ImageOperandsLodMask |
                                    spv::ImageOperandsGradMask | spv::ImageOperandsConstOffsetMask |
                                    spv::ImageOperandsOffsetMask | spv::ImageOperandsConstOffsetsMask;
        if (mask & ~known) unsupported(m, ins, "image operands other than bias, lod, gradients and offsets");
        std::size_t k = at + 1;  // operands follow the mask in the order of its bits
        auto next = [&] { return value(ins, o.at(k++)); };
        if (mask & spv::ImageOperandsBiasMask) t.bias = next();
        if (mask & spv::ImageOperandsLodMask) t.lod = next();
        if (mask & spv::ImageOperandsGradMask) {
          t.grad_x = next();
          t.grad_y = next();
        }
        if (mask & spv::ImageOperandsConstOffsetMask) t.offset = next();
        if (mask & spv::ImageOperandsOffsetMask) t.offset = next();
        if (mask & spv::ImageOperandsConstOffsetsMask) t.offsets = next();
        t.implicit_lod = t.kind == TexOp::Kind::Sample && t.lod == kNone && t.grad_x == kNone;
      }
    }
    x.aux = std::uint32_t(p.textures.size());
    p.textures.push_back(t);
    emit(x);
  }

  void decode(const Instruction& ins) {
    if (ins.result && aliased[ins.result]) return;  // nothing to run: see alias_of
    const auto& o = ins.operands;
    auto V = [&](std::size_t i) { return value(ins, o.at(i)); };
    auto simple = [&](XOp op, int nargs, Scalar s = Scalar::None) {
      XIns x = base(ins, op);
      if (nargs > 0) x.a = V(0);
      if (nargs > 1) x.b = V(1);
      if (nargs > 2) x.c = V(2);
      if (s != Scalar::None) x.s = s;
      else if (nargs > 0) x.s = scalar_of(o[0]);
      emit(x);
    };
    switch (spv::Op(ins.opcode)) {
      case spv::OpNop:
      case spv::OpSelectionMerge:
      case spv::OpLoopMerge:
      case spv::OpMemoryBarrier:
      case spv::OpLine:
      case spv::OpNoLine:
        return;
      case spv::OpEmitVertex:
      case spv::OpEndPrimitive:
      case spv::OpEmitStreamVertex:
      case spv::OpEndStreamPrimitive: {
        XIns x = base(ins, XOp::Emit);
        const bool stream = ins.opcode == spv::OpEmitStreamVertex || ins.opcode == spv::OpEndStreamPrimitive;
        x.aux = stream ? m.constants.at(o.at(0)).at(0) : 0u;  // GLSL: a constant integral expression
        x.b = ins.opcode == spv::OpEndPrimitive || ins.opcode == spv::OpEndStreamPrimitive;
        emit(x);
        return;
      }
      case spv::OpControlBarrier:  // lanes run in lock step (executor.h): a mark for the source trace
        emit(base(ins, XOp::Nop));
        return;
      case spv::OpExtInst: {
        if (o.at(0) != m.glsl_std450) return;  // NonSemantic debug info: nothing to run
        XIns x = base(ins, XOp::Ext);
        x.aux = o.at(1);
        switch (x.aux) {
          case GLSLstd450InterpolateAtCentroid:
          case GLSLstd450InterpolateAtSample:
          case GLSLstd450InterpolateAtOffset:
            unsupported(m, ins, "interpolateAtCentroid/Sample/Offset");
          default: break;
        }
        if (o.size() > 2) {
          x.a = V(2);
          x.s = scalar_of(o[2]);
          x.m = comps_of(o[2]);
        }
        const bool pointer_form = x.aux == GLSLstd450Modf || x.aux == GLSLstd450Frexp;
        const bool struct_form = x.aux == GLSLstd450ModfStruct || x.aux == GLSLstd450FrexpStruct;
        if (pointer_form || struct_form) {
          // Second result: a struct's second member, or staging rows stored through the pointer.
          x.n = x.m;
          const std::uint32_t first_words = x.n * std::uint32_t(scalar_words(x.s));
          if (struct_form) {
            x.c = x.dst + first_words;
          } else {
            const Type& pt = m.type(m.type(value_type.at(o[3])).element);
            x.b = chain_access(ins, o[3], pt);
            x.c = alloc_rows(pt.words);
          }
          emit(x);
          return;
        }
        if (o.size() > 3) x.b = V(3);
        if (o.size() > 4) x.c = V(4);
        emit(x);
        return;
      }
      case spv::OpUndef: {
        XIns x = base(ins, XOp::Undef);
        x.n = m.type(ins.type).words;
        x.doubles = doubles_in(ins.type, 0, x.n);
        emit(x);
        return;
      }
      case spv::OpCopyObject: {
        XIns x = base(ins, XOp::Copy);
        x.a = V(0);
        x.n = m.type(ins.type).words;
        x.doubles = doubles_in(ins.type, 0, x.n);
        emit(x);
        return;
      }
      case spv::OpFNegate: case spv::OpSNegate: simple(XOp::Neg, 1); return;
      case spv::OpNot: simple(XOp::Not, 1); return;
      case spv::OpLogicalNot: simple(XOp::LogicalNot, 1); return;
      case spv::OpFAdd: case spv::OpIAdd: simple(XOp::Add, 2); return;
      case spv::OpFSub: case spv::OpISub: simple(XOp::Sub, 2); return;
      case spv::OpFMul: case spv::OpIMul: simple(XOp::Mul, 2); return;
      case spv::OpFDiv: case spv::OpSDiv: simple(XOp::Div, 2); return;
      case spv::OpUDiv: simple(XOp::Div, 2, Scalar::U32); return;
      case spv::OpFRem: case spv::OpSRem: simple(XOp::Rem, 2); return;
      case spv::OpFMod: case spv::OpSMod: simple(XOp::Mod, 2); return;
      case spv::OpUMod: simple(XOp::Rem, 2, Scalar::U32); return;
      case spv::OpShiftLeftLogical: simple(XOp::Shl, 2, Scalar::U32); return;
      case spv::OpShiftRightLogical: simple(XOp::Shr, 2, Scalar::U32); return;
      case spv::OpShiftRightArithmetic: simple(XOp::Sar, 2, Scalar::I32); return;
      case spv::OpBitwiseAnd: simple(XOp::And, 2, Scalar::U32); return;
      case spv::OpBitwiseOr: simple(XOp::Or, 2, Scalar::U32); return;
      case spv::OpBitwiseXor: simple(XOp::Xor, 2, Scalar::U32); return;
      case spv::OpLogicalAnd: simple(XOp::LogicalAnd, 2); return;
      case spv::OpLogicalOr: simple(XOp::LogicalOr, 2); return;
      case spv::OpLogicalEqual: simple(XOp::LogicalEq, 2); return;
      case spv::OpLogicalNotEqual: simple(XOp::LogicalNe, 2); return;
      case spv::OpFOrdEqual: simple(XOp::OrdEq, 2); return;
      case spv::OpFOrdNotEqual: simple(XOp::OrdNe, 2); return;
      case spv::OpFOrdLessThan: simple(XOp::OrdLt, 2); return;
      case spv::OpFOrdGreaterThan: simple(XOp::OrdGt, 2); return;
      case spv::OpFOrdLessThanEqual: simple(XOp::OrdLe, 2); return;
      case spv::OpFOrdGreaterThanEqual: simple(XOp::OrdGe, 2); return;
      case spv::OpFUnordEqual: simple(XOp::UnordEq, 2); return;
      case spv::OpFUnordNotEqual: simple(XOp::UnordNe, 2); return;
      case spv::OpFUnordLessThan: simple(XOp::UnordLt, 2); return;
      case spv::OpFUnordGreaterThan: simple(XOp::UnordGt, 2); return;
      case spv::OpFUnordLessThanEqual: simple(XOp::UnordLe, 2); return;
      case spv::OpFUnordGreaterThanEqual: simple(XOp::UnordGe, 2); return;
      case spv::OpIEqual: simple(XOp::IEq, 2, Scalar::U32); return;
      case spv::OpINotEqual: simple(XOp::INe, 2, Scalar::U32); return;
      case spv::OpSLessThan: simple(XOp::SLt, 2, Scalar::I32); return;
      case spv::OpSGreaterThan: simple(XOp::SGt, 2, Scalar::I32); return;
      case spv::OpSLessThanEqual: simple(XOp::SLe, 2, Scalar::I32); return;
      case spv::OpSGreaterThanEqual: simple(XOp::SGe, 2, Scalar::I32); return;
      case spv::OpULessThan: simple(XOp::ULt, 2, Scalar::U32); return;
      case spv::OpUGreaterThan: simple(XOp::UGt, 2, Scalar::U32); return;
      case spv::OpULessThanEqual: simple(XOp::ULe, 2, Scalar::U32); return;
      case spv::OpUGreaterThanEqual: simple(XOp::UGe, 2, Scalar::U32); return;
      case spv::OpIsNan: simple(XOp::IsNan, 1); return;
      case spv::OpIsInf: simple(XOp::IsInf, 1); return;
      case spv::OpAny: case spv::OpAll: {
        XIns x = base(ins, ins.opcode == spv::OpAny ? XOp::Any : XOp::All);
        x.a = V(0);
        x.m = comps_of(o[0]);
        emit(x);
        return;
      }
      case spv::OpSelect: {
        XIns x = base(ins, XOp::Select);
        x.a = V(0);
        x.b = V(1);
        x.c = V(2);
        x.m = comps_of(o[0]);  // 1: one condition for every component
        x.n = m.type(ins.type).words;
        x.s = Scalar::U32;
        if (m.type(ins.type).kind == TypeKind::Vector && x.m > 1) {
          x.n = comps_of(o[1]);
          x.s = m.type(ins.type).scalar;
        } else {
          x.m = 1;
          x.s = Scalar::None;  // whole-value select, word by word
          x.doubles = doubles_in(ins.type, 0, x.n);
        }
        emit(x);
        return;
      }
      case spv::OpConvertFToS: simple(XOp::ConvFToS, 1); return;
      case spv::OpConvertFToU: simple(XOp::ConvFToU, 1); return;
      case spv::OpConvertSToF: case spv::OpConvertUToF: {
        XIns x = base(ins, ins.opcode == spv::OpConvertSToF ? XOp::ConvSToF : XOp::ConvUToF);
        x.a = V(0);
        x.aux = m.type(ins.type).scalar == Scalar::F64 ? 1u : 0u;
        x.s = scalar_of(o[0]);
        emit(x);
        return;
      }
      case spv::OpFConvert: simple(XOp::FConvert, 1); return;
      case spv::OpSConvert: case spv::OpUConvert: case spv::OpBitcast: {
        XIns x = base(ins, XOp::Bitcast);
        x.a = V(0);
        x.aux = scalar_words(m.type(ins.type).scalar) != scalar_words(scalar_of(o[0])) ? 1u : 0u;
        x.s = scalar_of(o[0]);
        x.m = comps_of(o[0]);
        if (x.aux == 0) x.doubles = doubles_in(ins.type, 0, m.type(ins.type).words);
        emit(x);
        return;
      }
      case spv::OpDot: {
        XIns x = base(ins, XOp::Dot);
        x.a = V(0);
        x.b = V(1);
        x.m = comps_of(o[0]);
        emit(x);
        return;
      }
      case spv::OpVectorTimesScalar: simple(XOp::VecTimesScalar, 2); return;
      case spv::OpMatrixTimesScalar: simple(XOp::MatTimesScalar, 2); return;
      case spv::OpVectorTimesMatrix: case spv::OpMatrixTimesVector:
      case spv::OpMatrixTimesMatrix: case spv::OpOuterProduct: case spv::OpTranspose: {
        const spv::Op op = spv::Op(ins.opcode);
        XIns x = base(ins, op == spv::OpVectorTimesMatrix ? XOp::VecTimesMat
                           : op == spv::OpMatrixTimesVector ? XOp::MatTimesVec
                           : op == spv::OpMatrixTimesMatrix ? XOp::MatTimesMat
                           : op == spv::OpOuterProduct ? XOp::OuterProduct : XOp::Transpose);
        x.a = V(0);
        if (o.size() > 1) x.b = V(1);
        x.s = m.type(ins.type).scalar;
        // Shapes: aux = columns of a, m = rows of a (a vector counts as one column).
        const Type& ta = m.type(value_type.at(o[0]));
        x.aux = ta.kind == TypeKind::Matrix ? ta.count : 1;
        x.m = ta.kind == TypeKind::Matrix ? m.type(ta.element).count : ta.count;
        if (o.size() > 1) {
          const Type& tb = m.type(value_type.at(o[1]));
          x.d = tb.kind == TypeKind::Matrix ? tb.count : 1;  // columns of b
          if (op == spv::OpOuterProduct) x.d = tb.count;
        }
        emit(x);
        return;
      }
      case spv::OpCompositeConstruct: {
        XIns x = base(ins, XOp::Composite);
        std::vector<WordCopy> cs;
        std::uint32_t w = 0;
        for (std::size_t i = 0; i < o.size(); ++i) {
          const std::uint32_t words = m.type(value_type.at(o[i])).words;
          cs.push_back({w, V(i), 0, words, doubles_in(value_type.at(o[i]), 0, words)});
          w += words;
        }
        x.n = w;
        x.aux = add_copies(std::move(cs));
        emit(x);
        return;
      }
      case spv::OpCompositeExtract: case spv::OpCompositeInsert: {
        const bool insert = ins.opcode == spv::OpCompositeInsert;
        const std::uint32_t composite = insert ? o.at(1) : o.at(0);
        std::uint32_t t = value_type.at(composite);
        std::uint32_t offset = 0;
        for (std::size_t i = insert ? 2 : 1; i < o.size(); ++i) {
          const Type& ct = m.type(t);
          if (ct.kind == TypeKind::Struct) {
            offset += ct.member_word.at(o[i]);
            t = ct.members.at(o[i]);
          } else {
            t = ct.element;
            offset += o[i] * m.type(t).words;
          }
        }
        const std::uint32_t part = m.type(t).words;
        XIns x = base(ins, XOp::Composite);
        std::vector<WordCopy> cs;
        const std::uint32_t ct = value_type.at(composite);
        if (insert) {
          const std::uint32_t all = m.type(ct).words;
          cs.push_back({0, V(1), 0, offset, doubles_in(ct, 0, offset)});
          cs.push_back({offset, V(0), 0, part, doubles_in(ct, offset, part)});
          cs.push_back({offset + part, V(1), offset + part, all - offset - part,
                        doubles_in(ct, offset + part, all - offset - part)});
          x.n = all;
        } else {
          cs.push_back({0, V(0), offset, part, doubles_in(ct, offset, part)});
          x.n = part;
        }
        x.aux = add_copies(std::move(cs));
        emit(x);
        return;
      }
      case spv::OpVectorShuffle: {
        const Type& t1 = m.type(value_type.at(o.at(0)));
        const std::uint32_t n1 = t1.count;
        const std::uint32_t cw = std::uint32_t(scalar_words(t1.scalar));
        XIns x = base(ins, XOp::Composite);
        std::vector<WordCopy> cs;
        for (std::size_t i = 2; i < o.size(); ++i) {
          const std::uint32_t sel = o[i];
          const std::uint32_t dw = std::uint32_t(i - 2) * cw;
          if (sel == 0xffffffffu) continue;  // undefined component: left as it was
          const std::uint32_t d = cw == 2 ? doubles_in(value_type.at(o[0]), 0, 2) : kNone;
          if (sel < n1) cs.push_back({dw, V(0), sel * cw, cw, d});
          else cs.push_back({dw, V(1), (sel - n1) * cw, cw, d});
        }
        x.n = std::uint32_t(o.size() - 2) * cw;
        x.aux = add_copies(std::move(cs));
        emit(x);
        return;
      }
      case spv::OpVectorExtractDynamic: case spv::OpVectorInsertDynamic: {
        const bool insert = ins.opcode == spv::OpVectorInsertDynamic;
        XIns x = base(ins, insert ? XOp::InsertDyn : XOp::ExtractDyn);
        x.a = V(0);
        x.b = V(1);
        if (insert) x.c = V(2);
        const Type& vt = m.type(value_type.at(o[0]));
        x.s = vt.scalar;
        x.m = vt.count;
        x.aux = std::uint32_t(scalar_of(o[insert ? 2 : 1]));  // index scalar
        if (insert) x.doubles = doubles_in(value_type.at(o[0]), 0, m.type(value_type.at(o[0])).words);
        emit(x);
        return;
      }
      case spv::OpAccessChain: case spv::OpInBoundsAccessChain: {
        const std::uint32_t base_ptr = o.at(0);
        if (base_ptr >= chain_slot.size() || chain_slot[base_ptr] == kNone)
          unsupported(m, ins, "an access chain into a pointer that is not a variable");
        chain_slot[ins.result] = chain_slot[base_ptr];
        std::uint32_t t = m.type(value_type.at(base_ptr)).element;
        Chain chain;
        ChainStep constant;
        for (std::size_t i = 1; i < o.size(); ++i) {
          const Type& ct = m.type(t);
          auto c = m.constants.find(o[i]);
          if (ct.kind == TypeKind::Struct) {
            const std::uint32_t k = c->second.at(0);
            constant.offset += ct.member_word.at(k);
            t = ct.members.at(k);
            continue;
          }
          const std::uint32_t elem = ct.element;  // component, column or array element
          const std::uint32_t stride = m.type(elem).words;
          const std::uint32_t length = ct.count;
          t = elem;
          if (c != m.constants.end()) {
            const std::uint32_t k = std::min(c->second.at(0), length ? length - 1 : 0u);
            constant.offset += k * stride;
          } else {
            ChainStep s;
            s.index_reg = V(i);
            s.index_scalar = scalar_of(o[i]);
            s.stride = stride;
            s.length = length;
            chain.steps.push_back(s);
          }
        }
        pointee_of[ins.result] = t;
        if (chain_of[base_ptr] == kNone) {
          constant.offset += static_offset[base_ptr];
          if (chain.steps.empty()) {  // constant indices only: folded, nothing to run
            static_offset[ins.result] = constant.offset;
            return;
          }
        }
        chain.steps.insert(chain.steps.begin(), constant);
        XIns x = base(ins, XOp::AccessChain);
        x.a = chain_of[base_ptr];  // kNone: the variable itself
        x.aux = std::uint32_t(p.chains.size());
        p.chains.push_back(std::move(chain));
        chain_of[ins.result] = x.dst;
        emit(x);
        return;
      }
      case spv::OpArrayLength: {  // a storage block's runtime array: as many elements as the range bound
        const Type& block = m.type(pointee(o.at(0)));
        const std::uint32_t count = m.type(block.members.at(o.at(1))).count;
        p.constant_init.push_back({reg[ins.result], {count}});
        p.constant_scalars.push_back({reg[ins.result], Scalar::U32});
        return;
      }
      case spv::OpLoad: {
        XIns x = base(ins, XOp::Load);
        x.aux = chain_access(ins, o.at(0), m.type(ins.type));
        emit(x);
        return;
      }
      case spv::OpStore: {
        XIns x = base(ins, XOp::Store);
        const std::uint32_t ptr = o.at(0);
        x.aux = chain_access(ins, ptr, m.type(value_type.at(o.at(1))));
        x.a = V(1);
        emit(x);
        return;
      }
      case spv::OpCopyMemory: {
        XIns x = base(ins, XOp::CopyMemory);
        const Type& t = m.type(pointee(o.at(1)));
        x.aux = chain_access(ins, o.at(0), t);
        x.b = chain_access(ins, o.at(1), t);
        x.dst = alloc_rows(t.words);  // staging rows
        emit(x);
        return;
      }
      case spv::OpBitCount: simple(XOp::BitCount, 1, Scalar::U32); return;
      case spv::OpBitReverse: simple(XOp::BitReverse, 1, Scalar::U32); return;
      case spv::OpBitFieldInsert: {
        XIns x = base(ins, XOp::BitFieldInsert);
        x.a = V(0); x.b = V(1); x.c = V(2); x.d = V(3);
        emit(x);
        return;
      }
      case spv::OpBitFieldSExtract: case spv::OpBitFieldUExtract: {
        XIns x = base(ins, ins.opcode == spv::OpBitFieldSExtract ? XOp::BitFieldSExtract : XOp::BitFieldUExtract);
        x.a = V(0); x.b = V(1); x.c = V(2);
        emit(x);
        return;
      }
      // Plain, coarse and fine derivatives alike, all fine (Runner::derivative).
      case spv::OpDPdx: case spv::OpDPdxCoarse: case spv::OpDPdxFine: simple(XOp::DPdx, 1); return;
      case spv::OpDPdy: case spv::OpDPdyCoarse: case spv::OpDPdyFine: simple(XOp::DPdy, 1); return;
      case spv::OpFwidth: case spv::OpFwidthCoarse: case spv::OpFwidthFine: simple(XOp::Fwidth, 1); return;
      case spv::OpSampledImage: case spv::OpImage: {
        XIns x = base(ins, XOp::Copy);
        x.a = V(0);
        x.n = 1;
        emit(x);
        return;
      }
      case spv::OpImageSampleImplicitLod: case spv::OpImageSampleExplicitLod:
      case spv::OpImageSampleProjImplicitLod: case spv::OpImageSampleProjExplicitLod:
      case spv::OpImageSampleDrefImplicitLod: case spv::OpImageSampleDrefExplicitLod:
      case spv::OpImageSampleProjDrefImplicitLod: case spv::OpImageSampleProjDrefExplicitLod:
      case spv::OpImageGather: case spv::OpImageDrefGather:
      case spv::OpImageFetch: case spv::OpImageQuerySizeLod: case spv::OpImageQuerySize:
      case spv::OpImageQueryLevels: case spv::OpImageQueryLod:
        texture(ins, o);
        return;
      case spv::OpImageRead: case spv::OpImageWrite:
        image_access(ins, o);
        return;
      case spv::OpImageTexelPointer:
        image_texel_pointer(ins, o);
        return;
      case spv::OpAtomicIIncrement: case spv::OpAtomicIDecrement: case spv::OpAtomicLoad:
      case spv::OpAtomicIAdd: case spv::OpAtomicISub: case spv::OpAtomicStore: case spv::OpAtomicSMin:
      case spv::OpAtomicUMin: case spv::OpAtomicSMax: case spv::OpAtomicUMax: case spv::OpAtomicAnd:
      case spv::OpAtomicOr: case spv::OpAtomicXor: case spv::OpAtomicExchange:
      case spv::OpAtomicCompareExchange: {
        XOp op = XOp::AtomicLoad;
        switch (spv::Op(ins.opcode)) {
          case spv::OpAtomicIIncrement: op = XOp::AtomicInc; break;
          case spv::OpAtomicIDecrement: op = XOp::AtomicDec; break;
          case spv::OpAtomicIAdd: op = XOp::AtomicAdd; break;
          case spv::OpAtomicISub: op = XOp::AtomicSub; break;
          case spv::OpAtomicStore: op = XOp::AtomicStore; break;
          case spv::OpAtomicSMin: op = XOp::AtomicSMin; break;
          case spv::OpAtomicUMin: op = XOp::AtomicUMin; break;
          case spv::OpAtomicSMax: op = XOp::AtomicSMax; break;
          case spv::OpAtomicUMax: op = XOp::AtomicUMax; break;
          case spv::OpAtomicAnd: op = XOp::AtomicAnd; break;
          case spv::OpAtomicOr: op = XOp::AtomicOr; break;
          case spv::OpAtomicXor: op = XOp::AtomicXor; break;
          case spv::OpAtomicExchange: op = XOp::AtomicExchange; break;
          case spv::OpAtomicCompareExchange: op = XOp::AtomicCompareExchange; break;
          default: break;
        }
        XIns x = base(ins, op);
        const std::uint32_t ptr = o.at(0);
        if (const auto texel = texel_pointer.find(ptr); texel != texel_pointer.end()) {
          TexOp t = texel->second;
          t.atomic = op;
          if (op == XOp::AtomicCompareExchange) {
            t.texel = V(4);
            t.comparator = V(5);
          } else if (op != XOp::AtomicInc && op != XOp::AtomicDec && op != XOp::AtomicLoad) {
            t.texel = V(3);
          }
          x.op = XOp::Texture;
          x.aux = std::uint32_t(p.textures.size());
          p.textures.push_back(t);
          emit(x);
          return;
        }
        const Type& t = m.type(pointee(ptr));
        if (t.kind != TypeKind::Int)
          unsupported(m, ins, "an atomic operation on a " + m.name_of(pointee(ptr)) + " (GL 4.5's atomics take int and uint)");
        x.aux = chain_access(ins, ptr, t);
        // Operands: pointer, scope, semantics [, unequal semantics], value [, comparator].
        if (op == XOp::AtomicCompareExchange) {
          x.a = V(4);
          x.b = V(5);
        } else if (op != XOp::AtomicInc && op != XOp::AtomicDec && op != XOp::AtomicLoad) {
          x.a = V(3);
        }
        emit(x);
        return;
      }
      case spv::OpDemoteToHelperInvocation:
        emit(base(ins, XOp::Kill));
        return;
      default:
        unsupported(m, ins, "this instruction is outside the executor's scope");
    }
  }

  std::vector<std::uint32_t> pointee_of;  // access chain result id -> pointee type id
  std::vector<std::uint32_t> static_offset;  // pointer id -> constant word offset (no register)
  std::vector<bool> aliased;                 // value id -> its rows are another value's (alias_of)
  std::uint32_t pointee(std::uint32_t ptr) const {
    if (ptr < pointee_of.size() && pointee_of[ptr]) return pointee_of[ptr];
    return m.type(value_type.at(ptr)).element;
  }
  // The doubles of type `type` that start in words [first, first + words), relative to first.
  std::uint32_t doubles_in(std::uint32_t type, std::uint32_t first, std::uint32_t words) {
    std::vector<std::uint32_t> starts;
    for (const FlatComponent& c : m.type(type).flat)
      if (c.scalar == Scalar::F64 && c.word >= first && c.word < first + words) starts.push_back(c.word - first);
    if (starts.empty()) return kNone;
    p.doubles.push_back(std::move(starts));
    return std::uint32_t(p.doubles.size() - 1);
  }

  std::uint32_t add_copies(std::vector<WordCopy> cs) {
    p.copies.push_back(std::move(cs));
    return std::uint32_t(p.copies.size() - 1);
  }

  void run() {
    value_type.assign(m.bound, 0);
    pointee_of.assign(m.bound, 0);
    static_offset.assign(m.bound, 0);
    aliased.assign(m.bound, false);
    add_constants();
    for (const auto& [id, t] : m.constant_types) value_type[id] = t;
    add_variables();
    for (const Variable& v : m.variables) value_type[v.id] = pointer_type_for(v);
    for (const Variable& v : m.function_variables) value_type[v.id] = pointer_type_for(v);
    for (std::size_t i = 0; i < m.blocks.size(); ++i) block_of[m.blocks[i].label] = std::uint32_t(i);
    // Rows for every SSA result (pointers: one row of per-lane word offsets).
    for (const Block& b : m.blocks)
      for (const Instruction& ins : b.body)
        if (ins.result && ins.type) {
          value_type[ins.result] = ins.type;
          const Type& t = m.type(ins.type);
          if (const std::uint32_t rows = alias_of(ins); rows != kNone) {
            reg[ins.result] = rows;
            aliased[ins.result] = true;
            continue;
          }
          reg[ins.result] = alloc_rows(std::max<std::uint32_t>(t.words, 1));
          describe_rows(reg[ins.result], t);
        }
    p.fragment = m.model == ExecutionModel::Fragment;
    p.blocks.resize(m.blocks.size());
    for (std::size_t i = 0; i < m.blocks.size(); ++i) decode_block(m.blocks[i], p.blocks[i]);
    for (std::size_t i = 0; i < m.blocks.size(); ++i)
      for (const Instruction& ins : m.blocks[i].body)
        if (ins.opcode == spv::OpSelectionMerge && !ins.operands.empty()) {
          XBlock& merge = p.blocks[block_index(ins, ins.operands[0])];
          if (!merge.phis.empty()) merge.join_line = p.blocks[i].term.line;
        }
  }

  // A copy or a part of another SSA value (OpCopyObject, OpCompositeExtract with constant indices)
  // needs no rows and no instruction: it is the source's rows. SSA values never change once
  // written for a lane, and blocks come in dominance order, so the source's rows are final here.
  // Returns the rows, or kNone.
  std::uint32_t alias_of(const Instruction& ins) {
    const auto& o = ins.operands;
    if (ins.opcode == spv::OpCopyObject && !o.empty() && o[0] < reg.size() && reg[o[0]] != kNone &&
        m.constants.find(o[0]) == m.constants.end())
      return reg[o[0]];
    if (ins.opcode != spv::OpCompositeExtract || o.empty() || o[0] >= reg.size() || reg[o[0]] == kNone)
      return kNone;
    std::uint32_t t = value_type[o[0]];
    std::uint32_t offset = 0;
    for (std::size_t i = 1; i < o.size(); ++i) {
      const Type& ct = m.type(t);
      if (ct.kind == TypeKind::Struct) {
        offset += ct.member_word.at(o[i]);
        t = ct.members.at(o[i]);
      } else {
        t = ct.element;
        offset += o[i] * m.type(t).words;
      }
    }
    return reg[o[0]] + offset;
  }

  // A pointer type id whose element is the variable's type (for value_type lookups).
  std::uint32_t pointer_type_for(const Variable& v) {
    for (const auto& [id, t] : m.types)
      if (t.kind == TypeKind::Pointer && t.element == v.type && t.storage == v.storage) return id;
    throw SpirvError("SPIR-V: variable %" + std::to_string(v.id) + " has no pointer type");
  }
};

}  // namespace

std::unique_ptr<DecodedProgram> decode_program(const Module& m) {
  auto p = std::make_unique<DecodedProgram>();
  Decoder d(m, *p);
  d.run();
  return p;
}

}  // namespace tessref::shader
