#pragma once
// The stage programs a GlslProgram hands to the pipeline: each fills its executable's inputs from
// tessref's stage structs, runs a batch of invocations and reads the outputs back.
#include "stages/glsl/glsl_program.h"

namespace tessref::glsl {

TessLayout layout_of(const shader::ExecutionModes& modes);

// A TCS: all invocations of a patch run as one batch, in lock step (so barrier() holds).
class GlslControl final : public TessControlProgram {
 public:
  explicit GlslControl(const StageProgram& sp) : sp_(sp) {}
  int output_vertices() const override;
  void run(int phase, int invocation_id, const Patch& in, PatchOutput& out) const override;
  void run_phase(int phase, const Patch& in, PatchOutput& out) const override;
  void run_patches(const Patch* const* in, PatchOutput* const* out, int count) const override;
  // GL's phases of the shader (its barrier() calls + 1; GLSL allows barrier() only in main(),
  // outside control flow, so each runs once). The executor runs them in lock step, in one pass,
  // which is why phases() stays 1.
  int gl_phases() const;

 private:
  void read_outputs(shader::Invocations& inv, int group, PatchOutput& out) const;
  const StageProgram& sp_;
};

// No TCS in the program: the patch's vertices go to the TES as they are, with the default levels
// (glPatchParameterfv(GL_PATCH_DEFAULT_OUTER_LEVEL / INNER_LEVEL)).
class PassThroughControl final : public TessControlProgram {
 public:
  PassThroughControl(int vertices, const glm::vec4& outer, const glm::vec2& inner)
      : vertices_(vertices), outer_(outer), inner_(inner) {}
  int output_vertices() const override { return vertices_; }
  void run(int phase, int invocation_id, const Patch& in, PatchOutput& out) const override;

 private:
  int vertices_;
  glm::vec4 outer_;
  glm::vec2 inner_;
};

class GlslEvaluation final : public TessEvalProgram {
 public:
  // primitive_id_varying: the varying that carries gl_PrimitiveID to the fragment shader (-1: none).
  // outputs: where its outputs go in the rasterizer's vertex; varyings: that vertex's varyings.
  GlslEvaluation(const StageProgram& sp, const TessLayout& layout, const VaryingLayout& outputs, int varyings,
                 const VaryingMask& flat, int primitive_id_varying)
      : sp_(sp), layout_(layout), outputs_(outputs), varyings_(varyings), flat_(flat),
        primitive_id_varying_(primitive_id_varying) {}
  TessLayout layout() const override { return layout_; }
  int num_varyings() const override { return varyings_; }
  VaryingMask flat_varyings() const override { return flat_; }
  // --dump-tess: locations 0 and 1 (the twins' v_world_position and v_world_normal).
  std::array<int, 2> dump_varyings() const override { return {0, 4}; }
  ClipVertex evaluate(const glm::vec3& tess_coord, const PatchOutput& patch, int primitive_id) const override;
  void evaluate_batch(const PatchOutput& patch, int primitive_id, TessEvalBatch& batch) const override;

 private:
  // Points [first, first + n) of the batch as one run of the executor.
  void evaluate_lanes(const PatchOutput& patch, int primitive_id, TessEvalBatch& batch, int first, int n) const;
  const StageProgram& sp_;
  TessLayout layout_;
  VaryingLayout outputs_;
  int varyings_;
  VaryingMask flat_;
  int primitive_id_varying_;
  int output_locations_ = 0;  // 1 + the highest output location the program writes (at most 8)
};

class GlslFragment final : public FragmentProgram {
 public:
  GlslFragment(const StageProgram& sp, const VaryingLayout& inputs, int varyings, int primitive_id_varying);
  FragmentOutput shade(const FragmentInput& in) const override;
  void shade_batch(FragmentBatch& batch) const override;
  bool may_discard() const override { return sp_.exe->may_discard(); }
  bool writes_depth() const override { return frag_depth_ != nullptr; }
  bool reads_quads() const override { return sp_.exe->reads_quads(); }
  bool shades_whole_vectors() const override { return samples_textures_; }
  bool has_side_effects() const override { return sp_.side_effects; }
  bool early_fragment_tests() const override { return sp_.exe->module().modes.early_fragment_tests; }

 private:
  void shade_lanes(FragmentBatch& batch, int first, int n) const;  // lanes [first, first + n)
  const StageProgram& sp_;
  VaryingLayout inputs_;  // where the rasterizer's vertex carries what the fragment shader reads
  int varyings_;
  int primitive_id_varying_;
  bool samples_textures_;  // the lanes llvmpipe samples together then matter (shade_batch)
  const IoVariable* frag_depth_ = nullptr;  // gl_FragDepth, if the shader writes it
  int output_locations_ = 0;  // 1 + the highest output location the program writes (at most 8)
};

void run_vertex_stage(const StageProgram& sp, const std::vector<VertexAttribute>& attributes,
                      std::size_t first, std::size_t count, int instance, StageVertex* out,
                      const Parallel& parallel, const std::uint32_t* vertex_ids = nullptr);

}  // namespace tessref::glsl
