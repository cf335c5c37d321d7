#pragma once
// A user's GLSL program on tessref's pipeline: the compiled stages on the SPIR-V executor, adapted
// to the stage interfaces (TessControlProgram, TessEvalProgram, FragmentProgram) and a batched
// vertex stage. See glsl_interface.h for how values travel between stages.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "raster/rasterizer.h"
#include "shader/executor.h"
#include "shader/glsl_compile.h"
#include "stages/draw_program.h"
#include "stages/glsl/glsl_interface.h"
#include "stages/tess_stage.h"

namespace tessref::glsl {

// A stage failed at run time: the message names the stage, the patch or vertex, the invocation
// and the source line.
class StageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One compiled stage: the executable, its interface and the values of its uniforms.
struct StageProgram {
  shader::Stage stage = shader::Stage::Vertex;
  std::unique_ptr<shader::Executable> exe;
  StageInterface io;
  std::vector<std::uint32_t> uniforms;  // an image of the shared words holding uniforms
  std::vector<std::pair<std::uint32_t, std::uint32_t>> uniform_ranges;  // (first word, words)
  const std::vector<const texture::Texture*>* textures = nullptr;  // the program's, by unit
  const std::vector<texture::Texture*>* images = nullptr;          // the program's, by image unit
  const bool* cube_map_seamless = nullptr;  // the program's GL_TEXTURE_CUBE_MAP_SEAMLESS
  // Atomic counters: (shared word, binding, word offset in the binding's buffer), and the
  // program's buffers (binding -> words), which every run reads and writes back.
  std::vector<std::array<std::uint32_t, 3>> counters;
  std::map<std::uint32_t, std::vector<std::uint32_t>>* counter_buffers = nullptr;
  // Shader storage blocks: (variable id, the words of its StorageMemory), bound at every batch.
  std::vector<std::pair<std::uint32_t, std::uint32_t*>> storage;
  // Whether invocations write memory others see (shader::Executable::writes_memory): then each
  // batch is one invocation (a TCS: one patch; a fragment shader: one quad, or the two quads of
  // one sampling vector), so that side effects happen in the order of a serial run whatever the
  // batch size.
  bool side_effects = false;

  // This thread's invocations with the uniforms and counters loaded and the shared memory of
  // `groups` groups (patches) zeroed.
  shader::Invocations& prepare(int groups = 1) const;
  // After a run: the counters back into the program's buffers.
  void finish(shader::Invocations& inv) const;
  [[noreturn]] void rethrow(const shader::ShaderRuntimeError& e, const std::string& where) const;
};

// A uniform's value as the user gives it: flattened scalars (a double as two words, low first).
struct UniformValue {
  shader::Scalar scalar = shader::Scalar::F32;
  int columns = 1, rows = 1;  // a vecN: 1 x N; a matCxR: C x R
  std::vector<std::uint32_t> words;
};

using VertexAttribute = tessref::VertexAttribute;  // stages/draw_program.h

// A uniform's GLSL type: columns x rows of scalar (1 x N for a vector), elements for an array
// (for an element "u[i]": the elements from i to the end, which may be set in a row); or a
// struct (whose members are set by their own names).
struct UniformShape {
  shader::Scalar scalar = shader::Scalar::F32;
  int columns = 1, rows = 1, elements = 1;
  std::string glsl_name;  // "vec3", "mat4", "int[8]", "sampler2D", "struct Light[4]"
  bool is_struct = false;
  std::vector<std::string> members;  // a struct's member names, in order
};

class GlslProgram final : public DrawProgram {
 public:
  // Builds the stages of a compiled program. The program must have vertex, tessellation
  // evaluation and fragment stages; the control stage is optional (default levels are then used).
  // Throws shader::SpirvError for what the executor or tessref's limits cannot take.
  // storage: the bytes bound at each shader storage block binding, which size the blocks'
  // runtime arrays (shader/spirv_module.h); a block with one at an unsized binding is refused.
  explicit GlslProgram(const shader::CompiledProgram& compiled, shader::ExecLimits limits = {},
                       const shader::StorageBufferSizes& storage = {});
  ~GlslProgram() override;

  // Sets a uniform by its GL name ("u", "u[i]", "lights[2].color", "Block.member") in every stage
  // that declares it; values for several array elements in a row set them from that one on, as
  // glUniform*v does. Throws std::invalid_argument if no stage has it, its GLSL type differs from
  // the value's, it is a struct (set its members), or there are more values than elements.
  void set_uniform(const std::string& name, const UniformValue& value);
  std::vector<std::string> uniform_names() const;  // sorted, without duplicates
  // The type of the uniform with this GL name (an element's, for "name[i]"); nullopt if no stage
  // has it.
  std::optional<UniformShape> uniform_shape(const std::string& name) const;
  // Where the rasterizer's vertex holds each word of the last vertex stage's output `name`, as
  // glTransformFeedbackVaryings names it (stages/glsl/output_names.h); std::invalid_argument why not.
  OutputWords output_floats(const std::string& name) const;
  // A uniform block of the program: its GL name, binding point and the bytes its layout reads.
  struct UniformBlock {
    std::string name;
    std::uint32_t binding = 0;
    std::size_t extent = 0;  // shader::explicit_layout_extent
  };
  std::vector<UniformBlock> uniform_blocks() const;  // every stage's, without duplicates
  std::vector<UniformBlock> storage_blocks() const;  // the shader storage blocks, the same way
  // glBindBufferRange(GL_UNIFORM_BUFFER, binding, ...): the blocks at `binding` (in every stage)
  // take their values from range through their explicit layout. Returns false when no block uses
  // the binding; throws std::invalid_argument when range is shorter than a block's extent.
  bool bind_uniform_buffer(std::uint32_t binding, std::span<const std::byte> range);
  // glBindBufferRange(GL_SHADER_STORAGE_BUFFER, binding, ...): the same for the shader storage
  // blocks (std430), whose runtime arrays the constructor sized for this range's bytes. The
  // blocks' memory is the program's from here on; write_back_storage() puts what the shaders
  // wrote into range, which must outlive the draws.
  bool bind_storage_buffer(std::uint32_t binding, std::span<std::byte> range);
  // After a draw: every storage block's changed values back into its bound range's bytes
  // (nothing to do when no stage writes memory).
  void write_back_storage();
  // A storage block no range was bound to, if any: a draw refuses it (GL leaves its reads undefined).
  std::optional<UniformBlock> unbound_storage_block() const;
  // Binds a texture to a sampler's binding (texture unit). The texture must outlive the draws.
  void bind_texture(std::uint32_t unit, const texture::Texture* texture);
  // glBindImageTexture(unit, texture, level 0, layered, 0, GL_READ_WRITE, its format): the
  // images at `unit` read and write the texture's level 0 (docs/textures.md, "Images"). The
  // texture must outlive the draws.
  void bind_image(std::uint32_t unit, texture::Texture* texture);
  // The internal format an image uniform declares (layout(rgba32f) ...); nullopt if no stage has
  // an image of that name (or its format is one tessref's textures lack).
  std::optional<texture::TexelFormat> image_format(const std::string& name) const;
  // glEnable / glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS) for the draws that follow (off by default).
  void set_cube_map_seamless(bool on) { cube_map_seamless_ = on; }
  // Atomic counter buffers (binding -> 32-bit counters). A program that uses atomic counters is
  // drawn on one thread, in patch and tile order, so the counts and the values each invocation
  // sees do not depend on the thread count.
  bool uses_atomic_counters() const;
  // Whether a stage writes storage blocks or atomic counters: the draw then runs on one thread
  // and each stage one invocation a batch, so that the side effects and the values invocations
  // read back are those of a serial run in tessref's order (docs/executor.md, "Side effects").
  bool writes_memory() const;
  bool draws_serially() const override { return uses_atomic_counters() || writes_memory(); }
  std::string draw_refusal() const override;
  std::vector<std::uint32_t>& counter_buffer(std::uint32_t binding) { return counter_buffers_[binding]; }

  // The location of the vertex shader input with this name; nullopt if there is none.
  std::optional<std::uint32_t> attribute_location(const std::string& name) const;

  bool has_tcs() const { return tcs_ != nullptr; }
  bool has_tes() const override { return tes_ != nullptr; }
  TessLayout tes_layout() const;
  int tcs_output_vertices() const;

  // Runs the vertex shader for vertices [first, first + count) of the attribute arrays of instance
  // `instance` (gl_InstanceID); gl_VertexID is vertex_ids[i] when given, else first + i. out
  // receives gl_Position and the outputs as I/O slots.
  void run_vertices(const std::vector<VertexAttribute>& attributes, std::size_t first, std::size_t count,
                    int instance, StageVertex* out, const Parallel& parallel,
                    const std::uint32_t* vertex_ids = nullptr) const override;

  // Stage programs for tessellate() and draw_triangles(). default_outer/inner: the levels used when
  // there is no control stage (glPatchParameterfv); patch_vertices: GL_PATCH_VERTICES.
  std::shared_ptr<const TessControlProgram> control(int patch_vertices, const glm::vec4& default_outer,
                                                    const glm::vec2& default_inner) const override;
  std::shared_ptr<const TessEvalProgram> evaluation() const override;
  std::shared_ptr<const FragmentProgram> fragment() const override;
  std::shared_ptr<const GeometryProgram> geometry() const override;
  // The untessellated vertex's varyings: the fragment shader's, or with a geometry shader, the
  // vertex shader's outputs that shader reads (it interpolates nothing).
  int varyings() const override { return gs_ ? pre_geometry_layout_.total() : num_varyings_; }
  void rasterizer_vertex(const StageVertex& shaded, ClipVertex* records) const override;
  DistanceVaryings distance_varyings() const override;
  VaryingMask flat_varyings() const override { return gs_ ? VaryingMask{} : flat_varyings_; }
  bool has_geometry() const { return gs_ != nullptr; }
  // Draw the tessellation evaluation shader's patches with this layout instead of the one it
  // declares (the GLSL twins take the scene's spacing and winding, as the real-GL runner rewrites
  // their layout line).
  void override_tes_layout(const TessLayout& layout) { tes_layout_override_ = layout; }

 private:
  StageProgram* find(shader::Stage s);
  // Every stage in pipeline order, null where the program has none.
  std::array<StageProgram*, 5> stages() const { return {vs_.get(), tcs_.get(), tes_.get(), gs_.get(), fs_.get()}; }
  void map_patch_locations();
  void make_storage_memory();  // storage_, and each stage's pointers into it
  std::unique_ptr<StageProgram> vs_, tcs_, tes_, gs_, fs_;
  std::vector<const texture::Texture*> textures_;
  std::vector<texture::Texture*> images_;
  bool cube_map_seamless_ = false;
  std::map<std::uint32_t, std::vector<std::uint32_t>> counter_buffers_;
  std::set<std::uint32_t> bound_storage_;  // bindings bind_storage_buffer filled
  // A shader storage block's memory for the draws: its flattened words (every element of a block
  // array), shared by the stages that declare it alike, read from the bound ranges and written
  // back to them after each draw.
  struct StorageMemory {
    const shader::Module* module = nullptr;
    std::uint32_t type = 0;  // the block's struct type
    std::uint32_t first_binding = 0, elements = 1, element_words = 0;
    std::vector<std::uint32_t> words, original;  // now, and as read from the ranges
    std::vector<std::span<std::byte>> ranges;    // per element; empty where none is bound
  };
  std::vector<StorageMemory> storage_;  // made once by the constructor: stages point into it
  int num_varyings_ = 0;  // handed to the fragment shader: out_layout_, then gl_PrimitiveID's
  VaryingLayout out_layout_;  // the last stage before the rasterizer's outputs
  VaryingLayout pre_geometry_layout_;  // with a geometry shader: the outputs of the stage before it
  VaryingMask flat_varyings_;  // TriangleBatch::flat_varyings
  int primitive_id_varying_ = -1;
  std::optional<TessLayout> tes_layout_override_;  // the varying carrying gl_PrimitiveID to the FS, -1: none
};

}  // namespace tessref::glsl
