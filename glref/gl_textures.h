#pragma once
// A program's shaders.textures as GL textures, on the units tessref binds them to: texture k of
// the list on unit k, its sampler uniform set to k. Each is created as an application would:
// glTexStorage* with its internal format and every level it has, glTexSubImage* with the bytes
// tessref stored (render/texture_load.h) per level given, glGenerateMipmap when the scene asks for
// it, then the scene's glTexParameter state; a buffer texture as a buffer object with the scene
// buffer's bytes and glTexBufferRange.
#include <vector>

#include "scene/scene.h"

namespace tessref::glref {

class GlTextures {
 public:
  // The context must be current. InputError for an image that cannot be read.
  GlTextures(const Scene& scene, const ShaderSettings& shaders);
  ~GlTextures();
  GlTextures(const GlTextures&) = delete;
  GlTextures& operator=(const GlTextures&) = delete;

  // Sets the program's sampler uniforms to their units (after linking, the program in use).
  void set_samplers(unsigned program) const;
  // Binds every texture (and sampler object) to its unit, before a draw.
  void bind() const;

 private:
  const ShaderSettings& shaders_;
  std::vector<unsigned> ids_;
  std::vector<unsigned> samplers_;  // a sampler object per unit, 0 for none
  std::vector<unsigned> targets_;   // each unit's target (GL_TEXTURE_2D, ...)
  std::vector<unsigned> buffers_;   // the buffer objects of buffer textures
};

}  // namespace tessref::glref
