#include "render/draw.h"

#include "mesh/vertex_tags.h"
#include "render/builtin_program.h"
#include "render/draw_call.h"

namespace tessref {

DrawStats draw_mesh(const Mesh& mesh, const programs::TransformVertexShader& vertex_shader,
                    const TessellationSettings& tessellation, const RasterState& raster_state,
                    const FragmentProgram& fragment_shader, Framebuffer& fb,
                    const Parallel& parallel, const DrawOptions& options) {
  std::vector<VertexTags> tags;
  if (tessellation.enabled && tessellation.scheme == SurfaceScheme::ScalarTaggedPN)
    tags = load_vertex_tags(tessellation, mesh);
  const BuiltinProgram program(vertex_shader, tessellation, glm::vec2(float(fb.width), float(fb.height)),
                               fragment_shader, std::move(tags));
  DrawCall call;
  call.indices = mesh.indices;
  call.vertex_count = mesh.vertex_count();
  call.patches = tessellation.enabled;
  call.patch_vertices = 3;
  return run_draw(program, mesh_attributes(mesh), call, raster_state, fb, parallel, options);
}

}  // namespace tessref
