#pragma once
// The internal formats a texture's texels can have (glTexStorage2D's internalformat), what an
// image's float values become when stored in one, and what the sampler reads back.
//
// tessref converts a file's values to the format itself and gives the driver the stored bytes
// (GL_UNSIGNED_BYTE, GL_HALF_FLOAT or GL_FLOAT data of the format's own layout), so both read the
// same texels: GL 4.6 8.4.4.2 leaves the rounding of an upload's conversion to the implementation.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tessref::texture {

enum class TexelFormat {
  kRgba32F, kRg32F, kR32F,
  kRgba16F, kRg16F, kR16F,
  kRgba8, kRgb8, kRg8, kR8,
  kSrgb8Alpha8, kSrgb8,
  kDepth16, kDepth24, kDepth32F, kDepth24Stencil8,
  kRgba16, kRgb16, kRg16, kR16,
  kRgba16Snorm, kRgb16Snorm, kRg16Snorm, kR16Snorm,
  kRgba8Snorm, kRgb8Snorm, kRg8Snorm, kR8Snorm,
  kR11fG11fB10f, kRgb9E5,
};

// kUnorm24: a 24-bit depth in the top bits of a 32-bit word, as GL_UNSIGNED_INT (DEPTH_COMPONENT24:
// the low byte repeats the top bits, so any conversion to 24 bits gives the same value) and
// GL_UNSIGNED_INT_24_8 (DEPTH24_STENCIL8: the low byte is the stencil index, 0) give it.
// kUfloat11_11_10 and kRgb9E5: the packed float formats, one 32-bit word a texel
// (GL_UNSIGNED_INT_10F_11F_11F_REV, GL_UNSIGNED_INT_5_9_9_9_REV).
enum class ChannelType {
  kFloat32, kFloat16, kUnorm8, kSrgb8, kUnorm16, kUnorm24, kSnorm8, kSnorm16, kUfloat11_11_10, kRgb9E5,
};

struct TexelFormatInfo {
  const char* gl_name;  // "GL_RGBA8"
  int channels;         // 1..4 (R, RG, RGB, RGBA); 1 for depth
  ChannelType type;
  bool depth = false;   // DEPTH_COMPONENT or DEPTH_STENCIL base format: sampled as (d, 0, 0, 1)
  bool packed() const { return type == ChannelType::kUfloat11_11_10 || type == ChannelType::kRgb9E5; }
  int bytes_per_channel() const {  // of one channel; packed formats: of the texel's word
    switch (type) {
      case ChannelType::kFloat32: case ChannelType::kUnorm24: return 4;
      case ChannelType::kUfloat11_11_10: case ChannelType::kRgb9E5: return 4;
      case ChannelType::kFloat16: case ChannelType::kUnorm16: case ChannelType::kSnorm16: return 2;
      default: return 1;
    }
  }
  int bytes_per_texel() const { return packed() ? 4 : channels * bytes_per_channel(); }
  // Fixed-point unsigned channels (colour or depth), read in [0, 1].
  bool unsigned_normalized() const {
    return type == ChannelType::kUnorm8 || type == ChannelType::kSrgb8 || type == ChannelType::kUnorm16 ||
           type == ChannelType::kUnorm24;
  }
  bool signed_normalized() const { return type == ChannelType::kSnorm8 || type == ChannelType::kSnorm16; }
};

// GL 4.6 8.5.2: the largest value GL_RGB9_E5 holds, (2^9 - 1) / 2^9 * 2^(31 - 15).
inline constexpr float kMaxRgb9E5 = 65408.0f;

const TexelFormatInfo& info(TexelFormat f);
std::optional<TexelFormat> parse_texel_format(const std::string& gl_name);
std::string texel_format_names();  // "GL_RGBA32F, GL_RG32F, ...", for messages

// Stores `texels` RGBA floats (4 per texel) in format f: 32-bit float channels unchanged, 16-bit
// ones rounded to the nearest half (ties to even; beyond 65504: infinity), 8-bit normalized ones
// clamped to [0, 1] and rounded to the nearest k / 255 (sRGB formats: the value is taken as
// already encoded, as an 8-bit image file holds it), 16- and 24-bit depths likewise to the
// nearest k / (2^b - 1) (GL 4.6 8.4.4.2 clamps fixed-point depth to [0, 1]; a float depth is kept
// as it is, as Mesa keeps it); signed normalized ones clamped to [-1, 1] and rounded to the
// nearest k / (2^(b-1) - 1); GL_R11F_G11F_B10F's channels rounded to the nearest 11- and 10-bit
// unsigned float (ties to even; negative: 0, beyond the largest: the largest); GL_RGB9_E5 by GL
// 4.6 8.5.2's shared-exponent equations. Channels the format lacks are dropped.
std::vector<std::uint8_t> encode_texels(TexelFormat f, const float* rgba, std::size_t texels);

// What the sampler reads from stored texels (GL 4.6 15.2.1 and 8.24): each channel converted to
// float (normalized channels as llvmpipe converts them: common/fixed_point.h; sRGB ones decoded
// before filtering), missing green and blue 0, missing alpha 1. Four floats per texel.
std::vector<float> decode_texels(TexelFormat f, const std::vector<std::uint8_t>& bytes);

}  // namespace tessref::texture
