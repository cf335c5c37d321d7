#include "glref/render_target.h"

#include <epoxy/gl.h>

#include "glref/gl_context.h"
#include "glref/gl_error.h"

#include <algorithm>
#include <cstdio>

#include "common/fixed_point.h"

namespace tessref::glref {

namespace {

GLenum gl_internal_format(ColorFormat f) {
  switch (f) {
    case ColorFormat::kRgba32F: return GL_RGBA32F;
    case ColorFormat::kRgba16F: return GL_RGBA16F;
    case ColorFormat::kRgba8: return GL_RGBA8;
    case ColorFormat::kSrgb8Alpha8: return GL_SRGB8_ALPHA8;
  }
  return GL_RGBA32F;
}

// Reads color attachment `attachment` of the bound FBO as RGBA of `type`, rows bottom first.
template <typename Pixel>
std::vector<Pixel> read_color(int width, int height, int attachment, GLenum type, const char* what) {
  std::vector<Pixel> out(static_cast<std::size_t>(width) * height);
  glReadBuffer(GL_COLOR_ATTACHMENT0 + attachment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, type, out.data());
  check_gl(what);
  return out;
}

}  // namespace

RenderTarget::RenderTarget(GlContext& context, const RenderTargetDesc& desc)
    : context_(context), desc_(desc) {
  context_.make_current();
  GLint max_size = 0, max_colors = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &max_colors);
  if (desc.width <= 0 || desc.height <= 0 || desc.width > max_size || desc.height > max_size)
    throw GlError("RenderTarget: size " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                  " outside 1.." + std::to_string(max_size));
  if (desc.colors.empty() || static_cast<GLint>(desc.colors.size()) > max_colors)
    throw GlError("RenderTarget: " + std::to_string(desc.colors.size()) + " color attachments, 1.." +
                  std::to_string(max_colors) + " supported");

  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  color_textures_.resize(desc.colors.size());
  glGenTextures(static_cast<GLsizei>(color_textures_.size()), color_textures_.data());
  std::vector<GLenum> draw_buffers;
  for (std::size_t i = 0; i < desc.colors.size(); ++i) {
    glBindTexture(GL_TEXTURE_2D, color_textures_[i]);
    glTexStorage2D(GL_TEXTURE_2D, 1, gl_internal_format(desc.colors[i]), desc.width, desc.height);
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, color_textures_[i], 0);
    draw_buffers.push_back(attachment);
  }
  glDrawBuffers(static_cast<GLsizei>(draw_buffers.size()), draw_buffers.data());
  if (desc.depth) {
    glGenTextures(1, &depth_texture_);
    glBindTexture(GL_TEXTURE_2D, depth_texture_);
    glTexStorage2D(GL_TEXTURE_2D, 1, desc.depth24 ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT32F,
                   desc.width, desc.height);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_texture_, 0);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%x", status);
    release();
    throw GlError(std::string("RenderTarget: framebuffer incomplete, status ") + buf);
  }
  check_gl("RenderTarget: creating the framebuffer");
}

RenderTarget::~RenderTarget() { release(); }

void RenderTarget::release() noexcept {
  if (!fbo_) return;
  GLint bound = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  const bool was_bound = static_cast<unsigned>(bound) == fbo_;
  glDeleteFramebuffers(1, &fbo_);
  if (!color_textures_.empty())
    glDeleteTextures(static_cast<GLsizei>(color_textures_.size()), color_textures_.data());
  if (depth_texture_) glDeleteTextures(1, &depth_texture_);
  fbo_ = depth_texture_ = 0;
  color_textures_.clear();
  // Surfaceless: never leave the context without a framebuffer.
  if (was_bound) context_.bind_default_framebuffer();
}

void RenderTarget::bind() {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, desc_.width, desc_.height);
}

void RenderTarget::clear(const glm::vec4& color, float depth) {
  bind();
  for (std::size_t i = 0; i < color_textures_.size(); ++i)
    glClearBufferfv(GL_COLOR, static_cast<GLint>(i), &color[0]);
  if (desc_.depth) glClearBufferfv(GL_DEPTH, 0, &depth);
  check_gl("RenderTarget::clear");
}

void RenderTarget::upload_color(const std::vector<glm::vec4>& pixels, int attachment) {
  check_attachment(attachment);
  if (pixels.size() != std::size_t(desc_.width) * std::size_t(desc_.height))
    throw GlError("RenderTarget::upload_color: the image is not the target's size");
  glBindTexture(GL_TEXTURE_2D, color_textures_[std::size_t(attachment)]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (is_fixed_point(desc_.colors[std::size_t(attachment)])) {
    std::vector<glm::u8vec4> bytes(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i)
      for (int c = 0; c < 4; ++c) bytes[i][c] = fixed::unorm8_from_float(pixels[i][c]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, desc_.width, desc_.height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, desc_.width, desc_.height, GL_RGBA, GL_FLOAT, pixels.data());
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  check_gl("RenderTarget::upload_color");
}

void RenderTarget::upload_depth(const std::vector<float>& depth) {
  if (!desc_.depth) throw GlError("RenderTarget::upload_depth: the target has no depth buffer");
  if (depth.size() != std::size_t(desc_.width) * std::size_t(desc_.height))
    throw GlError("RenderTarget::upload_depth: the image is not the target's size");
  glBindTexture(GL_TEXTURE_2D, depth_texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (desc_.depth24) {  // GL_UNSIGNED_INT depth is k / (2^32 - 1): the 24-bit k in the high bits, repeated low
    std::vector<std::uint32_t> words(depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i) {
      const std::uint32_t k = fixed::depth24_from_float(depth[i]);
      words[i] = (k << 8) | (k >> 16);
    }
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, desc_.width, desc_.height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, words.data());
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, desc_.width, desc_.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  check_gl("RenderTarget::upload_depth");
}

void RenderTarget::check_attachment(int attachment) const {
  if (attachment < 0 || attachment >= static_cast<int>(color_textures_.size()))
    throw GlError("RenderTarget: no color attachment " + std::to_string(attachment));
}


std::vector<glm::u8vec4> RenderTarget::read_rgba8(int attachment) {
  check_attachment(attachment);
  bind();
  return read_color<glm::u8vec4>(desc_.width, desc_.height, attachment, GL_UNSIGNED_BYTE,
                                 "RenderTarget::read_rgba8");
}

std::vector<glm::vec4> RenderTarget::read_rgba_float(int attachment) {
  check_attachment(attachment);
  bind();
  return read_color<glm::vec4>(desc_.width, desc_.height, attachment, GL_FLOAT,
                               "RenderTarget::read_rgba_float");
}

std::vector<float> RenderTarget::read_depth() {
  if (!desc_.depth) throw GlError("RenderTarget: no depth attachment");
  bind();
  std::vector<float> out(static_cast<std::size_t>(desc_.width) * desc_.height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, desc_.width, desc_.height, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
  check_gl("RenderTarget::read_depth");
  return out;
}

Framebuffer RenderTarget::to_framebuffer() {
  Framebuffer fb(desc_.width, desc_.height);
  fb.depth = desc_.depth ? read_depth()
                         : std::vector<float>(static_cast<std::size_t>(desc_.width) * desc_.height, 1.0f);
  if (desc_.depth24)  // GL_FLOAT readback of a 24-bit k is k / (2^24 - 1) in float: tessref's form
    for (float& z : fb.depth) z = fixed::quantize_depth24(z);
  fb.depth_format = desc_.depth24 ? DepthFormat::k24 : DepthFormat::k32F;
  fb.set_draw_buffers(std::max<int>(2, int(color_textures_.size())));
  for (int k = 0; k < int(color_textures_.size()); ++k) {
    fb.color_format[std::size_t(k)] = desc_.colors[std::size_t(k)];
    std::vector<glm::vec4>& b = *fb.draw_buffer(k);
    if (is_fixed_point(desc_.colors[std::size_t(k)])) {  // the bytes as stored (sRGB not decoded)
      const std::vector<glm::u8vec4> bytes = read_rgba8(k);
      for (std::size_t i = 0; i < bytes.size(); ++i)
        for (int c = 0; c < 4; ++c) b[i][c] = fixed::unorm8_to_float(bytes[i][c]);
    } else {
      b = read_rgba_float(k);
    }
  }
  return fb;
}

}  // namespace tessref::glref
