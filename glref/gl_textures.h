#pragma once
// A program's shaders.textures as GL textures, on the units tessref binds them to: texture k of
// the list on unit k, its sampler uniform set to k. Each is created as an application would:
// glTexStorage2D with its internal format and every level it has, glTexSubImage2D with the bytes
// tessref stored (render/glsl_scene.h, load_texture) per level given, glGenerateMipmap when the
// scene asks for it, then the scene's glTexParameter state.
#include <vector>

#include "scene/scene.h"

namespace tessref::glref {

class GlTextures {
 public:
  // The context must be current. InputError for an image that cannot be read.
  GlTextures(const std::string& scene_source, const ShaderSettings& shaders);
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
  std::vector<unsigned> targets_;   // GL_TEXTURE_2D or GL_TEXTURE_2D_ARRAY per unit
};

}  // namespace tessref::glref
