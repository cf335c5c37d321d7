#pragma once
// A scene's GL draws (Scene::draws) issued to the driver as an application would: one buffer
// object per scene buffer, a vertex array object per draw, the state and the glDraw* calls, in
// order. What tessref draws from the same scene (render/draw_scene.h) is compared against it.
#include <cstdint>
#include <functional>
#include <vector>

#include "draw/vertex_fetch.h"
#include "glref/gl_textures.h"
#include "scene/scene.h"

namespace tessref::glref {

class GlDraws {
 public:
  // The context must be current; programs[i] is the linked program of scene.draws[i] (with its
  // uniforms set), textures[i] its textures (bound before the draw). GlError for a vertex input
  // name the program does not have.
  GlDraws(const Scene& scene, const std::vector<draw::Buffer>& buffers, std::vector<unsigned> programs,
          std::vector<const GlTextures*> textures);
  ~GlDraws();
  GlDraws(const GlDraws&) = delete;
  GlDraws& operator=(const GlDraws&) = delete;

  // Every draw into the bound framebuffer, each with its program and state; the state is left as
  // GL's defaults afterwards (depth test and culling off, program 0). around(d, true) runs after
  // draw d's state is bound and its clear done, around(d, false) after its calls (transform
  // feedback begins and ends there).
  void draw(const std::function<void(std::size_t, bool)>& around = {}) const;

  // Draw d one instance at a time with `program` (linked with the same vertex input locations as
  // the draw's own), for transform feedback: bind(d, program), then draw_instance(d, call, k) for
  // each instance k of each call (drawn as instance count 1, its instanced arrays' pointers
  // advanced to the elements instance k reads; what stands in for gl_InstanceID is the
  // caller's), then unbind(), which leaves the state as draw() does.
  void bind(std::size_t d, unsigned program) const;  // program, textures, arrays, state
  void draw_instance(std::size_t d, std::size_t call, std::uint32_t instance) const;
  void unbind() const;

 private:
  const Scene& scene_;
  std::vector<unsigned> programs_;  // per draw
  std::vector<const GlTextures*> textures_;  // per draw
  std::vector<unsigned> buffers_;
  std::vector<std::size_t> buffer_sizes_;
  std::vector<unsigned> vaos_;  // one per draw
  std::vector<std::vector<std::pair<std::uint32_t, draw::VertexArray>>> current_;  // disabled arrays per draw
  std::vector<std::vector<std::pair<std::uint32_t, draw::VertexArray>>> instanced_;  // divisor > 0, per draw
};

}  // namespace tessref::glref
