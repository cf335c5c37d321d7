#include "inspect/tagged_draw.h"

#include <string>

#include "common/error.h"
#include "inspect/fragment_tags.h"
#include "render/render.h"

namespace tessref {

void refuse_geometry_shaders(const Scene& scene, const char* option) {
  std::string key;
  if (scene.shaders.program == ShaderProgram::Custom && !scene.shaders.geometry.empty()) key = "shaders.geometry";
  for (const DrawSetting& d : scene.draws)
    if (key.empty() && d.shaders && !d.shaders->geometry.empty()) key = d.key + ".shaders.geometry";
  if (!key.empty())
    throw InputError(std::string(option) + ": " + key + ": the program has a geometry shader, and inspect does not "
                     "follow fragments through one yet (render and verify draw it)");
}

DrawStats draw_with_tagged_redraw(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                                  Framebuffer& fb, const TaggedRedraw& redraw, const char* option) {
  const auto no_patches = [&] {
    return InputError(std::string(option) + ": the scene does not tessellate (tessellation.enabled is false): "
                      "there are no patches to name");
  };
  if (scene.shaders.program == ShaderProgram::Builtin && !scene.tessellation.enabled) throw no_patches();
  refuse_geometry_shaders(scene, option);
  Framebuffer tagged_fb;
  tagged_fb.reset(scene.width, scene.height, scene.background, parallel);
  bool tessellated = false;
  RasterState state;
  state.cull_back_faces = scene.cull_back_faces;
  state.polygon_mode = scene.polygon_mode;
  state.depth_test = redraw.depth_test;
  DrawOptions options;
  options.tess_surface = [&](const std::vector<TessDumpRecord>& records, const TriangleBatch& batch) {
    tessellated = true;
    draw_triangles(tagged_triangles(records, batch), state, *redraw.fs, tagged_fb, parallel);
    if (redraw.after_chunk) redraw.after_chunk();
  };
  const DrawStats stats = render_scene(scene, mesh, parallel, fb, options);
  if (!tessellated && stats.triangles_generated > 0) throw no_patches();
  return stats;
}

}  // namespace tessref
