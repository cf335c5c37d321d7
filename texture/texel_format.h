#pragma once
// The internal formats a texture's texels can have (glTexStorage2D's internalformat), what an
// image's float values become when stored in one, and what the sampler reads back.
//
// tessref converts a file's values to the format itself and gives the driver the stored bytes
// (GL_UNSIGNED_BYTE, GL_HALF_FLOAT or GL_FLOAT data of the format's own layout), so both read the
// same texels: GL 4.6 8.4.4.2 leaves the rounding of an upload's conversion to the implementation.
#include <bit>
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
  kRgba8I, kRgb8I, kRg8I, kR8I, kRgba8Ui, kRgb8Ui, kRg8Ui, kR8Ui,
  kRgba16I, kRgb16I, kRg16I, kR16I, kRgba16Ui, kRgb16Ui, kRg16Ui, kR16Ui,
  kRgba32I, kRgb32I, kRg32I, kR32I, kRgba32Ui, kRgb32Ui, kRg32Ui, kR32Ui,
  kRgb10A2Ui,
  kRgb32F,
};

// kUnorm24: a 24-bit depth in the top bits of a 32-bit word, as GL_UNSIGNED_INT (DEPTH_COMPONENT24:
// the low byte repeats the top bits, so any conversion to 24 bits gives the same value) and
// GL_UNSIGNED_INT_24_8 (DEPTH24_STENCIL8: the low byte is the stencil index, 0) give it.
// kUfloat11_11_10 and kRgb9E5: the packed float formats, one 32-bit word a texel
// (GL_UNSIGNED_INT_10F_11F_11F_REV, GL_UNSIGNED_INT_5_9_9_9_REV). kSint* and kUint*: the integer
// formats (GL 4.6 table 8.12), read as integers; kUint10_10_10_2 is GL_RGB10_A2UI's packed word
// (GL_UNSIGNED_INT_2_10_10_10_REV).
enum class ChannelType {
  kFloat32, kFloat16, kUnorm8, kSrgb8, kUnorm16, kUnorm24, kSnorm8, kSnorm16, kUfloat11_11_10, kRgb9E5,
  kSint8, kSint16, kSint32, kUint8, kUint16, kUint32, kUint10_10_10_2,
};

struct TexelFormatInfo {
  const char* gl_name;  // "GL_RGBA8"
  int channels;         // 1..4 (R, RG, RGB, RGBA); 1 for depth
  ChannelType type;
  bool depth = false;   // DEPTH_COMPONENT or DEPTH_STENCIL base format: sampled as (d, 0, 0, 1)
  bool packed() const {
    return type == ChannelType::kUfloat11_11_10 || type == ChannelType::kRgb9E5 || type == ChannelType::kUint10_10_10_2;
  }
  int bytes_per_channel() const {  // of one channel; packed formats: of the texel's word
    switch (type) {
      case ChannelType::kFloat32: case ChannelType::kUnorm24: case ChannelType::kSint32: case ChannelType::kUint32:
        return 4;
      case ChannelType::kUfloat11_11_10: case ChannelType::kRgb9E5: case ChannelType::kUint10_10_10_2: return 4;
      case ChannelType::kFloat16: case ChannelType::kUnorm16: case ChannelType::kSnorm16: case ChannelType::kSint16:
      case ChannelType::kUint16:
        return 2;
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
  // The integer formats: read by isampler (signed) and usampler (unsigned) as integers.
  bool signed_integer() const {
    return type == ChannelType::kSint8 || type == ChannelType::kSint16 || type == ChannelType::kSint32;
  }
  bool unsigned_integer() const {
    return type == ChannelType::kUint8 || type == ChannelType::kUint16 || type == ChannelType::kUint32 ||
           type == ChannelType::kUint10_10_10_2;
  }
  bool integer() const { return signed_integer() || unsigned_integer(); }
  // The values channel c (0..3) of an integer format holds: [lo, hi].
  std::int64_t integer_min(int c) const;
  std::int64_t integer_max(int c) const;
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
// 4.6 8.5.2's shared-exponent equations; integer formats' values rounded to the nearest integer
// and clamped (encode_integer_texels). Channels the format lacks are dropped.
std::vector<std::uint8_t> encode_texels(TexelFormat f, const float* rgba, std::size_t texels);

// Stores integer texels (4 per texel) in integer format f, each channel already within the
// format's range (integer_min .. integer_max; others are clamped to it).
std::vector<std::uint8_t> encode_integer_texels(TexelFormat f, const std::int64_t* rgba, std::size_t texels);

// What the sampler reads from stored texels (GL 4.6 15.2.1 and 8.24): each channel converted to
// float (normalized channels as llvmpipe converts them: common/fixed_point.h; sRGB ones decoded
// before filtering), missing green and blue 0, missing alpha 1. Four floats per texel; for the
// integer formats four 32-bit integers (two's complement for signed ones) in the floats' bits
// (integer_bits), missing alpha the integer 1: GL samples them with GL_NEAREST only, so the
// sampler copies them and never computes with them.
std::vector<float> decode_texels(TexelFormat f, const std::vector<std::uint8_t>& bytes);

// One texel of the three above, written to or read from bytes_per_texel() bytes at dst / src
// (4 floats or integers at rgba): imageStore's single texels, without a vector each.
void encode_texel(TexelFormat f, const float* rgba, std::uint8_t* dst);
void encode_integer_texel(TexelFormat f, const std::int64_t* rgba, std::uint8_t* dst);
void decode_texel(TexelFormat f, const std::uint8_t* src, float* rgba);

// An integer texel's channel as decode_texels holds it: its 32 bits in a float.
inline float integer_bits(std::int64_t v) { return std::bit_cast<float>(std::uint32_t(v)); }

}  // namespace tessref::texture
