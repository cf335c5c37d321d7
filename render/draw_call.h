#pragma once
// The draw call every draw goes through, a user's GLSL program's and the built-in programs' alike:
// vertex shader over the attribute arrays, then, for GL_PATCHES, TCS -> primitive generator -> TES,
// then rasterizer -> fragment shader, instance by instance.
#include <cstddef>
#include <functional>
#include <span>

#include "render/draw.h"
#include "stages/draw_program.h"

namespace tessref {

struct DrawCall {
  // glDrawArrays: vertices [first, first + count). glDrawElements (indices not empty): the vertex
  // shader runs once for each of the attribute arrays' vertex_count vertices, and the primitives
  // take their vertices by index.
  std::size_t first = 0, count = 0;
  std::span<const std::uint32_t> indices;
  std::size_t vertex_count = 0;
  // When set (draw/vertex_fetch.h): the vertex shader runs once for each entry, with that
  // gl_VertexID, and indices (or, without indices, the order) refer to positions in this list.
  std::span<const std::uint32_t> vertex_ids;
  // Appends the attributes that change with the instance (instanced arrays) to the draw's.
  std::function<void(int instance, std::vector<VertexAttribute>&)> instance_attributes;
  int instances = 1;
  bool patches = true;               // GL_PATCHES; false: no tessellation stages, and
  int corners = 3;                   // vertices per primitive: 3 triangles, 2 lines, 1 points
  int patch_vertices = 3;            // GL_PATCH_VERTICES
  glm::vec4 default_outer{1.0f};     // GL_PATCH_DEFAULT_OUTER_LEVEL (no control shader)
  glm::vec2 default_inner{1.0f};     // GL_PATCH_DEFAULT_INNER_LEVEL
  // The tessellation records' patch ids: first_patch_id + instance * patches per instance +
  // gl_PrimitiveID, so that every patch of a scene's draw has its own.
  std::uint32_t first_patch_id = 0;
};

// The most vertices one draw shades (one instance): the vertex shader's outputs are all held at
// once, 528 bytes each, so this bounds a draw's shaded vertices to about 2 GiB.
inline constexpr std::size_t kMaxDrawVertices = std::size_t(1) << 22;

// Draws into fb. A partial last primitive is ignored, as in GL. Throws glsl::StageError when a
// shader fails at run time (instruction budget) and std::invalid_argument for a call GL would
// refuse (GL_PATCHES without a tessellation evaluation shader, or the reverse; a program's
// draw_refusal) or one that shades more than kMaxDrawVertices vertices. options.tess_chunk_patches
// overrides the program's tess_grain. The bytes of fb do not depend on parallel.threads(), the
// program's batch size nor the grain.
DrawStats run_draw(const DrawProgram& program, const std::vector<VertexAttribute>& attributes,
                   const DrawCall& call, const RasterState& raster_state, Framebuffer& fb,
                   const Parallel& parallel, const DrawOptions& options = {});

}  // namespace tessref
