#pragma once
// The built-in programs a scene is drawn with (shaders.program builtin), built in one place so that
// the draw (pipeline/draw.cpp, pipeline/render.cpp) and tools that rerun part of it
// (tessref inspect) construct the very same program objects with the same uniforms.
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/scene.h"
#include "pipeline/tessellation_settings.h"
#include "stages/programs/transform.h"
#include "stages/schemes/flat.h"
#include "stages/schemes/pn_triangles.h"
#include "stages/tess_stage.h"

namespace tessref {

// The scene's vertex shader: model matrix from scene.transform, view-projection from its camera
// (already fitted, if camera.fit) and image size.
programs::TransformVertexShader scene_vertex_shader(const Scene& scene);

// The control and evaluation programs of the scheme (pn or flat) the settings name. Holds both
// pairs; tcs()/tes() pick the one the draw runs. viewport: the framebuffer's size in pixels
// (adaptive levels).
struct BuiltinTessPrograms {
  PassThroughTcs flat_tcs;
  FlatTes flat_tes;
  PnTcs pn_tcs;
  PnTes pn_tes;
  bool pn = true;
  const TessControlProgram& tcs() const { return pn ? static_cast<const TessControlProgram&>(pn_tcs) : flat_tcs; }
  const TessEvalProgram& tes() const { return pn ? static_cast<const TessEvalProgram&>(pn_tes) : flat_tes; }
};
BuiltinTessPrograms builtin_tess_programs(const TessellationSettings& settings,
                                          const programs::TransformVertexShader& vs,
                                          const glm::vec2& viewport);

// The TCS's gl_in[] data: one StageVertex per vertex shader output (kAttrPosition = (world, 1),
// kAttrNormal = (normal, 0)).
std::vector<StageVertex> tess_control_points(const std::vector<programs::VertexOut>& shaded);

}  // namespace tessref
