#include "glref/gl_textures.h"

#include <epoxy/gl.h>

#include "glref/gl_error.h"
#include "render/buffer_load.h"
#include "render/texture_load.h"

namespace tessref::glref {
namespace {

using texture::ChannelType;
using texture::Filter;
using texture::Wrap;

GLint gl_wrap(Wrap w) {
  switch (w) {
    case Wrap::Repeat: return GL_REPEAT;
    case Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case Wrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case Wrap::ClampToBorder: return GL_CLAMP_TO_BORDER;
    case Wrap::MirrorClampToEdge: return GL_MIRROR_CLAMP_TO_EDGE;
  }
  return GL_REPEAT;
}

GLint gl_filter(Filter f) {
  switch (f) {
    case Filter::Nearest: return GL_NEAREST;
    case Filter::Linear: return GL_LINEAR;
    case Filter::NearestMipmapNearest: return GL_NEAREST_MIPMAP_NEAREST;
    case Filter::LinearMipmapNearest: return GL_LINEAR_MIPMAP_NEAREST;
    case Filter::NearestMipmapLinear: return GL_NEAREST_MIPMAP_LINEAR;
    case Filter::LinearMipmapLinear: return GL_LINEAR_MIPMAP_LINEAR;
  }
  return GL_LINEAR;
}

GLint gl_swizzle(texture::Swizzle s) {
  switch (s) {
    case texture::Swizzle::Red: return GL_RED;
    case texture::Swizzle::Green: return GL_GREEN;
    case texture::Swizzle::Blue: return GL_BLUE;
    case texture::Swizzle::Alpha: return GL_ALPHA;
    case texture::Swizzle::Zero: return GL_ZERO;
    case texture::Swizzle::One: return GL_ONE;
  }
  return GL_RED;
}

// One callable of several lambdas, chosen by argument type.
template <class... F>
struct Overloads : F... {
  using F::operator()...;
};
template <class... F>
Overloads(F...) -> Overloads<F...>;

struct GlFormat {
  GLenum internal, format, type;
};

GlFormat gl_format(texture::TexelFormat f) {
  using TF = texture::TexelFormat;
  const texture::TexelFormatInfo& fi = texture::info(f);
  static constexpr GLenum kByChannels[4] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
  static constexpr GLenum kIntegerByChannels[4] = {GL_RED_INTEGER, GL_RG_INTEGER, GL_RGB_INTEGER, GL_RGBA_INTEGER};
  const GLenum format = (fi.integer() ? kIntegerByChannels : kByChannels)[fi.channels - 1];
  GLenum type = GL_UNSIGNED_BYTE;
  switch (fi.type) {
    case ChannelType::kFloat32: type = GL_FLOAT; break;
    case ChannelType::kFloat16: type = GL_HALF_FLOAT; break;
    case ChannelType::kUnorm16: case ChannelType::kUint16: type = GL_UNSIGNED_SHORT; break;
    case ChannelType::kSnorm16: case ChannelType::kSint16: type = GL_SHORT; break;
    case ChannelType::kSnorm8: case ChannelType::kSint8: type = GL_BYTE; break;
    case ChannelType::kSint32: type = GL_INT; break;
    case ChannelType::kUint32: type = GL_UNSIGNED_INT; break;
    default: break;
  }
  switch (f) {
    case TF::kRgba32F: return {GL_RGBA32F, format, type};
    case TF::kRgb32F: return {GL_RGB32F, format, type};
    case TF::kRg32F: return {GL_RG32F, format, type};
    case TF::kR32F: return {GL_R32F, format, type};
    case TF::kRgba16F: return {GL_RGBA16F, format, type};
    case TF::kRg16F: return {GL_RG16F, format, type};
    case TF::kR16F: return {GL_R16F, format, type};
    case TF::kRgba8: return {GL_RGBA8, format, type};
    case TF::kRgb8: return {GL_RGB8, format, type};
    case TF::kRg8: return {GL_RG8, format, type};
    case TF::kR8: return {GL_R8, format, type};
    case TF::kSrgb8Alpha8: return {GL_SRGB8_ALPHA8, format, type};
    case TF::kSrgb8: return {GL_SRGB8, format, type};
    case TF::kRgba16: return {GL_RGBA16, format, type};
    case TF::kRgb16: return {GL_RGB16, format, type};
    case TF::kRg16: return {GL_RG16, format, type};
    case TF::kR16: return {GL_R16, format, type};
    case TF::kRgba16Snorm: return {GL_RGBA16_SNORM, format, type};
    case TF::kRgb16Snorm: return {GL_RGB16_SNORM, format, type};
    case TF::kRg16Snorm: return {GL_RG16_SNORM, format, type};
    case TF::kR16Snorm: return {GL_R16_SNORM, format, type};
    case TF::kRgba8Snorm: return {GL_RGBA8_SNORM, format, type};
    case TF::kRgb8Snorm: return {GL_RGB8_SNORM, format, type};
    case TF::kRg8Snorm: return {GL_RG8_SNORM, format, type};
    case TF::kR8Snorm: return {GL_R8_SNORM, format, type};
    case TF::kR11fG11fB10f: return {GL_R11F_G11F_B10F, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV};
    case TF::kRgb9E5: return {GL_RGB9_E5, GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV};
    case TF::kRgba8I: return {GL_RGBA8I, format, type};
    case TF::kRgb8I: return {GL_RGB8I, format, type};
    case TF::kRg8I: return {GL_RG8I, format, type};
    case TF::kR8I: return {GL_R8I, format, type};
    case TF::kRgba8Ui: return {GL_RGBA8UI, format, type};
    case TF::kRgb8Ui: return {GL_RGB8UI, format, type};
    case TF::kRg8Ui: return {GL_RG8UI, format, type};
    case TF::kR8Ui: return {GL_R8UI, format, type};
    case TF::kRgba16I: return {GL_RGBA16I, format, type};
    case TF::kRgb16I: return {GL_RGB16I, format, type};
    case TF::kRg16I: return {GL_RG16I, format, type};
    case TF::kR16I: return {GL_R16I, format, type};
    case TF::kRgba16Ui: return {GL_RGBA16UI, format, type};
    case TF::kRgb16Ui: return {GL_RGB16UI, format, type};
    case TF::kRg16Ui: return {GL_RG16UI, format, type};
    case TF::kR16Ui: return {GL_R16UI, format, type};
    case TF::kRgba32I: return {GL_RGBA32I, format, type};
    case TF::kRgb32I: return {GL_RGB32I, format, type};
    case TF::kRg32I: return {GL_RG32I, format, type};
    case TF::kR32I: return {GL_R32I, format, type};
    case TF::kRgba32Ui: return {GL_RGBA32UI, format, type};
    case TF::kRgb32Ui: return {GL_RGB32UI, format, type};
    case TF::kRg32Ui: return {GL_RG32UI, format, type};
    case TF::kR32Ui: return {GL_R32UI, format, type};
    case TF::kRgb10A2Ui: return {GL_RGB10_A2UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT_2_10_10_10_REV};
    // The stored words as tessref wrote them (texture/texel_format.h): no conversion on upload.
    case TF::kDepth16: return {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT};
    case TF::kDepth24: return {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT};
    case TF::kDepth32F: return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT};
    case TF::kDepth24Stencil8: return {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
  }
  return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
}

// glTexParameter or glSamplerParameter of every sampler state value, through `i`, `f` and
// `border` (the parameter's fv, Iiv or Iuiv form, as GLfloat*, GLint* or GLuint*): the border
// colour as integers for an integer format.
template <class SetI, class SetF, class SetBorder>
void set_sampler_state(const texture::SamplerState& s, texture::TexelFormat format, SetI i, SetF f, SetBorder border) {
  i(GL_TEXTURE_MIN_FILTER, gl_filter(s.min_filter));
  i(GL_TEXTURE_MAG_FILTER, gl_filter(s.mag_filter));
  i(GL_TEXTURE_WRAP_S, gl_wrap(s.wrap_s));
  i(GL_TEXTURE_WRAP_T, gl_wrap(s.wrap_t));
  i(GL_TEXTURE_WRAP_R, gl_wrap(s.wrap_r));
  const texture::TexelFormatInfo& fi = texture::info(format);
  GLint ints[4];
  GLuint uints[4];
  for (int c = 0; c < 4; ++c) {
    ints[c] = GLint(s.border_integer[std::size_t(c)]);
    uints[c] = GLuint(s.border_integer[std::size_t(c)]);
  }
  if (fi.signed_integer()) border(ints);
  else if (fi.unsigned_integer()) border(uints);
  else border(s.border.data());
  f(GL_TEXTURE_MIN_LOD, s.min_lod);
  f(GL_TEXTURE_MAX_LOD, s.max_lod);
  f(GL_TEXTURE_LOD_BIAS, s.lod_bias);
  i(GL_TEXTURE_COMPARE_MODE, s.compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
  static constexpr GLint kFuncs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  i(GL_TEXTURE_COMPARE_FUNC, kFuncs[int(s.compare_func)]);
}

GLenum gl_target(texture::Target t) {
  switch (t) {
    case texture::Target::k1D: return GL_TEXTURE_1D;
    case texture::Target::k2D: return GL_TEXTURE_2D;
    case texture::Target::k1DArray: return GL_TEXTURE_1D_ARRAY;
    case texture::Target::k2DArray: return GL_TEXTURE_2D_ARRAY;
    case texture::Target::kBuffer: return GL_TEXTURE_BUFFER;
    case texture::Target::k3D: return GL_TEXTURE_3D;
    case texture::Target::kRectangle: return GL_TEXTURE_RECTANGLE;
    case texture::Target::kCube: return GL_TEXTURE_CUBE_MAP;
    case texture::Target::kCubeArray: return GL_TEXTURE_CUBE_MAP_ARRAY;
  }
  return GL_TEXTURE_2D;
}

}  // namespace

GlTextures::GlTextures(const Scene& scene, const ShaderSettings& shaders) : shaders_(shaders) {
  ids_.resize(shaders.textures.size());
  targets_.assign(shaders.textures.size(), GL_TEXTURE_2D);
  samplers_.assign(shaders.textures.size(), 0u);
  if (ids_.empty()) return;
  glGenTextures(GLsizei(ids_.size()), ids_.data());
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    const TextureSetting& t = shaders.textures[k];
    const texture::Texture tex = load_texture(t, scene.source + ": " + shaders.key + ".textures." + t.sampler, scene);
    const GlFormat f = gl_format(tex.format);
    const texture::Level& level0 = tex.levels[0];
    const GLenum target = gl_target(tex.target);
    targets_[k] = target;
    glBindTexture(target, ids_[k]);
    if (tex.target == texture::Target::kBuffer) {
      // The buffer object as the application made it (load_texture checked the name and range), and
      // the range the scene names.
      const draw::Buffer source = load_buffer(scene.source, find_buffer(scene, t.buffer, t.buffer));
      GLuint buffer = 0;
      glGenBuffers(1, &buffer);
      buffers_.push_back(buffer);
      glBindBuffer(GL_TEXTURE_BUFFER, buffer);
      glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(source.bytes.size()), source.bytes.data(), GL_STATIC_DRAW);
      glBindBuffer(GL_TEXTURE_BUFFER, 0);
      glTexBufferRange(GL_TEXTURE_BUFFER, f.internal, buffer, GLintptr(t.buffer_offset),
                       GLsizeiptr(t.buffer_size.value_or(source.bytes.size() - t.buffer_offset)));
      continue;
    }
    // glTexStorage*: the levels given, or every level down to 1 (x 1) for glGenerateMipmap.
    const int given = t.layers.empty() ? int(t.levels.size()) : 1;
    const bool three_d = tex.target == texture::Target::k3D;
    const int all = texture::last_mip_level(0, level0.width, level0.height, three_d ? level0.layers : 1) + 1;
    const int levels = t.generate_mipmaps ? all : given;
    switch (tex.target) {
      case texture::Target::k1D: glTexStorage1D(target, levels, f.internal, level0.width); break;
      case texture::Target::k1DArray: glTexStorage2D(target, levels, f.internal, level0.width, level0.layers); break;
      case texture::Target::k2DArray: case texture::Target::k3D: case texture::Target::kCubeArray:
        glTexStorage3D(target, levels, f.internal, level0.width, level0.height, level0.layers);
        break;
      default: glTexStorage2D(target, levels, f.internal, level0.width, level0.height); break;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int l = 0; l < given; ++l) {
      const texture::Level& level = tex.levels[std::size_t(l)];
      const void* bytes = level.stored.data();
      switch (tex.target) {
        case texture::Target::k1D: glTexSubImage1D(target, l, 0, level.width, f.format, f.type, bytes); break;
        case texture::Target::k1DArray:  // the layers are the image's rows
          glTexSubImage2D(target, l, 0, 0, level.width, level.layers, f.format, f.type, bytes);
          break;
        case texture::Target::k2DArray: case texture::Target::k3D: case texture::Target::kCubeArray:
          glTexSubImage3D(target, l, 0, 0, 0, level.width, level.height, level.layers, f.format, f.type, bytes);
          break;
        case texture::Target::kCube:  // face by face, +X to -Z (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face)
          for (int face = 0; face < 6; ++face)
            glTexSubImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), l, 0, 0, level.width, level.height, f.format,
                            f.type, level.stored.data() + std::size_t(face) * (level.stored.size() / 6));
          break;
        default: glTexSubImage2D(target, l, 0, 0, level.width, level.height, f.format, f.type, bytes); break;
      }
    }
    // glGenerateMipmap right after the upload, with the initial base and max level: every level.
    if (t.generate_mipmaps) glGenerateMipmap(target);
    if (tex.target != texture::Target::kRectangle) {  // a rectangle texture has level 0 alone
      glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, tex.base_level);
      glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, tex.max_level);
    }
    // The texture's own sampler state; a sampler object's, when the scene binds one, overrides it.
    set_sampler_state(t.sampler_state, tex.format, [target](GLenum p, GLint v) { glTexParameteri(target, p, v); },
                      [target](GLenum p, GLfloat v) { glTexParameterf(target, p, v); },
                      Overloads{[target](const GLfloat* c) { glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, c); },
                                [target](const GLint* c) { glTexParameterIiv(target, GL_TEXTURE_BORDER_COLOR, c); },
                                [target](const GLuint* c) { glTexParameterIuiv(target, GL_TEXTURE_BORDER_COLOR, c); }});
    const GLint swizzle[4] = {gl_swizzle(tex.swizzle[0]), gl_swizzle(tex.swizzle[1]), gl_swizzle(tex.swizzle[2]),
                              gl_swizzle(tex.swizzle[3])};
    glTexParameteriv(target, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    if (t.sampler_object) {
      GLuint sampler = 0;
      glGenSamplers(1, &sampler);
      samplers_[k] = sampler;
      set_sampler_state(*t.sampler_object, tex.format, [sampler](GLenum p, GLint v) { glSamplerParameteri(sampler, p, v); },
                        [sampler](GLenum p, GLfloat v) { glSamplerParameterf(sampler, p, v); },
                        Overloads{[sampler](const GLfloat* c) { glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, c); },
                                  [sampler](const GLint* c) { glSamplerParameterIiv(sampler, GL_TEXTURE_BORDER_COLOR, c); },
                                  [sampler](const GLuint* c) { glSamplerParameterIuiv(sampler, GL_TEXTURE_BORDER_COLOR, c); }});
    }
  }
  for (const unsigned target : targets_) glBindTexture(target, 0);
  check_gl("GlTextures: uploading shaders.textures");
}

GlTextures::~GlTextures() {
  if (!ids_.empty()) glDeleteTextures(GLsizei(ids_.size()), ids_.data());
  if (!buffers_.empty()) glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
  for (unsigned sampler : samplers_)
    if (sampler) glDeleteSamplers(1, &sampler);
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
    glBindTexture(targets_[k], ids_[k]);
    glBindSampler(GLuint(k), samplers_[k]);
  }
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace tessref::glref
