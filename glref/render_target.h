#pragma once
// An offscreen framebuffer object for the GL runner: color attachments plus a 32-bit float (or
// 24-bit) depth buffer, read back in tessref's convention (row 0 is the bottom row, as in GL window space).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "raster/framebuffer.h"

namespace tessref::glref {

class GlContext;


struct RenderTargetDesc {
  int width = 0;
  int height = 0;
  // One entry per color attachment (fragment output location i -> attachment i).
  std::vector<ColorFormat> colors = {ColorFormat::kRgba8};
  bool depth = true;
  // GL_DEPTH_COMPONENT24 instead of GL_DEPTH_COMPONENT32F: what an application that wants only an
  // 8-bit image asks for (the fair benchmark's target).
  bool depth24 = false;
};

class RenderTarget {
 public:
  // Throws GlError if the size exceeds GL_MAX_RENDERBUFFER_SIZE or the FBO is incomplete.
  RenderTarget(GlContext& context, const RenderTargetDesc& desc);
  ~RenderTarget();  // rebinds the context's default FBO if this one is bound
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // Binds the FBO for drawing and reading and sets the viewport to the whole target.
  void bind();
  // Clears every color attachment to `color` and depth to `depth`.
  void clear(const glm::vec4& color, float depth = 1.0f);

  int width() const { return desc_.width; }
  int height() const { return desc_.height; }
  const RenderTargetDesc& desc() const { return desc_; }

  // Uploads width * height values, row 0 at the bottom, into colour attachment `attachment` or the
  // depth buffer: values the attachment's format holds exactly (raster/color_format.h), sent as
  // bytes to 8-bit formats (no sRGB encoding on the way) and as 24-bit integers to a 24-bit depth
  // buffer, so that no conversion of the driver's can round them.
  void upload_color(const std::vector<glm::vec4>& pixels, int attachment = 0);
  void upload_depth(const std::vector<float>& depth);

  // Readback, width * height values, row 0 at the bottom.
  std::vector<glm::u8vec4> read_rgba8(int attachment = 0);
  std::vector<glm::vec4> read_rgba_float(int attachment = 0);  // Rgba8 comes back as c / 255
  std::vector<float> read_depth();
  // Attachment 0 -> color, depth -> depth, attachment 1 (if any) -> aux, 2.. -> more: for comparing
  // with tessref's own framebuffer (with its formats).
  Framebuffer to_framebuffer();

 private:
  void check_attachment(int attachment) const;
  void release() noexcept;

  GlContext& context_;
  RenderTargetDesc desc_;
  unsigned fbo_ = 0;
  std::vector<unsigned> color_textures_;
  unsigned depth_texture_ = 0;
};

}  // namespace tessref::glref
