#pragma once
// A program's shaders.textures as GL textures, on the units tessref binds them to: texture k of
// the list on unit k, its sampler uniform set to k; the same texels (render/glsl_scene.h,
// load_texture) uploaded as GL_RGBA32F, level 0 only, with the scene's filter and wrap.
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
  // Binds every texture to its unit, before a draw.
  void bind() const;

 private:
  const ShaderSettings& shaders_;
  std::vector<unsigned> ids_;
};

}  // namespace tessref::glref
