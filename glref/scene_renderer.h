#pragma once
// A tessref scene drawn by the GL driver with its GLSL: tessref's twins (stages/programs/*.vert/.frag,
// stages/schemes/*.tesc/.tese), or the user's files for shaders.program custom (their uniforms
// set by name, their inputs bound as shaders.attributes says; textures not yet), set up exactly as tessref::render_scene sets up the C++ programs:
// the same matrices (mesh/camera.h, so both sides upload the same floats), uniforms,
// tessellation (scheme, normal mode, spacing, winding, constant or adaptive levels), culling (back
// faces, CCW front), depth test (LESS), clear color and viewport. The result is read back into a
// tessref Framebuffer (row 0 at the bottom), ready to compare with tessref's own.
#include <cstddef>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "glref/draw_split.h"
#include "glref/gl_draws.h"
#include "glref/gl_textures.h"
#include "glref/gl_program.h"
#include "glref/render_target.h"
#include "io/image_output.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "raster/framebuffer.h"
#include "render/transform_feedback.h"

namespace tessref::glref {

class GlContext;
class PatchMesh;

struct SceneRendererOptions {
  // Rgba32F keeps the shader's floats, so both images are quantized by the same code
  // (io/image_output.h to_rgb8); Rgba8 lets the driver round.
  ColorFormat color = ColorFormat::kRgba32F;
  bool normals_attachment = true;  // fragment output 1 (world normal) -> Framebuffer::aux
  std::size_t max_points_per_draw = kSafePointsPerDraw;  // tessellated draws split under this
  bool depth24 = false;  // GL_DEPTH_COMPONENT24 instead of 32F
  // Compile the twins for this scene, as an application compiles its shaders for one setup: the
  // light count, normal mode, adaptive switch and displacement switch become constants (glsl_rewrite.h specialize_uniforms), so the driver folds the loops and branches
  // they drive. The image is the same; a user's own program (shaders.program custom) is left
  // as written.
  bool specialize = false;

  // llvmpipe at its best for an 8-bit image, the benchmarks' baseline: one RGBA8 attachment,
  // 24-bit depth, no normals target, the twins specialized (read back with read_back_rgba8).
  static SceneRendererOptions fair_rgba8() {
    SceneRendererOptions o;
    o.color = ColorFormat::kRgba8;
    o.normals_attachment = false;
    o.depth24 = true;
    o.specialize = true;
    return o;
  }
};

struct SceneRenderStats {
  std::size_t draws = 0;         // GL draw calls (a tessellated mesh is split, see draw_split.h)
  double draw_seconds = 0.0;     // clear + draw calls + glFinish
  double readback_seconds = 0.0; // glReadPixels of color, depth (and normals)
};

// One TES invocation's outputs as transform feedback records them (one record per emitted
// vertex, 3 per triangle, so shared domain points repeat).
struct TessOutputVertex {
  glm::vec3 position{0.0f};    // v_world_position
  glm::vec3 normal{0.0f};      // v_world_normal
  glm::vec3 tess_coord{0.0f};  // gl_TessCoord
  std::uint32_t patch = 0;     // mesh triangle index (draw base + gl_PrimitiveID)
};

// Owns the programs, the mesh's buffers and the render target for one scene; render() may be
// called repeatedly (a benchmark frame). Throws GlError on any GL failure.
class SceneRenderer {
 public:
  SceneRenderer(GlContext& context, const Scene& scene, const Mesh& mesh,
                const SceneRendererOptions& options = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Clears, draws and waits for the driver (glFinish): one complete frame, not read back.
  void draw();
  // Reads the target back: color, depth, and aux (normals, or 0 without that attachment).
  Framebuffer read_back();
  // Reads attachment 0 back as RGBA8 only (GL_UNSIGNED_BYTE, the driver converts), row 0 at the
  // bottom: what an application that writes an 8-bit image reads.
  std::vector<glm::u8vec4> read_back_rgba8();
  // draw() then read_back().
  Framebuffer render();

  // The tessellated mesh's TES outputs, patch by patch in mesh order (rasterizer discard, draws
  // split and checked). Throws GlError when the scene does not tessellate.
  std::vector<TessOutputVertex> capture_tess();

  // A scene of draws: what every tessellated draw's evaluation shader emits, one record per
  // emitted vertex in emission order (rasterizer discard, instances one at a time): gl_TessCoord,
  // gl_Position in TessDumpRecord::clip, and the patch id tessref gives the patch
  // (render/draw_scene.h patch_numbering). The user's stages are wrapped, not read
  // (glref/capture_wrap.h). GlError when the driver's stream cannot be told apart into patches.
  std::vector<TessDumpRecord> capture_draws_tess();

  // A scene of draws: one frame (draw()) with transform feedback active over each draw that has
  // draws[].transform_feedback, its program linked with those varyings; what each recorded, in
  // draw order (the same shape as tessref's render/transform_feedback.h). GlError when a buffer
  // of 64 MiB is too small or GL reports an error.
  std::vector<FeedbackBuffers> transform_feedback();

  const SceneRenderStats& last_stats() const { return stats_; }
  const glm::mat4& view_projection() const { return view_projection_; }

 private:
  void set_uniforms(const Program& program, const ShaderSettings& shaders) const;
  void set_user_uniform(const Program& program, const UniformSetting& u) const;

  GlContext& context_;
  Scene scene_;
  SceneRendererOptions options_;
  glm::mat4 model_{1.0f}, view_projection_{1.0f};
  std::vector<std::size_t> point_bounds_;  // per patch, for splitting tessellated draws
  Program program_;  // the scene's shaders (none when every draw has its own)
  std::vector<Program> draw_programs_;  // draws[].shaders, by draw (empty: the scene's)
  Program capture_program_;  // linked on first capture_tess()
  std::unique_ptr<PatchMesh> patches_;  // tessellation on
  std::unique_ptr<GlDraws> draws_;      // the scene's GL draws (Scene::draws), replacing the mesh
  std::unique_ptr<GlTextures> textures_;  // the scene program's shaders.textures
  std::vector<std::unique_ptr<GlTextures>> draw_textures_;  // each draw's own, by draw
  unsigned vao_ = 0, buffers_[3] = {0, 0, 0};  // tessellation off: plain GL_TRIANGLES
  std::size_t index_count_ = 0;
  std::unique_ptr<RenderTarget> target_;
  SceneRenderStats stats_;
  std::vector<FeedbackBuffers>* feedback_ = nullptr;  // set during transform_feedback()
};

// An RGBA8 read-back (row 0 at the bottom) as the 8-bit RGB image a PNG holds (top row first), to
// compare with tessref's to_rgb8 (io/image_compare.h compare_images).
Rgb8Image rgb8_top_first(const std::vector<glm::u8vec4>& bottom_first, int width, int height);

}  // namespace tessref::glref
