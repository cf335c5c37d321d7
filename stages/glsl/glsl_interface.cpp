#include "stages/glsl/glsl_interface.h"

#include <spirv/unified1/spirv.hpp>

namespace tessref::glsl {

IoKind kind_of_builtin(std::uint32_t b) {
  switch (spv::BuiltIn(b)) {
    case spv::BuiltInPosition: return IoKind::Position;
    case spv::BuiltInTessLevelOuter: return IoKind::TessLevelOuter;
    case spv::BuiltInTessLevelInner: return IoKind::TessLevelInner;
    case spv::BuiltInPrimitiveId: return IoKind::PrimitiveId;
    case spv::BuiltInInvocationId: return IoKind::InvocationId;
    case spv::BuiltInPatchVertices: return IoKind::PatchVertices;
    case spv::BuiltInTessCoord: return IoKind::TessCoord;
    case spv::BuiltInFragCoord: return IoKind::FragCoord;
    case spv::BuiltInFrontFacing: return IoKind::FrontFacing;
    case spv::BuiltInHelperInvocation: return IoKind::HelperInvocation;
    case spv::BuiltInVertexId: case spv::BuiltInVertexIndex: return IoKind::VertexId;
    case spv::BuiltInInstanceId: case spv::BuiltInInstanceIndex: return IoKind::InstanceId;
    case spv::BuiltInPointSize: return IoKind::PointSize;
    case spv::BuiltInClipDistance: return IoKind::ClipDistance;
    case spv::BuiltInCullDistance: return IoKind::CullDistance;
    case spv::BuiltInFragDepth: return IoKind::FragDepth;
    case spv::BuiltInSampleMask: return IoKind::SampleMaskIn;  // an input (the output is refused: glsl_program.cpp)
    default: return IoKind::Other;
  }
}

namespace {

using shader::Module;
using shader::Type;
using shader::TypeKind;

struct Walker {
  const Module& m;
  const std::string& name;
  int max_slots;  // I/O slots of 4 words (slot 0: gl_Position)
  std::vector<IoWord>& out;

  // Lays out type t from `location` (component `component`): each scalar or vector starts a new
  // location, at the variable's Component decoration (0 without one); doubles take two words.
  void walk(std::uint32_t type_id, std::uint32_t var_word, std::uint32_t& location,
            std::uint32_t component) {
    const Type& t = m.type(type_id);
    switch (t.kind) {
      case TypeKind::Bool: case TypeKind::Int: case TypeKind::Float: case TypeKind::Vector: {
        std::uint32_t io = 4 + 4 * location + component;
        for (const shader::FlatComponent& c : t.flat) {
          place(var_word + c.word, io, c.scalar);
          io += std::uint32_t(shader::scalar_words(c.scalar));
        }
        location += (component + t.words + 3) / 4;
        break;
      }
      case TypeKind::Matrix: case TypeKind::Array: {
        // GLSL 4.50, 4.4.1.3: a component qualifier on an array or matrix applies to each element
        // (column), which sit at that component of consecutive locations.
        const std::uint32_t ew = m.type(t.element).words;
        for (std::uint32_t i = 0; i < t.count; ++i) walk(t.element, var_word + i * ew, location, component);
        break;
      }
      case TypeKind::Struct:
        for (std::size_t i = 0; i < t.members.size(); ++i) walk(t.members[i], var_word + t.member_word[i], location, 0);
        break;
      default:
        throw shader::SpirvError("'" + name + "': an interface variable of this type is not supported");
    }
  }

  void place(std::uint32_t var_word, std::uint32_t io_word, shader::Scalar s) {
    if (io_word + std::uint32_t(shader::scalar_words(s)) > std::uint32_t(4 * max_slots))
      throw shader::SpirvError("'" + name + "': location " + std::to_string((io_word - 4) / 4) +
                               " is past tessref's limit of " + std::to_string(max_slots - 1) +
                               " locations (vec4 slots) between these stages");
    out.push_back({var_word, io_word, s});
  }
};

// Whether the module reads or writes member `member` of block variable v (an access chain into it):
// glslang declares gl_ClipDistance and gl_CullDistance in every gl_PerVertex block, used or not.
bool member_used(const Module& m, const shader::Variable& v, std::uint32_t member) {
  for (const shader::Block& block : m.blocks)
    for (const shader::Instruction& ins : block.body) {
      if (ins.opcode != spv::OpAccessChain && ins.opcode != spv::OpInBoundsAccessChain) continue;
      if (ins.operands.at(0) != v.id) continue;
      std::size_t first = 1;
      if (m.type(v.type).kind == TypeKind::Array) ++first;  // gl_in[i].member
      if (ins.operands.size() <= first) continue;
      const auto c = m.constants.find(ins.operands[first]);
      if (c != m.constants.end() && c->second.at(0) == member) return true;
    }
  return false;
}

std::uint32_t builtin_word(IoKind kind) {
  return kind == IoKind::ClipDistance ? kClipDistanceWord : kind == IoKind::CullDistance ? kCullDistanceWord : kPointSizeWord;
}

// The words of gl_ClipDistance, gl_CullDistance or gl_PointSize (type t) at word `at` of its variable.
void builtin_words(const Module& m, std::uint32_t type, std::uint32_t at, IoKind kind, std::vector<IoWord>& out) {
  const Type& t = m.type(type);
  const std::uint32_t n = t.kind == TypeKind::Array ? t.count : 1;
  if (kind != IoKind::PointSize && n > kMaxDistances)
    throw shader::SpirvError(std::string(kind == IoKind::ClipDistance ? "gl_ClipDistance" : "gl_CullDistance") + "[" +
                             std::to_string(n) + "]: GL_MAX_CLIP_DISTANCES and GL_MAX_CULL_DISTANCES are " +
                             std::to_string(kMaxDistances));
  for (std::uint32_t k = 0; k < n; ++k) out.push_back({at + k, builtin_word(kind) + k, shader::Scalar::F32});
}

bool per_vertex_array(const Module& m, const shader::Variable& v, IoKind kind) {
  if (v.decorations.patch || m.type(v.type).kind != TypeKind::Array) return false;
  if (kind != IoKind::User && kind != IoKind::Position) return false;
  if (m.model == shader::ExecutionModel::TessControl) return true;
  return (m.model == shader::ExecutionModel::TessEval || m.model == shader::ExecutionModel::Geometry) &&
         v.storage == spv::StorageClassInput;
}

}  // namespace

StageInterface read_interface(const shader::Executable& exe, int max_slots) {
  const Module& m = exe.module();
  StageInterface si;
  for (const shader::Variable& v : m.variables) {
    if (v.storage != spv::StorageClassInput && v.storage != spv::StorageClassOutput) continue;
    IoVariable io;
    io.variable = &v;
    io.slot = exe.slot(v.id);
    io.patch = v.decorations.patch;
    // A gl_PerVertex block: its members carry the built-ins; gl_Position is the one carried.
    bool per_vertex_block = false;
    for (const shader::Decorations& d : v.member_decorations) per_vertex_block |= d.builtin.has_value();
    if (v.decorations.builtin) io.kind = kind_of_builtin(*v.decorations.builtin);
    else if (per_vertex_block) io.kind = IoKind::Position;

    io.arrayed = per_vertex_array(m, v, io.kind);
    std::uint32_t element = v.type;
    if (io.arrayed) {
      const Type& at = m.type(v.type);
      io.elements = at.count;
      element = at.element;
      io.element_words = m.type(element).words;
    } else {
      io.element_words = m.type(v.type).words;
    }
    if (io.kind == IoKind::Position) {
      const Type& st = m.type(element);
      if (per_vertex_block) {
        for (std::size_t i = 0; i < v.member_decorations.size(); ++i) {
          const auto b = v.member_decorations[i].builtin;
          if (b == std::uint32_t(spv::BuiltInPosition))
            for (std::uint32_t k = 0; k < 4; ++k) io.words.push_back({st.member_word[i] + k, k, shader::Scalar::F32});
          const IoKind member = b ? kind_of_builtin(*b) : IoKind::Other;
          if ((member == IoKind::ClipDistance || member == IoKind::CullDistance || member == IoKind::PointSize) &&
              member_used(m, v, std::uint32_t(i)))
            builtin_words(m, st.members[i], st.member_word[i], member, io.words);
        }
      } else {
        for (std::uint32_t k = 0; k < 4; ++k) io.words.push_back({k, k, shader::Scalar::F32});
      }
    } else if (io.kind == IoKind::ClipDistance || io.kind == IoKind::CullDistance) {
      builtin_words(m, element, 0, io.kind, io.words);
    } else if (io.kind == IoKind::User) {
      if (!v.decorations.location)
        throw shader::SpirvError("'" + v.name + "' has no location (the front end assigns them)");
      std::uint32_t location = *v.decorations.location;
      // Per-patch variables have their own slots (GlslProgram maps their locations to them).
      Walker w{m, v.name, io.patch ? 1 + kMaxPatchLocations : max_slots, io.words};
      w.walk(element, 0, location, v.decorations.component.value_or(0));
    }
    for (const IoWord& w : io.words)
      si.io_words_used = std::max(si.io_words_used, w.io_word + std::uint32_t(shader::scalar_words(w.scalar)));
    (v.storage == spv::StorageClassInput ? si.inputs : si.outputs).push_back(std::move(io));
  }
  return si;
}

}  // namespace tessref::glsl
