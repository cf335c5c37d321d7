#include "shader/spirv_module.h"

#include "shader/opcode_names.h"

#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/spirv.hpp>

namespace tessref::shader {
namespace {

Type make_type(TypeKind kind, Scalar scalar = Scalar::None) {
  Type t;
  t.kind = kind;
  t.scalar = scalar;
  return t;
}

std::string read_string(std::span<const std::uint32_t> words, std::size_t& pos) {
  std::string s;
  for (; pos < words.size(); ++pos) {
    const std::uint32_t w = words[pos];
    for (int b = 0; b < 4; ++b) {
      const char c = char((w >> (8 * b)) & 0xffu);
      if (c == '\0') {
        ++pos;
        return s;
      }
      s.push_back(c);
    }
  }
  throw SpirvError("SPIR-V: unterminated string literal");
}

void apply_decoration(Decorations& d, std::uint32_t decoration, std::span<const std::uint32_t> args) {
  auto arg = [&]() -> std::uint32_t {
    if (args.empty()) throw SpirvError("SPIR-V: decoration without its operand");
    return args[0];
  };
  switch (spv::Decoration(decoration)) {
    case spv::DecorationLocation: d.location = arg(); break;
    case spv::DecorationComponent: d.component = arg(); break;
    case spv::DecorationBinding: d.binding = arg(); break;
    case spv::DecorationBuiltIn: d.builtin = arg(); break;
    case spv::DecorationOffset: d.offset = arg(); break;
    case spv::DecorationStream: d.stream = arg(); break;
    case spv::DecorationArrayStride: d.array_stride = arg(); break;
    case spv::DecorationMatrixStride: d.matrix_stride = arg(); break;
    case spv::DecorationRowMajor: d.row_major = true; break;
    case spv::DecorationPatch: d.patch = true; break;
    case spv::DecorationFlat: d.flat = true; break;
    case spv::DecorationNoPerspective: d.noperspective = true; break;
    case spv::DecorationBlock: d.block = true; break;
    case spv::DecorationBufferBlock: d.buffer_block = true; break;
    default: break;
  }
}

std::uint64_t size_in_words(const Type& t) { return t.oversized_words ? t.oversized_words : t.words; }

std::uint64_t saturating_product(std::uint64_t a, std::uint64_t b) {
  std::uint64_t p;
  return __builtin_mul_overflow(a, b, &p) ? UINT64_MAX : p;
}

std::uint64_t saturating_sum(std::uint64_t a, std::uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }

// Marks `t` oversized, without a layout, when `words` is above kMaxValueWords.
bool oversized(Type& t, std::uint64_t words) {
  if (words <= kMaxValueWords) return false;
  t.oversized_words = words;
  t.words = 0;
  t.flat.clear();
  return true;
}

// Refuses, by name, a variable whose type has no layout (above kMaxValueWords).
void refuse_oversized(const Module& m, const Variable& v) {
  const std::uint64_t words = m.type(v.type).oversized_words;
  if (words == 0) return;
  const std::string bytes = words >= UINT64_MAX / 4 ? "more than 2^64" : std::to_string(words * 4);
  throw SpirvError("'" + (v.name.empty() ? m.name_of(v.id) : v.name) + "' is " + bytes +
                   " bytes: one variable holds at most " + std::to_string(kMaxValueWords * 4 >> 20) +
                   " MiB in tessref's executor (GL's minimum GL_MAX_SHADER_STORAGE_BLOCK_SIZE)");
}

// Fills words and flat for a type whose parts are known.
void lay_out(Module& m, Type& t) {
  auto scalar_type = [&](Scalar s) {
    t.words = std::uint32_t(scalar_words(s));
    t.flat = {FlatComponent{0, s}};
  };
  switch (t.kind) {
    case TypeKind::Bool:
    case TypeKind::Int:
    case TypeKind::Float: scalar_type(t.scalar); break;
    case TypeKind::Vector:
    case TypeKind::Matrix:
    case TypeKind::Array: {
      const Type& e = m.type(t.element);
      if (t.kind != TypeKind::Array) t.scalar = e.scalar;
      if (oversized(t, saturating_product(size_in_words(e), t.count))) break;
      t.words = e.words * t.count;
      for (std::uint32_t i = 0; i < t.count; ++i)
        for (const FlatComponent& c : e.flat) t.flat.push_back({c.word + i * e.words, c.scalar});
      break;
    }
    case TypeKind::Struct: {
      std::uint64_t words = 0;
      for (std::uint32_t member : t.members) words = saturating_sum(words, size_in_words(m.type(member)));
      if (oversized(t, words)) break;
      t.words = 0;
      for (std::uint32_t member : t.members) {
        const Type& e = m.type(member);
        t.member_word.push_back(t.words);
        for (const FlatComponent& c : e.flat) t.flat.push_back({c.word + t.words, c.scalar});
        t.words += e.words;
      }
      break;
    }
    case TypeKind::Pointer: t.words = 1; break;  // a per-lane word offset
    case TypeKind::SampledImage:
    case TypeKind::Image:
    // A texture unit: one word, a flat component so that loads and copies move it (without one,
    // every sampler read unit 0).
    case TypeKind::Sampler: scalar_type(Scalar::U32); break;
    default: t.words = 0; break;
  }
}

ExecutionModel model_of(std::uint32_t m) {
  switch (spv::ExecutionModel(m)) {
    case spv::ExecutionModelVertex: return ExecutionModel::Vertex;
    case spv::ExecutionModelTessellationControl: return ExecutionModel::TessControl;
    case spv::ExecutionModelTessellationEvaluation: return ExecutionModel::TessEval;
    case spv::ExecutionModelGeometry: return ExecutionModel::Geometry;
    case spv::ExecutionModelFragment: return ExecutionModel::Fragment;
    default: return ExecutionModel::Other;
  }
}

}  // namespace

const Type& Module::type(std::uint32_t id) const {
  auto it = types.find(id);
  if (it == types.end()) throw SpirvError("SPIR-V: unknown type %" + std::to_string(id));
  return it->second;
}

const Variable* Module::variable(std::uint32_t id) const {
  for (const Variable& v : variables)
    if (v.id == id) return &v;
  for (const Variable& v : function_variables)
    if (v.id == id) return &v;
  return nullptr;
}

std::string Module::name_of(std::uint32_t id) const {
  auto it = names.find(id);
  return it != names.end() && !it->second.empty() ? it->second : "%" + std::to_string(id);
}

// A shader storage block whose last member is runtime-sized: that member becomes an array of as
// many elements as the bound range holds past its Offset (a type of its own, since blocks may
// share the runtime array type), and the block is laid out again.
void size_runtime_array(Module& m, const Variable& v, const StorageBufferSizes& storage) {
  std::uint32_t block = v.type;
  const bool arrayed = m.type(block).kind == TypeKind::Array;
  if (arrayed) block = m.type(block).element;
  Type& st = m.types.at(block);
  if (st.kind != TypeKind::Struct || st.members.empty() || !m.type(st.members.back()).runtime) return;
  const std::string name = m.names.count(block) ? m.names.at(block) : v.name;
  if (arrayed)
    throw SpirvError("an array of shader storage blocks with a runtime-sized member is not supported: '" + name + "'");
  const std::uint32_t binding = v.decorations.binding.value_or(0);
  const auto bound = storage.find(binding);
  if (bound == storage.end())
    throw SpirvError("shader storage block '" + name + "' (binding " + std::to_string(binding) +
                     ") has a runtime-sized array; bind a buffer range there to size it");
  const std::uint32_t last = std::uint32_t(st.members.size() - 1);
  const auto md = m.member_decorations.find({block, last});
  const std::uint32_t runtime = st.members.back();
  const auto td = m.type_decorations.find(runtime);
  if (md == m.member_decorations.end() || !md->second.offset || td == m.type_decorations.end() || !td->second.array_stride)
    throw SpirvError("shader storage block '" + name + "': its runtime-sized array has no Offset or ArrayStride");
  const std::size_t offset = *md->second.offset, stride = *td->second.array_stride;
  Type sized = m.type(runtime);
  sized.count = std::uint32_t(bound->second > offset ? (bound->second - offset) / stride : 0);
  sized.flat.clear();
  lay_out(m, sized);
  const std::uint32_t id = m.bound++;
  m.types[id] = sized;
  m.type_decorations[id] = td->second;
  st.members.back() = id;
  st.member_word.clear();
  st.flat.clear();
  lay_out(m, st);
}

Module read_module(std::span<const std::uint32_t> words, const StorageBufferSizes& storage) {
  if (words.size() < 5 || words[0] != spv::MagicNumber)
    throw SpirvError("SPIR-V: not a SPIR-V module (bad magic number)");
  Module m;
  m.bound = words[3];
  std::map<std::uint32_t, Decorations> decorations;
  std::map<std::pair<std::uint32_t, std::uint32_t>, Decorations> member_decorations;
  std::uint32_t entry_count = 0;
  bool in_function = false, function_seen = false;
  int line = 0;
  Block* block = nullptr;

  for (std::size_t pos = 5; pos < words.size();) {
    const std::uint32_t head = words[pos];
    const std::uint16_t op = std::uint16_t(head & 0xffffu);
    const std::size_t count = head >> 16;
    if (count == 0 || pos + count > words.size())
      throw SpirvError("SPIR-V: truncated instruction at word " + std::to_string(pos));
    std::span<const std::uint32_t> w = words.subspan(pos + 1, count - 1);
    pos += count;
    auto need = [&](std::size_t n) {
      if (w.size() < n)
        throw SpirvError("SPIR-V: opcode " + std::to_string(op) + " has too few operands");
    };

    switch (spv::Op(op)) {
      case spv::OpCapability:
      case spv::OpExtension:
      case spv::OpMemoryModel:
      case spv::OpSource:
      case spv::OpSourceContinued:
      case spv::OpSourceExtension:
      case spv::OpModuleProcessed:
      case spv::OpDecorationGroup:
      case spv::OpNoLine:
        if (op == spv::OpNoLine) line = 0;
        break;
      case spv::OpExtInstImport: {
        need(1);
        std::size_t p = 1;
        const std::string name = read_string(w, p);
        if (name == "GLSL.std.450") m.glsl_std450 = w[0];
        else if (name.rfind("NonSemantic.", 0) != 0)
          throw SpirvError("SPIR-V: extended instruction set '" + name + "' is not supported");
        break;
      }
      case spv::OpEntryPoint: {
        need(2);
        if (++entry_count > 1) throw SpirvError("SPIR-V: more than one entry point");
        m.model = model_of(w[0]);
        m.entry_function = w[1];
        std::size_t p = 2;
        m.entry_name = read_string(w, p);
        break;
      }
      case spv::OpExecutionMode: {
        need(2);
        switch (spv::ExecutionMode(w[1])) {
          case spv::ExecutionModeOutputVertices: need(3); m.modes.output_vertices = int(w[2]); break;
          case spv::ExecutionModeInputPoints: m.modes.input_vertices = 1; break;
          case spv::ExecutionModeInputLines: m.modes.input_vertices = 2; break;
          case spv::ExecutionModeInputLinesAdjacency: m.modes.input_vertices = 4; break;
          case spv::ExecutionModeInputTrianglesAdjacency: m.modes.input_vertices = 6; break;
          case spv::ExecutionModeOutputPoints:
          case spv::ExecutionModeOutputLineStrip:
          case spv::ExecutionModeOutputTriangleStrip: m.modes.output_primitive = w[1]; break;
          case spv::ExecutionModeInvocations: need(3); m.modes.invocations = int(w[2]); break;
          case spv::ExecutionModeTriangles:
            m.modes.input_vertices = 3;  // a geometry shader's input; a TES's domain
            m.modes.primitive = w[1];
            break;
          case spv::ExecutionModeQuads:
          case spv::ExecutionModeIsolines: m.modes.primitive = w[1]; break;
          case spv::ExecutionModeSpacingEqual:
          case spv::ExecutionModeSpacingFractionalEven:
          case spv::ExecutionModeSpacingFractionalOdd: m.modes.spacing = w[1]; break;
          case spv::ExecutionModeVertexOrderCw:
          case spv::ExecutionModeVertexOrderCcw: m.modes.order = w[1]; break;
          case spv::ExecutionModePointMode: m.modes.point_mode = true; break;
          case spv::ExecutionModeOriginUpperLeft: m.modes.origin_upper_left = true; break;
          case spv::ExecutionModeEarlyFragmentTests: m.modes.early_fragment_tests = true; break;
          default: break;
        }
        break;
      }
      case spv::OpString: {
        need(1);
        std::size_t p = 1;
        m.files[w[0]] = read_string(w, p);
        break;
      }
      case spv::OpMemberName: {
        need(2);
        std::size_t p = 2;
        m.member_names[{w[0], w[1]}] = read_string(w, p);
        break;
      }
      case spv::OpName: {
        need(1);
        std::size_t p = 1;
        m.names[w[0]] = read_string(w, p);
        break;
      }
      case spv::OpDecorate:
        need(2);
        apply_decoration(decorations[w[0]], w[1], w.subspan(2));
        break;
      case spv::OpMemberDecorate:
        need(3);
        apply_decoration(member_decorations[{w[0], w[1]}], w[2], w.subspan(3));
        break;
      case spv::OpLine:
        need(3);
        line = int(w[1]);
        break;

      // Types
      case spv::OpTypeVoid: need(1); m.types[w[0]] = make_type(TypeKind::Void); break;
      case spv::OpTypeBool: {
        need(1);
        Type t = make_type(TypeKind::Bool, Scalar::Bool);
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeInt: {
        need(3);
        if (w[1] != 32) throw SpirvError("SPIR-V: " + std::to_string(w[1]) + "-bit integers are not supported");
        Type t = make_type(TypeKind::Int, w[2] ? Scalar::I32 : Scalar::U32);
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeFloat: {
        need(2);
        if (w[1] != 32 && w[1] != 64)
          throw SpirvError("SPIR-V: " + std::to_string(w[1]) + "-bit floats are not supported");
        Type t = make_type(TypeKind::Float, w[1] == 64 ? Scalar::F64 : Scalar::F32);
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeVector:
      case spv::OpTypeMatrix: {
        need(3);
        Type t = make_type(op == spv::OpTypeVector ? TypeKind::Vector : TypeKind::Matrix);
        t.element = w[1];
        t.count = w[2];
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeArray: {
        need(3);
        auto c = m.constants.find(w[2]);
        if (c == m.constants.end()) throw SpirvError("SPIR-V: array length is not a constant");
        Type t = make_type(TypeKind::Array);
        t.element = w[1];
        t.count = c->second[0];
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeRuntimeArray: {  // sized once the variables' bindings are known (below)
        need(2);
        Type t = make_type(TypeKind::Array);
        t.element = w[1];
        t.runtime = true;
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeStruct: {
        need(1);
        Type t = make_type(TypeKind::Struct);
        t.members.assign(w.begin() + 1, w.end());
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypePointer: {
        need(3);
        Type t = make_type(TypeKind::Pointer);
        t.storage = w[1];
        t.element = w[2];
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeFunction: need(1); m.types[w[0]] = make_type(TypeKind::Function); break;
      case spv::OpTypeImage: {
        need(8);
        Type t = make_type(TypeKind::Image);
        t.image_sampled_type = w[1];
        t.image_dim = w[2];
        t.image_arrayed = w[4] != 0;
        t.image_depth = w[3] == 1;
        t.image_ms = w[5] != 0;
        t.image_storage = w[6] == 2;
        t.image_format = w[7];
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeSampler: {
        need(1);
        Type t = make_type(TypeKind::Sampler);
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }
      case spv::OpTypeSampledImage: {
        need(2);
        Type t = make_type(TypeKind::SampledImage);
        t.element = w[1];
        const Type& image = m.type(w[1]);
        t.image_dim = image.image_dim;
        t.image_arrayed = image.image_arrayed;
        t.image_depth = image.image_depth;
        t.image_ms = image.image_ms;
        t.image_sampled_type = image.image_sampled_type;
        lay_out(m, t);
        m.types[w[0]] = t;
        break;
      }

      // Constants
      case spv::OpConstantTrue:
      case spv::OpConstantFalse:
        need(2);
        m.constants[w[1]] = {op == spv::OpConstantTrue ? 1u : 0u};
        m.constant_types[w[1]] = w[0];
        break;
      case spv::OpConstant:
      case spv::OpSpecConstant:
        need(3);
        m.constants[w[1]].assign(w.begin() + 2, w.end());
        m.constant_types[w[1]] = w[0];
        break;
      case spv::OpSpecConstantTrue:
      case spv::OpSpecConstantFalse:
        need(2);
        m.constants[w[1]] = {op == spv::OpSpecConstantTrue ? 1u : 0u};
        m.constant_types[w[1]] = w[0];
        break;
      case spv::OpConstantComposite:
      case spv::OpSpecConstantComposite: {
        need(2);
        std::vector<std::uint32_t> v;
        for (std::size_t i = 2; i < w.size(); ++i) {
          auto c = m.constants.find(w[i]);
          if (c == m.constants.end()) throw SpirvError("SPIR-V: composite constant of non-constants");
          v.insert(v.end(), c->second.begin(), c->second.end());
        }
        m.constants[w[1]] = v;
        m.constant_types[w[1]] = w[0];
        break;
      }
      case spv::OpConstantNull:
      case spv::OpUndef:
        need(2);
        if (!in_function || op == spv::OpConstantNull) {
          m.constants[w[1]] = std::vector<std::uint32_t>(m.type(w[0]).words, 0u);
          m.constant_types[w[1]] = w[0];
        } else {
          block->body.push_back(Instruction{op, w[0], w[1], {}, line});
        }
        break;
      case spv::OpSpecConstantOp:
        throw SpirvError("SPIR-V: OpSpecConstantOp is not supported");

      case spv::OpVariable: {
        need(3);
        Variable v;
        v.type = m.type(w[0]).element;
        v.id = w[1];
        v.storage = w[2];
        if (w.size() > 3) v.initializer = w[3];
        if (in_function) m.function_variables.push_back(v);
        else m.variables.push_back(v);
        break;
      }

      case spv::OpFunction:
        need(2);
        if (function_seen)
          throw SpirvError("SPIR-V: more than one function (calls are expected to be inlined)");
        function_seen = in_function = true;
        break;
      case spv::OpFunctionParameter:
        throw SpirvError("SPIR-V: the entry point takes parameters");
      case spv::OpFunctionEnd:
        in_function = false;
        block = nullptr;
        break;
      case spv::OpLabel:
        need(1);
        m.blocks.push_back(Block{w[0], {}});
        block = &m.blocks.back();
        break;
      case spv::OpFunctionCall:
        throw SpirvError("SPIR-V: a function call was left after inlining (recursion?)");

      default: {
        if (!in_function || !block)
          throw SpirvError(std::string("SPIR-V: unsupported module-level instruction ") +
                           (opcode_name(op) ? opcode_name(op) : std::to_string(op).c_str()));
        // Generic instruction: does it have a result type and id?
        bool has_result = false, has_type = false;
        spv::HasResultAndType(spv::Op(op), &has_result, &has_type);
        Instruction ins;
        ins.opcode = op;
        ins.line = line;
        std::size_t k = 0;
        if (has_type) ins.type = w[k++];
        if (has_result) ins.result = w[k++];
        ins.operands.assign(w.begin() + std::ptrdiff_t(k), w.end());
        block->body.push_back(std::move(ins));
        break;
      }
    }
  }
  if (entry_count == 0) throw SpirvError("SPIR-V: no entry point");
  if (m.blocks.empty()) throw SpirvError("SPIR-V: the entry point has no body");

  // Decorations onto variables (and onto the members of the block types they hold).
  auto attach = [&](Variable& v) {
    if (auto it = decorations.find(v.id); it != decorations.end()) v.decorations = it->second;
    auto n = m.names.find(v.id);
    if (n != m.names.end()) v.name = n->second;
    std::uint32_t t = v.type;
    while (m.type(t).kind == TypeKind::Array) t = m.type(t).element;
    if (auto it = decorations.find(t); it != decorations.end() && it->second.block) v.decorations.block = true;
    if (auto it = decorations.find(t); it != decorations.end() && it->second.buffer_block) v.decorations.buffer_block = true;
    const Type& st = m.type(t);
    if (st.kind == TypeKind::Struct) {
      v.member_decorations.resize(st.members.size());
      for (std::uint32_t i = 0; i < st.members.size(); ++i)
        if (auto it = member_decorations.find({t, i}); it != member_decorations.end())
          v.member_decorations[i] = it->second;
      if (v.name.empty() || v.name.rfind("gl_", 0) == 0) {
        auto tn = m.names.find(t);
        if (v.name.empty() && tn != m.names.end()) v.name = tn->second;
      }
    }
  };
  for (Variable& v : m.variables) attach(v);
  for (Variable& v : m.function_variables) attach(v);
  // The explicit layout of every type (uniform blocks read from buffer bytes: buffer_layout.h).
  for (const auto& [id, t] : m.types) {
    (void)t;
    if (auto it = decorations.find(id); it != decorations.end()) m.type_decorations[id] = it->second;
  }
  m.member_decorations = std::move(member_decorations);
  for (const Variable& v : m.variables) {
    if (v.storage == spv::StorageClassStorageBuffer)
      throw SpirvError("the StorageBuffer storage class is not supported (GLSL for OpenGL gives Uniform + BufferBlock): '" +
                       v.name + "'");
    if (v.decorations.buffer_block) size_runtime_array(m, v, storage);
  }
  for (const Variable& v : m.variables) refuse_oversized(m, v);
  for (const Variable& v : m.function_variables) refuse_oversized(m, v);
  return m;
}

std::string sampler_glsl_name(const Module& m, const Type& t) {
  std::string prefix;
  if (m.type(t.image_sampled_type).scalar == Scalar::I32) prefix = "i";
  if (m.type(t.image_sampled_type).scalar == Scalar::U32) prefix = "u";
  std::string dim;
  switch (t.image_dim) {
    case spv::Dim1D: dim = "1D"; break;
    case spv::Dim2D: dim = "2D"; break;
    case spv::Dim3D: dim = "3D"; break;
    case spv::DimCube: dim = "Cube"; break;
    case spv::DimRect: dim = "2DRect"; break;
    case spv::DimBuffer: dim = "Buffer"; break;
    default: dim = "(dimension " + std::to_string(t.image_dim) + ")"; break;
  }
  return prefix + (t.image_storage ? "image" : "sampler") + dim + (t.image_ms ? "MS" : "") + (t.image_arrayed ? "Array" : "") +
         (t.image_depth ? "Shadow" : "");
}

}  // namespace tessref::shader
