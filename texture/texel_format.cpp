#include "texture/texel_format.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>

#include "common/fixed_point.h"
#include "common/half_float.h"

namespace tessref::texture {
namespace {

struct Named {
  TexelFormat format;
  TexelFormatInfo info;
};

constexpr std::array<Named, 16> kFormats{{
    {TexelFormat::kRgba32F, {"GL_RGBA32F", 4, ChannelType::kFloat32}},
    {TexelFormat::kRg32F, {"GL_RG32F", 2, ChannelType::kFloat32}},
    {TexelFormat::kR32F, {"GL_R32F", 1, ChannelType::kFloat32}},
    {TexelFormat::kRgba16F, {"GL_RGBA16F", 4, ChannelType::kFloat16}},
    {TexelFormat::kRg16F, {"GL_RG16F", 2, ChannelType::kFloat16}},
    {TexelFormat::kR16F, {"GL_R16F", 1, ChannelType::kFloat16}},
    {TexelFormat::kRgba8, {"GL_RGBA8", 4, ChannelType::kUnorm8}},
    {TexelFormat::kRgb8, {"GL_RGB8", 3, ChannelType::kUnorm8}},
    {TexelFormat::kRg8, {"GL_RG8", 2, ChannelType::kUnorm8}},
    {TexelFormat::kR8, {"GL_R8", 1, ChannelType::kUnorm8}},
    {TexelFormat::kSrgb8Alpha8, {"GL_SRGB8_ALPHA8", 4, ChannelType::kSrgb8}},
    {TexelFormat::kSrgb8, {"GL_SRGB8", 3, ChannelType::kSrgb8}},
    {TexelFormat::kDepth16, {"GL_DEPTH_COMPONENT16", 1, ChannelType::kUnorm16, true}},
    {TexelFormat::kDepth24, {"GL_DEPTH_COMPONENT24", 1, ChannelType::kUnorm24, true}},
    {TexelFormat::kDepth32F, {"GL_DEPTH_COMPONENT32F", 1, ChannelType::kFloat32, true}},
    {TexelFormat::kDepth24Stencil8, {"GL_DEPTH24_STENCIL8", 1, ChannelType::kUnorm24, true}},
}};

// An sRGB channel as the sampler decodes it. GL 4.6 equation 8.17 is exact; llvmpipe
// (lp_build_srgb_to_linear) evaluates a linear segment up to k = 15 and a cubic above it, whose
// results differ from the equation in the last bits for all but 2 of the 256 values, so tessref
// evaluates the same cubic with the same constants and fused operations (256 of 256 measured).
float srgb8_texel_to_float(std::uint8_t k) {
  const float x = float(k);
  if (x <= 15.0f) return x * std::bit_cast<float>(0x39a32d56u);  // 1 / (12.6 * 255)
  const float c0 = std::bit_cast<float>(0x3b16bb99u);  // 0.0023
  const float c1 = std::bit_cast<float>(0x37456107u);  // 0.0030 / 255
  const float c2 = std::bit_cast<float>(0x3732ee61u);  // 0.6935 / 255^2
  const float c3 = std::bit_cast<float>(0x329c092bu);  // 0.3012 / 255^3
  const float x2 = x * x;
  const float even = std::fma(x2, c2, c0), odd = std::fma(x2, c3, c1);
  return std::fma(odd, x, even);
}

}  // namespace

const TexelFormatInfo& info(TexelFormat f) {
  for (const Named& n : kFormats)
    if (n.format == f) return n.info;
  return kFormats[0].info;
}

std::optional<TexelFormat> parse_texel_format(const std::string& gl_name) {
  for (const Named& n : kFormats)
    if (gl_name == n.info.gl_name) return n.format;
  return std::nullopt;
}

std::string texel_format_names() {
  std::string out;
  for (const Named& n : kFormats) out += (out.empty() ? "" : ", ") + std::string(n.info.gl_name);
  return out;
}

std::vector<std::uint8_t> encode_texels(TexelFormat f, const float* rgba, std::size_t texels) {
  const TexelFormatInfo& fi = info(f);
  std::vector<std::uint8_t> out(texels * std::size_t(fi.bytes_per_texel()));
  std::uint8_t* dst = out.data();
  for (std::size_t t = 0; t < texels; ++t)
    for (int c = 0; c < fi.channels; ++c) {
      const float v = rgba[t * 4 + std::size_t(c)];
      switch (fi.type) {
        case ChannelType::kFloat32: std::memcpy(dst, &v, 4); dst += 4; break;
        case ChannelType::kFloat16: {
          const auto h = std::uint16_t(half_from_float(v));
          std::memcpy(dst, &h, 2);
          dst += 2;
          break;
        }
        case ChannelType::kUnorm8:
        case ChannelType::kSrgb8: *dst++ = fixed::unorm8_from_float(v); break;
        case ChannelType::kUnorm16: {
          const auto k = std::uint16_t(fixed::unorm_from_float(v, 16));
          std::memcpy(dst, &k, 2);
          dst += 2;
          break;
        }
        case ChannelType::kUnorm24: {
          const std::uint32_t k = fixed::unorm_from_float(v, 24);
          const std::uint32_t word = (k << 8) | (f == TexelFormat::kDepth24 ? k >> 16 : 0u);
          std::memcpy(dst, &word, 4);
          dst += 4;
          break;
        }
      }
    }
  return out;
}

std::vector<float> decode_texels(TexelFormat f, const std::vector<std::uint8_t>& bytes) {
  const TexelFormatInfo& fi = info(f);
  const std::size_t texels = bytes.size() / std::size_t(fi.bytes_per_texel());
  std::vector<float> out(texels * 4);
  const std::uint8_t* src = bytes.data();
  for (std::size_t t = 0; t < texels; ++t) {
    float* dst = out.data() + t * 4;
    dst[0] = dst[1] = dst[2] = 0.0f;
    dst[3] = 1.0f;
    for (int c = 0; c < fi.channels; ++c) {
      switch (fi.type) {
        case ChannelType::kFloat32: std::memcpy(&dst[c], src, 4); src += 4; break;
        case ChannelType::kFloat16: {
          std::uint16_t h;
          std::memcpy(&h, src, 2);
          dst[c] = half_to_float(h);
          src += 2;
          break;
        }
        case ChannelType::kUnorm8: dst[c] = fixed::unorm8_texel_to_float(*src++); break;
        // Alpha is linear (GL 4.6 8.24).
        case ChannelType::kSrgb8:
          dst[c] = c == 3 ? fixed::unorm8_texel_to_float(*src) : srgb8_texel_to_float(*src);
          ++src;
          break;
        case ChannelType::kUnorm16: {
          std::uint16_t k;
          std::memcpy(&k, src, 2);
          dst[c] = fixed::unorm_texel_to_float(k, 16);
          src += 2;
          break;
        }
        case ChannelType::kUnorm24: {
          std::uint32_t word;
          std::memcpy(&word, src, 4);
          dst[c] = fixed::unorm_texel_to_float(word >> 8, 24);
          src += 4;
          break;
        }
      }
    }
  }
  return out;
}

}  // namespace tessref::texture
