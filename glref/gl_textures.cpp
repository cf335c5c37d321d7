#include "glref/gl_textures.h"

#include <epoxy/gl.h>

#include "glref/gl_error.h"
#include "render/glsl_scene.h"

namespace tessref::glref {
namespace {

GLint gl_wrap(shader::Texture::Wrap w) {
  switch (w) {
    case shader::Texture::Wrap::Repeat: return GL_REPEAT;
    case shader::Texture::Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    default: return GL_CLAMP_TO_EDGE;
  }
}

}  // namespace

GlTextures::GlTextures(const std::string& scene_source, const ShaderSettings& shaders) : shaders_(shaders) {
  ids_.resize(shaders.textures.size());
  if (ids_.empty()) return;
  glGenTextures(GLsizei(ids_.size()), ids_.data());
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    const TextureSetting& t = shaders.textures[k];
    const shader::Texture tex = load_texture(t, scene_source + ": " + shaders.key + ".textures." + t.sampler);
    glBindTexture(GL_TEXTURE_2D, ids_[k]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, tex.width, tex.height, 0, GL_RGBA, GL_FLOAT, tex.texels.data());
    const GLint filter = tex.linear ? GL_LINEAR : GL_NEAREST;  // no mipmaps: level 0 only
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap(tex.wrap_s));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap(tex.wrap_t));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  check_gl("GlTextures: uploading shaders.textures");
}

GlTextures::~GlTextures() {
  if (!ids_.empty()) glDeleteTextures(GLsizei(ids_.size()), ids_.data());
}

void GlTextures::set_samplers(unsigned program) const {
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    const GLint location = glGetUniformLocation(program, shaders_.textures[k].sampler.c_str());
    if (location >= 0) glProgramUniform1i(program, location, GLint(k));
  }
  check_gl("GlTextures: setting the samplers");
}

void GlTextures::bind() const {
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    glActiveTexture(GLenum(GL_TEXTURE0 + k));
    glBindTexture(GL_TEXTURE_2D, ids_[k]);
  }
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace tessref::glref
