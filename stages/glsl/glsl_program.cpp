#include "stages/glsl/glsl_program.h"

#include <algorithm>
#include <map>
#include <cstring>
#include <stdexcept>
#include <tuple>

#include <spirv/unified1/spirv.hpp>

#include "shader/buffer_layout.h"
#include "shader/resource_names.h"
#include "shader/glsl_rewrite.h"
#include "stages/glsl/glsl_geometry.h"
#include "stages/glsl/glsl_stages.h"
#include "stages/glsl/output_names.h"

namespace tessref::glsl {
namespace {

using shader::Scalar;
using shader::TypeKind;

// tessref's I/O slot limits (see glsl_interface.h): slot 0 is gl_Position.
constexpr int kVertexSlots = 1 + kMaxStageLocations;               // StageVertex::attr
constexpr int kVaryingSlots = 1 + kMaxVaryings / 4;                // ClipVertex varyings
constexpr int kPatchSlots = 1 + kMaxPatchAttributes;               // PatchOutput::patch

static_assert(shader::kGlMaxPatchVertices == kMaxPatchVertices, "GL_MAX_PATCH_VERTICES: one value");

// What the executor runs but the pipeline does not carry, refused by name rather than ignored.
void refuse_unsupported_io(const shader::Module& m, shader::Stage stage) {
  // The compiler refuses a larger patch (glsl_compile.cpp); this guards SPIR-V from elsewhere.
  if (stage == shader::Stage::TessControl &&
      (m.modes.output_vertices < 1 || m.modes.output_vertices > kMaxPatchVertices))
    throw shader::SpirvError("layout(vertices = " + std::to_string(m.modes.output_vertices) +
                             "): an output patch has 1 to GL_MAX_PATCH_VERTICES (" +
                             std::to_string(kMaxPatchVertices) + ") vertices");
  for (const shader::Variable& v : m.variables) {
    // A built-in the pipeline does not carry (gl_SubGroupSizeARB, gl_PointCoord, gl_SampleID,
    // gl_Layer, gl_DrawID, ...) would read 0 or go nowhere: refused by name.
    // (glslang declares gl_SubGroupSizeARB as a UniformConstant, not an Input.)
    // gl_SampleMask (the output) would change coverage, which tessref does not model.
    const bool sample_mask_out = v.decorations.builtin && *v.decorations.builtin == spv::BuiltInSampleMask &&
                                 v.storage == spv::StorageClassOutput;
    if (v.decorations.builtin && (kind_of_builtin(*v.decorations.builtin) == IoKind::Other || sample_mask_out))
      throw shader::SpirvError("'" + (v.name.empty() ? "built-in " + std::to_string(*v.decorations.builtin) : v.name) +
                               "' is a built-in " + (v.storage == spv::StorageClassOutput ? "output" : "input") +
                               " tessref's pipeline does not provide");
    if (v.storage != spv::StorageClassOutput) continue;
    if (stage == shader::Stage::Fragment && v.decorations.location && *v.decorations.location >= kMaxDrawBuffers)
      throw shader::SpirvError("fragment output '" + v.name + "' at location " + std::to_string(*v.decorations.location) +
                               ": past GL_MAX_DRAW_BUFFERS (" + std::to_string(kMaxDrawBuffers) +
                               ", locations 0 to " + std::to_string(kMaxDrawBuffers - 1) + ")");
  }
}

std::unique_ptr<StageProgram> make_stage(const shader::CompiledStage& cs, shader::ExecLimits limits,
                                         const shader::StorageBufferSizes& storage) {
  auto sp = std::make_unique<StageProgram>();
  sp->stage = cs.stage;
  try {
    shader::Module module = shader::read_module(cs.spirv, storage);
    refuse_unsupported_io(module, cs.stage);
    sp->exe = std::make_unique<shader::Executable>(std::move(module), limits);
  } catch (const shader::SpirvError& e) {
    throw shader::SpirvError(std::string(shader::stage_name(cs.stage)) + ": " + e.what());
  }
  const int slots = cs.stage == shader::Stage::Fragment ? kVaryingSlots
                    : cs.stage == shader::Stage::Vertex ? kVertexSlots
                                                        : std::max(kVertexSlots, kPatchSlots);
  sp->io = read_interface(*sp->exe, slots);
  const shader::Module& m = sp->exe->module();
  for (const shader::Variable& v : m.variables) {
    const shader::VariableSlot* slot = sp->exe->slot(v.id);
    if (v.storage == spv::StorageClassAtomicCounter) {
      const std::uint32_t binding = v.decorations.binding.value_or(0);
      const std::uint32_t offset = v.decorations.offset.value_or(0) / 4;
      for (std::uint32_t w = 0; w < slot->words; ++w) sp->counters.push_back({slot->base + w, binding, offset + w});
      continue;
    }
    if (v.storage != spv::StorageClassUniformConstant && v.storage != spv::StorageClassUniform) continue;
    if (v.decorations.buffer_block) continue;  // in the program's StorageMemory
    sp->uniform_ranges.push_back({slot->base, slot->words});
  }
  std::uint32_t words = 0;
  for (const auto& [first, n] : sp->uniform_ranges) words = std::max(words, first + n);
  sp->uniforms.assign(words, 0u);
  for (const shader::Variable& v : m.variables) {
    const shader::VariableSlot* slot = sp->exe->slot(v.id);
    if (slot->per_lane) continue;
    // A sampler's value is its texture unit: its binding until the user sets it.
    if (m.type(v.type).kind == TypeKind::SampledImage || m.type(v.type).kind == TypeKind::Image)
      sp->uniforms[slot->base] = v.decorations.binding.value_or(0);
    // 'uniform T x = initializer;' (GLSL 1.20+): the value until the user sets it.
    if (v.initializer && (v.storage == spv::StorageClassUniformConstant || v.storage == spv::StorageClassUniform)) {
      const auto& words = m.constants.at(*v.initializer);
      std::copy(words.begin(), words.end(), sp->uniforms.begin() + slot->base);
    }
  }
  return sp;
}

// The GLSL shape of a uniform's type: scalar, columns x rows (1 x N for vectors).
struct Shape {
  Scalar scalar = Scalar::None;
  int columns = 1, rows = 1;
  bool sampler = false;
  std::string sampler_name;  // "sampler2D", "usampler3D", "samplerCube", ...
};

Shape shape_of(const shader::Module& m, std::uint32_t type) {
  const shader::Type& t = m.type(type);
  Shape s;
  switch (t.kind) {
    case TypeKind::Bool: case TypeKind::Int: case TypeKind::Float: s.scalar = t.scalar; break;
    case TypeKind::Vector: s.scalar = t.scalar; s.rows = int(t.count); break;
    case TypeKind::Matrix:
      s.scalar = t.scalar;
      s.columns = int(t.count);
      s.rows = int(m.type(t.element).count);
      break;
    case TypeKind::SampledImage:
    case TypeKind::Image:  // a storage image: its value is its image unit
      s.sampler = true;
      s.scalar = Scalar::I32;
      s.sampler_name = sampler_glsl_name(m, t);
      break;
    default: break;
  }
  return s;
}

const char* scalar_name(Scalar s) {
  switch (s) {
    case Scalar::Bool: return "bool";
    case Scalar::I32: return "int";
    case Scalar::U32: return "uint";
    case Scalar::F32: return "float";
    case Scalar::F64: return "double";
    default: return "?";
  }
}

std::string shape_name(const Shape& s) {
  if (s.sampler) return s.sampler_name;
  std::string base = scalar_name(s.scalar);
  if (s.columns == 1 && s.rows == 1) return base;
  const std::string prefix = s.scalar == Scalar::F32 ? "" : s.scalar == Scalar::F64 ? "d"
                             : s.scalar == Scalar::I32 ? "i" : s.scalar == Scalar::U32 ? "u" : "b";
  if (s.columns == 1) return prefix + "vec" + std::to_string(s.rows);
  return prefix + "mat" + std::to_string(s.columns) + "x" + std::to_string(s.rows);
}

// A default-block uniform by its name, or a uniform block's member by "member" or "Block.member"
// (its value lives in the block's words): the type and word offset in the variable, or nullopt.
std::optional<std::pair<std::uint32_t, std::uint32_t>> find_uniform(const shader::Module& m, const shader::Variable& v,
                                                                    const std::string& name) {
  if (v.storage == spv::StorageClassUniformConstant) {
    if (v.name == name) return std::pair{v.type, 0u};
    return std::nullopt;
  }
  if (v.storage != spv::StorageClassUniform || m.type(v.type).kind != TypeKind::Struct) return std::nullopt;
  const shader::Type& block = m.type(v.type);
  const auto block_name = m.names.find(v.type);
  for (std::uint32_t k = 0; k < block.members.size(); ++k) {
    const auto mn = m.member_names.find({v.type, k});
    if (mn == m.member_names.end()) continue;
    if (name == mn->second || (block_name != m.names.end() && name == block_name->second + "." + mn->second))
      return std::pair{block.members[k], block.member_word[k]};
  }
  return std::nullopt;
}

// A uniform by its full GL name: a head find_uniform knows, then its accessors
// (shader/resource_names.h), as glGetUniformLocation takes them ("lights[2].color").
std::optional<shader::NamedValue> resolve_uniform(const shader::Module& m, const shader::Variable& v,
                                                  const std::string& name) {
  // Heads: up to the first accessor, or (Block.member) up to the second '.'.
  std::vector<std::size_t> heads;
  const std::size_t first = name.find_first_of(".[");
  heads.push_back(first);
  if (first != std::string::npos && name[first] == '.') heads.push_back(name.find_first_of(".[", first + 1));
  for (const std::size_t head : heads) {
    const auto found = find_uniform(m, v, name.substr(0, head));
    if (!found) continue;
    const std::string_view accessors = head == std::string::npos ? std::string_view() : std::string_view(name).substr(head);
    const shader::Access a = shader::follow_accessors(m, {found->first, found->second, 1}, name.substr(0, head), accessors);
    if (a.index_past_end)
      throw std::invalid_argument("uniform '" + name + "': index " + a.index + " past the array's " +
                                  std::to_string(a.count) + " elements");
    if (a.why.empty()) return a.value;
  }
  return std::nullopt;
}

// "struct Light" for a struct type (its GLSL name from OpName).
std::string struct_name(const shader::Module& m, std::uint32_t type) {
  const auto n = m.names.find(type);
  return "struct " + (n != m.names.end() ? n->second : std::string("?"));
}

// Every name find_uniform knows in the module.
void uniform_names_of(const shader::Module& m, std::vector<std::string>& out) {
  for (const shader::Variable& v : m.variables) {
    if (v.storage == spv::StorageClassUniformConstant && !v.name.empty()) out.push_back(v.name);
    if (v.storage != spv::StorageClassUniform || m.type(v.type).kind != TypeKind::Struct) continue;
    for (std::uint32_t k = 0; k < m.type(v.type).members.size(); ++k)
      if (const auto mn = m.member_names.find({v.type, k}); mn != m.member_names.end()) out.push_back(mn->second);
  }
}

}  // namespace

shader::Invocations& StageProgram::prepare(int groups) const {
  shader::Invocations& inv = exe->local();
  inv.zero_shared(groups);
  for (const auto& [first, n] : uniform_ranges)
    std::copy_n(uniforms.begin() + first, n, inv.shared_words() + first);
  if (textures)
    for (std::uint32_t unit = 0; unit < textures->size(); ++unit) inv.bind_texture(unit, (*textures)[unit]);
  if (images)
    for (std::uint32_t unit = 0; unit < images->size(); ++unit) inv.bind_image(unit, (*images)[unit]);
  inv.set_cube_map_seamless(cube_map_seamless && *cube_map_seamless);
  for (const auto& [id, words] : storage) inv.bind_storage(id, words);
  for (const auto& [word, binding, offset] : counters) {
    const std::vector<std::uint32_t>& buffer = (*counter_buffers)[binding];
    inv.shared_words()[word] = offset < buffer.size() ? buffer[offset] : 0u;
  }
  return inv;
}

void StageProgram::finish(shader::Invocations& inv) const {
  for (const auto& [word, binding, offset] : counters) {
    std::vector<std::uint32_t>& buffer = (*counter_buffers)[binding];
    if (buffer.size() <= offset) buffer.resize(offset + 1, 0u);
    buffer[offset] = inv.shared_words()[word];
  }
}

void StageProgram::rethrow(const shader::ShaderRuntimeError& e, const std::string& where) const {
  std::string msg = std::string(shader::stage_name(stage)) + ", " + where;
  if (e.line > 0) msg += ", line " + std::to_string(e.line);
  throw StageError(msg + ": " + e.what());
}

GlslProgram::GlslProgram(const shader::CompiledProgram& compiled, shader::ExecLimits limits,
                         const shader::StorageBufferSizes& storage) {
  for (const shader::CompiledStage& cs : compiled.stages) {
    switch (cs.stage) {
      case shader::Stage::Vertex: vs_ = make_stage(cs, limits, storage); break;
      case shader::Stage::TessControl: tcs_ = make_stage(cs, limits, storage); break;
      case shader::Stage::TessEval: tes_ = make_stage(cs, limits, storage); break;
      case shader::Stage::Geometry: gs_ = make_stage(cs, limits, storage); break;
      case shader::Stage::Fragment: fs_ = make_stage(cs, limits, storage); break;
    }
  }
  if (!vs_) throw shader::SpirvError("the program has no vertex shader");
  if (!fs_) throw shader::SpirvError("the program has no fragment shader");
  for (StageProgram* s : stages())
    if (s) {
      s->textures = &textures_;
      s->images = &images_;
      s->cube_map_seamless = &cube_map_seamless_;
      s->counter_buffers = &counter_buffers_;
      s->side_effects = s->exe->writes_memory();
    }
  make_storage_memory();
  // Varyings handed to the rasterizer: every word the last geometry stage writes past gl_Position.
  // With a geometry shader, the stage before it hands its vertices on in the same form.
  const auto varyings_of = [](const StageProgram& stage) {
    std::uint32_t used = 4;
    for (const IoVariable& v : stage.io.outputs)
      for (const IoWord& w : v.words)
        if (v.kind == IoKind::User) used = std::max(used, w.io_word + std::uint32_t(shader::scalar_words(w.scalar)));
    if (used - 4 > std::uint32_t(kMaxVaryings))
      throw shader::SpirvError("the " + std::string(shader::stage_name(stage.stage)) + " writes " +
                               std::to_string(used - 4) + " varying components; tessref's limit is " +
                               std::to_string(kMaxVaryings));
    return int(used - 4);
  };
  // Then the gl_ClipDistance and gl_CullDistance elements it writes (glsl_interface.h).
  const auto layout_of = [&](const StageProgram& stage) {
    VaryingLayout l;
    l.user = varyings_of(stage);
    for (const IoVariable& v : stage.io.outputs)
      for (const IoWord& w : v.words) {
        const int d = int(w.io_word) - int(kClipDistanceWord);
        if (d >= 0 && d < int(kMaxDistances)) l.clip = std::max(l.clip, d + 1);
        else if (d >= int(kMaxDistances) && d < 2 * int(kMaxDistances)) l.cull = std::max(l.cull, d - int(kMaxDistances) + 1);
        else if (w.io_word == kPointSizeWord) l.point_size = 1;
      }
    const std::string stage_name = shader::stage_name(stage.stage);
    if (l.clip + l.cull > int(kMaxDistances))
      throw shader::SpirvError("the " + stage_name + " writes " + std::to_string(l.clip) + " clip and " +
                               std::to_string(l.cull) + " cull distances; GL_MAX_COMBINED_CLIP_AND_CULL_DISTANCES is " +
                               std::to_string(kMaxDistances));
    if (l.total() > kMaxVaryings)
      throw shader::SpirvError("the " + stage_name + " writes " + std::to_string(l.user) + " varying components and " +
                               std::to_string(l.total() - l.user) +
                               " clip and cull distances and point size; tessref carries " + std::to_string(kMaxVaryings) +
                               " in all");
    return l;
  };
  if (gs_) {
    if (gs_->exe->module().modes.input_vertices < 1 || gs_->exe->module().modes.output_primitive == 0)
      throw shader::SpirvError("geometry shader: it declares no input or output primitive layout");
    pre_geometry_layout_ = layout_of(tes_ ? *tes_ : *vs_);
  }
  out_layout_ = layout_of(gs_ ? *gs_ : tes_ ? *tes_ : *vs_);
  num_varyings_ = out_layout_.total();
  map_patch_locations();
  // gl_PrimitiveID in the fragment shader: the patch's, carried as one more (flat) varying.
  for (const IoVariable& v : fs_->io.inputs)
    if (v.kind == IoKind::PrimitiveId) {
      if (num_varyings_ == kMaxVaryings)
        throw shader::SpirvError("the fragment shader reads gl_PrimitiveID, and every varying component is in use");
      primitive_id_varying_ = num_varyings_++;
      flat_varyings_.set(std::size_t(primitive_id_varying_));
    }
  // Flat: what the fragment shader declares flat, and every integer or double (which GLSL requires
  // to be flat, and whose bits must reach the fragment shader unchanged).
  for (const IoVariable& v : fs_->io.inputs) {
    if (v.kind != IoKind::User) continue;
    bool flat = v.variable->decorations.flat;
    for (const shader::Decorations& d : v.variable->member_decorations) flat |= d.flat;
    for (const IoWord& w : v.words) {
      if (!flat && w.scalar == Scalar::F32) continue;
      for (int h = 0; h < shader::scalar_words(w.scalar); ++h)
        if (w.io_word + h >= 4 && w.io_word + h - 4 < std::uint32_t(kMaxVaryings)) flat_varyings_.set(w.io_word + h - 4);
    }
  }
}

GlslProgram::~GlslProgram() = default;

void GlslProgram::map_patch_locations() {
  // A TCS's patch outputs meet the TES's patch inputs by location: the locations in use, in
  // increasing order, take PatchOutput::patch[0], [1], ...
  std::vector<IoVariable*> vars;
  for (StageProgram* sp : {tcs_.get(), tes_.get()})
    if (sp)
      for (auto* list : {&sp->io.inputs, &sp->io.outputs})
        for (IoVariable& v : *list)
          if (v.patch && v.kind == IoKind::User) vars.push_back(&v);
  std::map<std::uint32_t, std::uint32_t> slot;
  for (const IoVariable* v : vars)
    for (const IoWord& w : v->words) slot[(w.io_word - 4) / 4] = 0;
  std::uint32_t next = 0;
  for (auto& [location, s] : slot) s = next++;
  if (next > std::uint32_t(kMaxPatchAttributes))
    throw shader::SpirvError("the patch variables use " + std::to_string(next) +
                             " locations; tessref's limit is " + std::to_string(kMaxPatchAttributes) +
                             " (120 components)");
  for (IoVariable* v : vars)
    for (IoWord& w : v->words) w.io_word = 4 + 4 * slot[(w.io_word - 4) / 4] + (w.io_word - 4) % 4;
}

StageProgram* GlslProgram::find(shader::Stage s) {
  switch (s) {
    case shader::Stage::Vertex: return vs_.get();
    case shader::Stage::TessControl: return tcs_.get();
    case shader::Stage::TessEval: return tes_.get();
    case shader::Stage::Geometry: return gs_.get();
    case shader::Stage::Fragment: return fs_.get();
    default: return nullptr;
  }
}

void GlslProgram::set_uniform(const std::string& name, const UniformValue& value) {
  bool found = false;
  for (StageProgram* sp : stages()) {
    if (!sp) continue;
    const shader::Module& m = sp->exe->module();
    for (const shader::Variable& v : m.variables) {
      const auto at = resolve_uniform(m, v, name);
      if (!at) continue;
      std::uint32_t type = at->type, count = at->remaining;
      if (m.type(type).kind == TypeKind::Array) {  // "u" for u[N]: its elements from 0
        count = m.type(type).count;
        type = m.type(type).element;
      }
      if (m.type(type).kind == TypeKind::Struct || m.type(type).kind == TypeKind::Array)
        throw std::invalid_argument("uniform '" + name + "' is a " +
                                    (m.type(type).kind == TypeKind::Struct ? struct_name(m, type) : std::string("array of arrays")) +
                                    ": set its members or elements by their GL names ('" + name +
                                    (m.type(type).kind == TypeKind::Struct ? ".member" : "[i]") + "')");
      const Shape want = shape_of(m, type);
      const Shape got{value.scalar, value.columns, value.rows, false, {}};
      const bool sampler_ok = want.sampler && value.scalar == Scalar::I32 && value.columns == 1 && value.rows == 1;
      if (!sampler_ok && (want.scalar != got.scalar || want.columns != got.columns || want.rows != got.rows))
        throw std::invalid_argument("uniform '" + name + "' is a " + shape_name(want) + ", not a " +
                                    shape_name(got));
      const std::uint32_t ew = m.type(type).words;
      if (value.words.size() > std::size_t(count) * ew)
        throw std::invalid_argument("uniform '" + name + "': " + std::to_string(value.words.size() / std::max(ew, 1u)) +
                                    " values for " + std::to_string(count) + " array elements");
      const std::uint32_t base = sp->exe->slot(v.id)->base + at->word;
      // Several array elements may be given at once (count values in a row, as glUniform*v).
      std::copy(value.words.begin(), value.words.end(), sp->uniforms.begin() + base);
      found = true;
    }
  }
  if (!found) throw std::invalid_argument("no active uniform named '" + name + "'");
}

std::optional<UniformShape> GlslProgram::uniform_shape(const std::string& name) const {
  for (const StageProgram* sp : stages()) {
    if (!sp) continue;
    const shader::Module& m = sp->exe->module();
    for (const shader::Variable& v : m.variables) {
      const auto at = resolve_uniform(m, v, name);
      if (!at) continue;
      std::uint32_t type = at->type;
      int elements = int(at->remaining);  // "u[i]": elements i.. may be given in a row
      const bool whole_array = m.type(type).kind == TypeKind::Array;
      if (whole_array) {
        elements = int(m.type(type).count);
        type = m.type(type).element;
      }
      UniformShape u;
      u.elements = elements;
      if (m.type(type).kind == TypeKind::Struct) {
        u.is_struct = true;
        u.glsl_name = struct_name(m, type);
        for (std::uint32_t k = 0; k < m.type(type).members.size(); ++k)
          if (const auto mn = m.member_names.find({type, k}); mn != m.member_names.end()) u.members.push_back(mn->second);
      } else {
        const Shape s = shape_of(m, type);
        u.scalar = s.scalar;
        u.columns = s.columns;
        u.rows = s.rows;
        u.glsl_name = shape_name(s);
      }
      if (whole_array && elements > 1) u.glsl_name += "[" + std::to_string(elements) + "]";
      return u;
    }
  }
  return std::nullopt;
}

namespace {

// Calls fn(variable, element, block type, binding) for every uniform block (each element of a
// block array: binding + element) of the module.
// The uniform blocks (storage false) or the shader storage blocks of a module.
template <class Fn>
void for_each_block(const shader::Module& m, const Fn& fn, bool storage = false) {
  for (const shader::Variable& v : m.variables) {
    if (v.storage != spv::StorageClassUniform || !(storage ? v.decorations.buffer_block : v.decorations.block)) continue;
    std::uint32_t type = v.type, count = 1;
    if (m.type(type).kind == TypeKind::Array) {
      count = m.type(type).count;
      type = m.type(type).element;
    }
    const std::uint32_t binding = v.decorations.binding.value_or(0);
    for (std::uint32_t e = 0; e < count; ++e) fn(v, e, type, binding + e);
  }
}

}  // namespace

namespace {

std::vector<GlslProgram::UniformBlock> blocks_of(std::span<StageProgram* const> stages, bool storage) {
  std::vector<GlslProgram::UniformBlock> out;
  for (const StageProgram* sp : stages) {
    if (!sp) continue;
    const shader::Module& m = sp->exe->module();
    for_each_block(m, [&](const shader::Variable&, std::uint32_t, std::uint32_t type, std::uint32_t binding) {
      const auto n = m.names.find(type);
      GlslProgram::UniformBlock b{n != m.names.end() ? n->second : m.name_of(type), binding, shader::explicit_layout_extent(m, type)};
      if (std::none_of(out.begin(), out.end(), [&](const GlslProgram::UniformBlock& o) { return o.binding == b.binding && o.name == b.name; }))
        out.push_back(b);
    }, storage);
  }
  return out;
}

[[noreturn]] void throw_short_range(const shader::Module& m, std::uint32_t type, std::uint32_t binding,
                                    std::size_t extent, std::size_t range, bool storage) {
  const auto n = m.names.find(type);
  throw std::invalid_argument(std::string(storage ? "shader storage block '" : "uniform block '") +
                              (n != m.names.end() ? n->second : m.name_of(type)) + "' (binding " +
                              std::to_string(binding) + ") reads " + std::to_string(extent) +
                              " bytes; the bound range holds " + std::to_string(range));
}

bool bind_uniform_blocks(std::span<StageProgram* const> stages, std::uint32_t binding, std::span<const std::byte> range) {
  bool found = false;
  for (StageProgram* sp : stages) {
    if (!sp) continue;
    const shader::Module& m = sp->exe->module();
    for_each_block(m, [&](const shader::Variable& v, std::uint32_t element, std::uint32_t type, std::uint32_t b) {
      if (b != binding) return;
      const std::size_t extent = shader::explicit_layout_extent(m, type);
      if (range.size() < extent) throw_short_range(m, type, binding, extent, range.size(), false);
      std::uint32_t* out = sp->uniforms.data() + sp->exe->slot(v.id)->base + element * m.type(type).words;
      shader::read_explicit_layout(m, type, range, out);
      found = true;
    });
  }
  return found;
}

// Whether two block types flatten to the same words (the same scalars at the same places).
bool same_words(const shader::Module& a, std::uint32_t ta, const shader::Module& b, std::uint32_t tb) {
  const std::vector<shader::FlatComponent>& fa = a.type(ta).flat;
  const std::vector<shader::FlatComponent>& fb = b.type(tb).flat;
  return fa.size() == fb.size() && std::equal(fa.begin(), fa.end(), fb.begin(), [](const auto& x, const auto& y) {
           return x.word == y.word && x.scalar == y.scalar;
         });
}

}  // namespace

std::vector<GlslProgram::UniformBlock> GlslProgram::uniform_blocks() const {
  return blocks_of(stages(), false);
}
std::vector<GlslProgram::UniformBlock> GlslProgram::storage_blocks() const {
  return blocks_of(stages(), true);
}

bool GlslProgram::bind_uniform_buffer(std::uint32_t binding, std::span<const std::byte> range) {
  return bind_uniform_blocks(stages(), binding, range);
}

void GlslProgram::make_storage_memory() {
  std::vector<std::tuple<StageProgram*, std::uint32_t, std::size_t>> uses;  // stage, variable, memory
  for (StageProgram* sp : stages()) {
    if (!sp) continue;
    const shader::Module& m = sp->exe->module();
    for (const shader::Variable& v : m.variables) {
      if (v.storage != spv::StorageClassUniform || !v.decorations.buffer_block) continue;
      std::uint32_t type = v.type, elements = 1;
      if (m.type(type).kind == TypeKind::Array) {
        elements = m.type(type).count;
        type = m.type(type).element;
      }
      const std::uint32_t binding = v.decorations.binding.value_or(0);
      auto it = std::find_if(storage_.begin(), storage_.end(), [&](const StorageMemory& s) {
        return s.first_binding == binding && s.elements == elements && same_words(*s.module, s.type, m, type);
      });
      if (it == storage_.end()) {
        StorageMemory s;
        s.module = &m;
        s.type = type;
        s.first_binding = binding;
        s.elements = elements;
        s.element_words = m.type(type).words;
        s.words.assign(std::size_t(elements) * s.element_words, 0u);
        s.original = s.words;
        s.ranges.assign(elements, {});
        storage_.push_back(std::move(s));
        it = storage_.end() - 1;
      }
      uses.emplace_back(sp, v.id, std::size_t(it - storage_.begin()));
    }
  }
  // Pointers only once storage_ has stopped growing.
  for (const auto& [sp, id, k] : uses) sp->storage.push_back({id, storage_[k].words.data()});
}

bool GlslProgram::bind_storage_buffer(std::uint32_t binding, std::span<std::byte> range) {
  bool found = false;
  for (StorageMemory& s : storage_) {
    if (binding < s.first_binding || binding - s.first_binding >= s.elements) continue;
    const std::uint32_t e = binding - s.first_binding;
    const std::size_t extent = shader::explicit_layout_extent(*s.module, s.type);
    if (range.size() < extent) throw_short_range(*s.module, s.type, binding, extent, range.size(), true);
    std::uint32_t* words = s.words.data() + std::size_t(e) * s.element_words;
    shader::read_explicit_layout(*s.module, s.type, range, words);
    std::copy_n(words, s.element_words, s.original.data() + std::size_t(e) * s.element_words);
    s.ranges[e] = range;
    found = true;
  }
  if (found) bound_storage_.insert(binding);
  return found;
}

void GlslProgram::write_back_storage() {
  if (!writes_memory()) return;  // read-only blocks: nothing changed to compare or write
  for (StorageMemory& s : storage_)
    for (std::uint32_t e = 0; e < s.elements; ++e) {
      if (s.ranges[e].empty()) continue;
      const std::size_t at = std::size_t(e) * s.element_words;
      shader::write_explicit_layout(*s.module, s.type, s.words.data() + at, s.original.data() + at, s.ranges[e]);
      std::copy_n(s.words.data() + at, s.element_words, s.original.data() + at);
    }
}

bool GlslProgram::writes_memory() const {
  for (const StageProgram* sp : stages())
    if (sp && sp->side_effects) return true;
  return false;
}

std::optional<GlslProgram::UniformBlock> GlslProgram::unbound_storage_block() const {
  for (const UniformBlock& b : storage_blocks())
    if (!bound_storage_.count(b.binding)) return b;
  return std::nullopt;
}

std::string GlslProgram::draw_refusal() const {
  const auto block = unbound_storage_block();
  if (!block) return {};
  return "the shader storage block '" + block->name + "' (binding " + std::to_string(block->binding) +
         ") has no buffer range bound; GL leaves its reads undefined (bind one)";
}

std::vector<std::string> GlslProgram::uniform_names() const {
  std::vector<std::string> names;
  for (const StageProgram* sp : stages())
    if (sp) uniform_names_of(sp->exe->module(), names);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

bool GlslProgram::uses_atomic_counters() const {
  for (const StageProgram* sp : stages())
    if (sp && !sp->counters.empty()) return true;
  return false;
}

void GlslProgram::bind_texture(std::uint32_t unit, const texture::Texture* texture) {
  if (textures_.size() <= unit) textures_.resize(unit + 1, nullptr);
  textures_[unit] = texture;
}

void GlslProgram::bind_image(std::uint32_t unit, texture::Texture* texture) {
  if (images_.size() <= unit) images_.resize(unit + 1, nullptr);
  images_[unit] = texture;
}

std::optional<texture::TexelFormat> GlslProgram::image_format(const std::string& name) const {
  for (const StageProgram* sp : stages()) {
    if (!sp) continue;
    const shader::Module& m = sp->exe->module();
    for (const shader::Variable& v : m.variables)
      if (v.name == name && m.type(v.type).kind == TypeKind::Image) return shader::image_texel_format(m.type(v.type).image_format);
  }
  return std::nullopt;
}

std::optional<std::uint32_t> GlslProgram::attribute_location(const std::string& name) const {
  for (const IoVariable& v : vs_->io.inputs)
    if (v.kind == IoKind::User && v.variable->name == name) return v.variable->decorations.location;
  return std::nullopt;
}

TessLayout GlslProgram::tes_layout() const {
  if (!tes_) throw std::logic_error("tes_layout: no tessellation evaluation shader");
  return tes_layout_override_ ? *tes_layout_override_ : layout_of(tes_->exe->module().modes);
}

int GlslProgram::tcs_output_vertices() const { return tcs_ ? tcs_->exe->module().modes.output_vertices : 0; }

void GlslProgram::run_vertices(const std::vector<VertexAttribute>& attributes, std::size_t first,
                               std::size_t count, int instance, StageVertex* out,
                               const Parallel& parallel, const std::uint32_t* vertex_ids) const {
  run_vertex_stage(*vs_, attributes, first, count, instance, out, parallel, vertex_ids);
}

std::shared_ptr<const TessControlProgram> GlslProgram::control(int patch_vertices, const glm::vec4& default_outer,
                                                               const glm::vec2& default_inner) const {
  if (tcs_) return std::make_unique<GlslControl>(*tcs_);
  return std::make_unique<PassThroughControl>(patch_vertices, default_outer, default_inner);
}

std::shared_ptr<const TessEvalProgram> GlslProgram::evaluation() const {
  if (!tes_) throw std::logic_error("evaluation: no tessellation evaluation shader");
  if (gs_) return std::make_unique<GlslEvaluation>(*tes_, tes_layout(), pre_geometry_layout_, pre_geometry_layout_.total(),
                                                   VaryingMask{}, -1);
  return std::make_unique<GlslEvaluation>(*tes_, tes_layout(), out_layout_, num_varyings_, flat_varyings_,
                                          primitive_id_varying_);
}

std::shared_ptr<const GeometryProgram> GlslProgram::geometry() const {
  if (!gs_) return nullptr;
  return std::make_unique<GlslGeometry>(*gs_, pre_geometry_layout_, out_layout_, num_varyings_, flat_varyings_,
                                        primitive_id_varying_);
}

std::shared_ptr<const FragmentProgram> GlslProgram::fragment() const {
  return std::make_unique<GlslFragment>(*fs_, out_layout_, num_varyings_, primitive_id_varying_);
}

void GlslProgram::rasterizer_vertex(const StageVertex& shaded, ClipVertex* records) const {
  // The vertex shader's outputs as I/O words, placed as the layout of the stage's output says.
  const VaryingLayout& layout = gs_ ? pre_geometry_layout_ : out_layout_;
  const auto* src = reinterpret_cast<const float*>(shaded.attr.data());
  auto* dst = reinterpret_cast<float*>(records);
  std::copy_n(src, 4 + layout.user, dst);
  std::copy_n(src + kClipDistanceWord, layout.clip, dst + 4 + layout.user);
  std::copy_n(src + kCullDistanceWord, layout.cull, dst + 4 + layout.user + layout.clip);
  std::copy_n(src + kPointSizeWord, layout.point_size, dst + 4 + layout.user + layout.clip + layout.cull);
}

OutputWords GlslProgram::output_floats(const std::string& name) const {
  return glsl::output_floats(gs_ ? *gs_ : tes_ ? *tes_ : *vs_, out_layout_, name);
}

DistanceVaryings GlslProgram::distance_varyings() const {
  DistanceVaryings d{out_layout_.user, out_layout_.clip, out_layout_.user + out_layout_.clip, out_layout_.cull};
  // The compatibility profile's gl_ClipVertex (shader/glsl_rewrite.h), where the last stage writes it.
  const StageProgram& last = gs_ ? *gs_ : tes_ ? *tes_ : *vs_;
  for (const IoVariable& v : last.io.outputs)
    if (v.kind == IoKind::User && v.variable->name == shader::kCompatibilityClipVertex && !v.words.empty())
      d.clip_vertex_first = out_layout_.float_of(v.words[0].io_word) - 4;
  return d;
}

}  // namespace tessref::glsl
