#pragma once
// A scene's GL draws (Scene::draws): the buffers loaded, each call's vertices pulled through its
// vertex arrays (draw/vertex_fetch.h), its primitives assembled and drawn with its GLSL program,
// in order, into one framebuffer.
#include <functional>
#include <vector>

#include "draw/vertex_fetch.h"
#include "render/buffer_load.h"
#include "render/draw_call.h"
#include "render/glsl_scene.h"
#include "scene/scene.h"

namespace tessref {

// Vertices per assembled primitive of an untessellated mode: 3, 2 (lines) or 1 (points).
int primitive_corners(DrawMode mode);

// The primitives' vertices for `mode`, as positions into the fetched vertices: each restarted run
// cut to whole primitives (GL ignores a partial last one), strips and fans as triangle lists in
// GL's vertex order (the last vertex of each triangle is GL's provoking vertex).
// Line strips and loops become line lists, points a point list.
std::vector<std::uint32_t> assemble(DrawMode mode, int patch_vertices,
                                    const std::vector<std::vector<std::uint32_t>>& runs);

// The patch ids a scene of draws gives its patches (DrawCall::first_patch_id): counted over
// the draws, their calls and instances in order, gl_PrimitiveID within an instance. For each draw,
// each call's first id and patches per instance (0 for an untessellated draw).
struct CallPatches {
  std::uint32_t first_patch = 0;
  std::uint32_t per_instance = 0;
  std::uint32_t instances = 0;
};
std::vector<std::vector<CallPatches>> patch_numbering(const Scene& scene, const std::vector<draw::Buffer>& buffers);

// One call of one draw, ready to run: its program with GL's state as it is at this call (the
// uniform buffers this draw and the earlier ones bound), the vertices' attributes and the call.
struct PreparedCall {
  std::size_t draw = 0, call_index = 0;  // Scene::draws[draw].calls[call_index]
  const DrawSetting& setting;
  glsl::GlslProgram& program;
  const std::vector<glsl::VertexAttribute>& attributes;  // per fetched vertex (call.vertex_ids)
  const DrawCall& call;
};

// A scene's draws with their buffers loaded and their programs compiled (all of them before the
// first draw, so that a broken one draws nothing): what render draws and inspect reruns.
class SceneDraws {
 public:
  explicit SceneDraws(const Scene& scene);  // InputError as load_buffers and build_scene_program
  ~SceneDraws();
  const std::vector<draw::Buffer>& buffers() const { return buffers_; }
  // The textures the programs bind as images, as DrawnMemory names them, with level 0's bytes.
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> images() const;
  // The GLSL sources of draw `draw`'s program (its own, or the scene's).
  std::vector<shader::ShaderSource> sources(std::size_t draw) const;
  // Calls fn for each call of draws [0, end), in order. The references fn receives live until
  // it returns. InputError naming the scene (and the draw's key for the stages' errors).
  void for_each_call(std::size_t end, const std::function<void(const PreparedCall&)>& fn);
  // What the programs' textures give a user reason to hear (incomplete ones).
  std::vector<std::string> warnings() const;

 private:
  const Scene& scene_;
  std::vector<draw::Buffer> buffers_;
  SceneProgram shared_;
  std::vector<SceneProgram> own_;
};

struct FeedbackBuffers;

// What a scene's draws leave besides the framebuffer: its buffers (what shaders wrote into storage
// blocks included) and the textures bound as images (level 0's stored bytes), after the frame.
struct DrawnMemory {
  std::vector<draw::Buffer> buffers;
  // ("NAME", or "drawD.NAME" for a draw's own shaders; NAME the image uniform's) and the bytes.
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> images;
};

// Draws every draw of the scene into fb (already cleared), each with its own program or the
// scene's. With `feedback`: appends what each draw with a transform_feedback key records
// (render/transform_feedback.h), in draw order. With `memory`: the buffers and images as the draws
// left them.
DrawStats draw_scene_draws(const Scene& scene, Framebuffer& fb, const Parallel& parallel, const DrawOptions& options,
                           std::vector<FeedbackBuffers>* feedback = nullptr, DrawnMemory* memory = nullptr);

}  // namespace tessref
