#pragma once
// The scene's draw, with each tessellated chunk drawn a second time, tagged (fragment_tags.h),
// right after the real one rasterized it: the tagged redraw sees the same triangles in the same
// order through the same rasterizer, so its fragments are the draw's, each knowing its patch,
// triangle and gl_TessCoord. What observes them is the redraw's fragment program.
#include <functional>
#include <vector>

#include "common/parallel.h"
#include "render/draw.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "raster/framebuffer.h"
#include "raster/rasterizer.h"

namespace tessref {

struct TaggedRedraw {
  // On: the redraw keeps the draw's winners; off: every fragment arrives, losers included. Back
  // faces are culled as the scene culls them: the redraw must see the draw's triangles.
  bool depth_test = true;
  const FragmentProgram* fs = nullptr;  // sees the tagged fragments
  // Called after each chunk's redraw, on the calling thread (null: nothing to do).
  std::function<void()> after_chunk;
};

// InputError naming `option` when a program of the scene has a geometry shader: the redraws tag
// the evaluation or vertex stage's primitives, and do not follow fragments through one yet.
void refuse_geometry_shaders(const Scene& scene, const char* option);

// Draws the scene into fb as render_scene does (fb then holds the image `render` writes) and
// redraws every chunk tagged into a framebuffer of its own. InputError (naming `option`) when the
// scene does not tessellate: without patches there is nothing to tag.
DrawStats draw_with_tagged_redraw(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                                  Framebuffer& fb, const TaggedRedraw& redraw, const char* option);

}  // namespace tessref
