#include "render/render.h"

#include "render/builtin_program.h"
#include "mesh/camera.h"
#include "render/draw_scene.h"
#include "render/glsl_scene.h"
#include "render/initial_images.h"
#include "stages/programs/normals.h"
#include "stages/programs/phong.h"

namespace tessref {
namespace {

programs::PhongShader phong_shader(const Scene& scene) {
  programs::PhongShader fs;
  fs.u_eye = scene.camera.eye;
  fs.u_num_lights = static_cast<int>(scene.lights.size());
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    fs.u_light_position[i] = scene.lights[i].position;
    fs.u_light_intensity[i] = scene.lights[i].intensity;
  }
  fs.u_ka = scene.material.ka;
  fs.u_kd = scene.material.kd;
  fs.u_ks = scene.material.ks;
  fs.u_shininess = scene.material.shininess;
  fs.u_color = scene.material.color;
  return fs;
}

// The draws of a frame whose clear was deferred (Framebuffer::reset): then the tiles no draw
// touched are cleared, also when a draw throws.
template <class Draw>
DrawStats cleared_after(Framebuffer& fb, const Parallel& parallel, Draw&& draw) {
  try {
    DrawStats stats = draw();
    fb.finish_clear(parallel);
    return stats;
  } catch (...) {
    fb.finish_clear(parallel);
    throw;
  }
}

}  // namespace

BuiltinFragmentProgram builtin_fragment_program(const Scene& scene) {
  BuiltinFragmentProgram p;
  p.phong = phong_shader(scene);
  p.use_phong = scene.shading == Shading::Phong;
  return p;
}

programs::TransformVertexShader scene_vertex_shader(const Scene& scene) {
  const glm::mat4 view_projection =
      projection_matrix(scene.camera, scene.width, scene.height) * view_matrix(scene.camera);
  return programs::TransformVertexShader::from(model_matrix(scene.transform), view_projection);
}

RenderResult render_scene(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                          const DrawOptions& options) {
  RenderResult result;
  result.stats = render_scene(scene, mesh, parallel, result.framebuffer, options);
  return result;
}

DrawStats render_scene(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                       Framebuffer& fb, const DrawOptions& options, std::vector<FeedbackBuffers>* feedback,
                       DrawnMemory* memory) {
  if (!scene.draws.empty()) {
    fb.reset(scene.width, scene.height, scene.background, parallel);
    set_up_framebuffer(scene, load_initial_images(scene), fb);
    return draw_scene_draws(scene, fb, parallel, options, feedback, memory);
  }
  if (scene.shaders.program != ShaderProgram::Builtin) {
    const SceneProgram program = build_scene_program(scene);
    fb.reset(scene.width, scene.height, scene.background, parallel, options.normals, true);
    DrawStats stats = cleared_after(fb, parallel, [&] { return draw_glsl_scene(scene, *program.program, mesh, fb, parallel, options); });
    stats.warnings.insert(stats.warnings.end(), program.warnings.begin(), program.warnings.end());
    return stats;
  }
  const auto vs = scene_vertex_shader(scene);
  RasterState state;
  state.cull_back_faces = scene.cull_back_faces;
  state.polygon_mode = scene.polygon_mode;

  const BuiltinFragmentProgram program = builtin_fragment_program(scene);
  const FragmentProgram& fs = program.get();

  fb.reset(scene.width, scene.height, scene.background, parallel, options.normals, true);
  return cleared_after(fb, parallel, [&] { return draw_mesh(mesh, vs, scene.tessellation, state, fs, fb, parallel, options); });
}

std::optional<std::uint64_t> predicted_tes_invocations(const Scene& scene, const Mesh& mesh) {
  const TessellationSettings& t = scene.tessellation;
  if (!t.enabled || t.adaptive.enabled || scene.shaders.program != ShaderProgram::Builtin) return std::nullopt;
  const TessLayout layout{TessDomain::Triangles, t.spacing, t.winding, false};
  // Held by name: the pattern dies with the last shared_ptr to it.
  const std::shared_ptr<const TessPattern> pattern = make_pattern(layout, t.levels, TessProfile::llvmpipe(), t.tessellator);
  return std::uint64_t(mesh.triangle_count()) * (pattern->points.discarded ? 0 : pattern->points.coords.size());
}

}  // namespace tessref
