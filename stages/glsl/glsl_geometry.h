#pragma once
// A user's geometry shader on the executor: one lane per input primitive and invocation
// (gl_InvocationID), the vertices each lane emits collected in its own order.
#include "stages/geometry_stage.h"
#include "stages/glsl/glsl_program.h"

namespace tessref::glsl {

class GlslGeometry final : public GeometryProgram {
 public:
  // inputs: where the input vertices carry what the stage before wrote; outputs: where the output
  // vertices carry this stage's outputs; varyings: the output vertices' varyings (the fragment
  // shader's inputs); primitive_id_varying: the varying that carries gl_PrimitiveID to the
  // fragment shader (-1: none).
  GlslGeometry(const StageProgram& sp, const VaryingLayout& inputs, const VaryingLayout& outputs, int varyings,
               const VaryingMask& flat, int primitive_id_varying);
  int input_vertices() const override { return input_vertices_; }
  int num_varyings() const override { return varyings_; }
  VaryingMask flat_varyings() const override { return flat_; }
  void run(const float* const* corners, int in_varyings, std::size_t count, std::uint32_t first_id,
           GeometryOutput& out) const override;

 private:
  // Lanes [0, n) run primitives first + lane / invocations, invocation lane % invocations.
  void run_lanes(const float* const* corners, int in_varyings, std::size_t first, int n, std::uint32_t first_id,
                 GeometryOutput& out) const;
  const StageProgram& sp_;
  VaryingLayout inputs_, outputs_;
  int varyings_;
  VaryingMask flat_;
  int primitive_id_varying_;
  int input_vertices_, output_corners_, max_vertices_, invocations_;
};

}  // namespace tessref::glsl
