#pragma once
// A scene's GL draws (Scene::draws) issued to the driver as an application would: one buffer
// object per scene buffer, a vertex array object per draw, the state and the glDraw* calls, in
// order. What tessref draws from the same scene (pipeline/draw_scene.h) is compared against it.
#include <vector>

#include "draw/vertex_fetch.h"
#include "pipeline/scene.h"

namespace tessref::glref {

class GlDraws {
 public:
  // The context must be current; `program` linked from the scene's shaders. GlError for a
  // vertex input name the program does not have.
  GlDraws(const Scene& scene, const std::vector<draw::Buffer>& buffers, unsigned program);
  ~GlDraws();
  GlDraws(const GlDraws&) = delete;
  GlDraws& operator=(const GlDraws&) = delete;

  // Every draw into the bound framebuffer, with the program in use; the state is left as GL's
  // defaults afterwards (depth test and culling off).
  void draw() const;

 private:
  const Scene& scene_;
  std::vector<unsigned> buffers_;
  std::vector<unsigned> vaos_;  // one per draw
  std::vector<std::vector<std::pair<std::uint32_t, draw::VertexArray>>> current_;  // disabled arrays per draw
};

}  // namespace tessref::glref
