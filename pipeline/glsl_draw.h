#pragma once
// A draw call with a user's GLSL program: vertex shader over the attribute arrays, then
// TCS -> primitive generator -> TES -> rasterizer -> fragment shader, instance by instance.
#include <cstddef>

#include "pipeline/draw.h"
#include "stages/glsl/glsl_program.h"

namespace tessref {

struct GlslDrawCall {
  std::size_t first = 0, count = 0;  // vertices, as glDrawArrays
  int instances = 1;
  int patch_vertices = 3;            // GL_PATCH_VERTICES
  glm::vec4 default_outer{1.0f};     // GL_PATCH_DEFAULT_OUTER_LEVEL (no control shader)
  glm::vec2 default_inner{1.0f};     // GL_PATCH_DEFAULT_INNER_LEVEL
};

// Draws count / patch_vertices patches (a partial last patch is ignored, as in GL) of each
// instance into fb. Throws glsl::StageError when a shader fails at run time (instruction budget,
// ...). The bytes of fb do not depend on parallel.threads().
DrawStats draw_glsl_patches(const glsl::GlslProgram& program,
                            const std::vector<glsl::VertexAttribute>& attributes,
                            const GlslDrawCall& call, const RasterState& raster_state,
                            Framebuffer& fb, const Parallel& parallel,
                            const TessOptions& tess_options = {});

}  // namespace tessref
