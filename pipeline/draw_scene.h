#pragma once
// A scene's GL draws (Scene::draws): the buffers loaded, each call's vertices pulled through its
// vertex arrays (draw/vertex_fetch.h), its primitives assembled and drawn with its GLSL program,
// in order, into one framebuffer.
#include <vector>

#include "draw/vertex_fetch.h"
#include "pipeline/glsl_draw.h"
#include "pipeline/scene.h"

namespace tessref {

// The scene's buffers with their bytes (files read now). InputError naming buffers.NAME.file.
std::vector<draw::Buffer> load_buffers(const Scene& scene);

// Vertices per assembled primitive of an untessellated mode: 3, 2 (lines) or 1 (points).
int primitive_corners(DrawMode mode);

// The primitives' vertices for `mode`, as positions into the fetched vertices: each restarted run
// cut to whole primitives (GL ignores a partial last one), strips and fans as triangle lists in
// GL's vertex order (the last vertex of each triangle is GL's provoking vertex).
// Line strips and loops become line lists, points a point list.
std::vector<std::uint32_t> assemble(DrawMode mode, int patch_vertices,
                                    const std::vector<std::vector<std::uint32_t>>& runs);

// The patch ids a scene of draws gives its patches (GlslDrawCall::first_patch_id): counted over
// the draws, their calls and instances in order, gl_PrimitiveID within an instance. For each draw,
// each call's first id and patches per instance (0 for an untessellated draw).
struct CallPatches {
  std::uint32_t first_patch = 0;
  std::uint32_t per_instance = 0;
  std::uint32_t instances = 0;
};
std::vector<std::vector<CallPatches>> patch_numbering(const Scene& scene, const std::vector<draw::Buffer>& buffers);

// Draws every draw of the scene into fb (already cleared): a draw with its own `shaders` with its
// program, the others with the scene's (all compiled before the first draw, so a broken one
// draws nothing).
DrawStats draw_scene_draws(const Scene& scene, Framebuffer& fb, const Parallel& parallel, const DrawOptions& options);

}  // namespace tessref
