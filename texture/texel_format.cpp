#include "texture/texel_format.h"

#include <algorithm>
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

constexpr Named kFormats[] = {
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
    {TexelFormat::kRgba16, {"GL_RGBA16", 4, ChannelType::kUnorm16}},
    {TexelFormat::kRgb16, {"GL_RGB16", 3, ChannelType::kUnorm16}},
    {TexelFormat::kRg16, {"GL_RG16", 2, ChannelType::kUnorm16}},
    {TexelFormat::kR16, {"GL_R16", 1, ChannelType::kUnorm16}},
    {TexelFormat::kRgba16Snorm, {"GL_RGBA16_SNORM", 4, ChannelType::kSnorm16}},
    {TexelFormat::kRgb16Snorm, {"GL_RGB16_SNORM", 3, ChannelType::kSnorm16}},
    {TexelFormat::kRg16Snorm, {"GL_RG16_SNORM", 2, ChannelType::kSnorm16}},
    {TexelFormat::kR16Snorm, {"GL_R16_SNORM", 1, ChannelType::kSnorm16}},
    {TexelFormat::kRgba8Snorm, {"GL_RGBA8_SNORM", 4, ChannelType::kSnorm8}},
    {TexelFormat::kRgb8Snorm, {"GL_RGB8_SNORM", 3, ChannelType::kSnorm8}},
    {TexelFormat::kRg8Snorm, {"GL_RG8_SNORM", 2, ChannelType::kSnorm8}},
    {TexelFormat::kR8Snorm, {"GL_R8_SNORM", 1, ChannelType::kSnorm8}},
    {TexelFormat::kR11fG11fB10f, {"GL_R11F_G11F_B10F", 3, ChannelType::kUfloat11_11_10}},
    {TexelFormat::kRgb9E5, {"GL_RGB9_E5", 3, ChannelType::kRgb9E5}},
    {TexelFormat::kRgba8I, {"GL_RGBA8I", 4, ChannelType::kSint8}},
    {TexelFormat::kRgb8I, {"GL_RGB8I", 3, ChannelType::kSint8}},
    {TexelFormat::kRg8I, {"GL_RG8I", 2, ChannelType::kSint8}},
    {TexelFormat::kR8I, {"GL_R8I", 1, ChannelType::kSint8}},
    {TexelFormat::kRgba8Ui, {"GL_RGBA8UI", 4, ChannelType::kUint8}},
    {TexelFormat::kRgb8Ui, {"GL_RGB8UI", 3, ChannelType::kUint8}},
    {TexelFormat::kRg8Ui, {"GL_RG8UI", 2, ChannelType::kUint8}},
    {TexelFormat::kR8Ui, {"GL_R8UI", 1, ChannelType::kUint8}},
    {TexelFormat::kRgba16I, {"GL_RGBA16I", 4, ChannelType::kSint16}},
    {TexelFormat::kRgb16I, {"GL_RGB16I", 3, ChannelType::kSint16}},
    {TexelFormat::kRg16I, {"GL_RG16I", 2, ChannelType::kSint16}},
    {TexelFormat::kR16I, {"GL_R16I", 1, ChannelType::kSint16}},
    {TexelFormat::kRgba16Ui, {"GL_RGBA16UI", 4, ChannelType::kUint16}},
    {TexelFormat::kRgb16Ui, {"GL_RGB16UI", 3, ChannelType::kUint16}},
    {TexelFormat::kRg16Ui, {"GL_RG16UI", 2, ChannelType::kUint16}},
    {TexelFormat::kR16Ui, {"GL_R16UI", 1, ChannelType::kUint16}},
    {TexelFormat::kRgba32I, {"GL_RGBA32I", 4, ChannelType::kSint32}},
    {TexelFormat::kRgb32I, {"GL_RGB32I", 3, ChannelType::kSint32}},
    {TexelFormat::kRg32I, {"GL_RG32I", 2, ChannelType::kSint32}},
    {TexelFormat::kR32I, {"GL_R32I", 1, ChannelType::kSint32}},
    {TexelFormat::kRgba32Ui, {"GL_RGBA32UI", 4, ChannelType::kUint32}},
    {TexelFormat::kRgb32Ui, {"GL_RGB32UI", 3, ChannelType::kUint32}},
    {TexelFormat::kRg32Ui, {"GL_RG32UI", 2, ChannelType::kUint32}},
    {TexelFormat::kR32Ui, {"GL_R32UI", 1, ChannelType::kUint32}},
    {TexelFormat::kRgb10A2Ui, {"GL_RGB10_A2UI", 4, ChannelType::kUint10_10_10_2}},
    {TexelFormat::kRgb32F, {"GL_RGB32F", 3, ChannelType::kFloat32}},
};
static_assert(std::size(kFormats) == std::size_t(TexelFormat::kRgb32F) + 1, "one entry per TexelFormat");
// info() indexes the table by the enum (every texel lookup asks for it).
constexpr bool in_enum_order() {
  for (std::size_t i = 0; i < std::size(kFormats); ++i)
    if (std::size_t(kFormats[i].format) != i) return false;
  return true;
}
static_assert(in_enum_order(), "kFormats lists the formats in TexelFormat's order");

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

// A channel of b bits, signed normalized: clamp to [-1, 1] (NaN to 0), round c * (2^(b-1) - 1).
std::int32_t snorm_from_float(float c, int bits) {
  const double clamped = std::isnan(c) ? 0.0 : std::clamp(double(c), -1.0, 1.0);
  return std::int32_t(std::nearbyint(clamped * double((1 << (bits - 1)) - 1)));
}
// llvmpipe's reading: k times the float nearest 1 / (2^(b-1) - 1), at least -1.
float snorm_texel_to_float(std::int32_t k, int bits) {
  const float x = float(k) * static_cast<float>(1.0 / double((1 << (bits - 1)) - 1));
  return x > -1.0f ? x : -1.0f;
}

// An unsigned float of 5 exponent bits (bias 15) and m mantissa bits (GL 4.6 2.3.4.3 and 2.3.4.4:
// 11- and 10-bit): the nearest, ties to even; negative and -0: 0; beyond the largest finite: the
// largest; NaN and infinity kept.
std::uint32_t ufloat_from_float(float v, int m) {
  if (std::isnan(v)) return (31u << m) | 1u;
  if (!(v > 0.0f)) return 0u;
  if (std::isinf(v)) return 31u << m;
  const std::uint32_t largest = (30u << m) | ((1u << m) - 1u);
  int e = 0;
  std::frexp(double(v), &e);  // v = f * 2^e, f in [0.5, 1)
  const int biased = e - 1 + 15;
  if (biased <= 0)  // a denormal: M / 2^m * 2^-14 (M = 2^m rounds up into exponent 1 exactly)
    return std::uint32_t(std::nearbyint(std::ldexp(double(v), 14 + m)));
  const auto scaled = std::uint32_t(std::nearbyint(std::ldexp(double(v), m - (biased - 15))));  // 2^m .. 2^(m+1)
  return std::min((std::uint32_t(biased) << m) + (scaled - (1u << m)), largest);  // a carry raises the exponent
}
float ufloat_to_float(std::uint32_t bits, int m) {
  const std::uint32_t e = bits >> m, mant = bits & ((1u << m) - 1u);
  if (e == 31) return mant ? NAN : INFINITY;
  if (e == 0) return float(std::ldexp(double(mant), -14 - m));
  return float(std::ldexp(double((1u << m) + mant), int(e) - 15 - m));
}

// GL 4.6 8.5.2: three channels sharing a 5-bit exponent (bias 15) with 9-bit mantissas, packed as
// GL_UNSIGNED_INT_5_9_9_9_REV (red in the low bits, the exponent in the top five).
std::uint32_t rgb9e5_from_float(const float* rgb) {
  double c[3];
  for (int k = 0; k < 3; ++k) c[k] = rgb[k] > 0.0f ? std::min(double(rgb[k]), double(kMaxRgb9E5)) : 0.0;  // NaN: 0
  const double maxc = std::max({c[0], c[1], c[2]});
  int floor_log2 = -16;  // max(-B - 1, floor(log2(maxc))): -16 also for maxc = 0
  if (maxc > 0.0) {
    int e = 0;
    std::frexp(maxc, &e);
    floor_log2 = std::max(-16, e - 1);
  }
  int exp_shared = floor_log2 + 1 + 15;
  if (std::floor(maxc / std::ldexp(1.0, exp_shared - 15 - 9) + 0.5) == 512.0) ++exp_shared;
  std::uint32_t word = std::uint32_t(exp_shared) << 27;
  for (int k = 0; k < 3; ++k)
    word |= std::uint32_t(std::floor(c[k] / std::ldexp(1.0, exp_shared - 15 - 9) + 0.5)) << (9 * k);
  return word;
}
float rgb9e5_channel(std::uint32_t word, int k) {
  return float(std::ldexp(double((word >> (9 * k)) & 511u), int(word >> 27) - 15 - 9));
}

// Bits of channel c of an integer type.
int integer_channel_bits(ChannelType t, int c) {
  switch (t) {
    case ChannelType::kSint8: case ChannelType::kUint8: return 8;
    case ChannelType::kSint16: case ChannelType::kUint16: return 16;
    case ChannelType::kUint10_10_10_2: return c == 3 ? 2 : 10;
    default: return 32;
  }
}

}  // namespace

std::int64_t TexelFormatInfo::integer_min(int c) const {
  return signed_integer() ? -(std::int64_t(1) << (integer_channel_bits(type, c) - 1)) : 0;
}
std::int64_t TexelFormatInfo::integer_max(int c) const {
  const int bits = integer_channel_bits(type, c);
  return signed_integer() ? (std::int64_t(1) << (bits - 1)) - 1 : (std::int64_t(1) << bits) - 1;
}

const TexelFormatInfo& info(TexelFormat f) { return kFormats[std::size_t(f)].info; }

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

void encode_texel(TexelFormat f, const float* rgba, std::uint8_t* dst) {
  const TexelFormatInfo& fi = info(f);
  if (fi.integer()) {  // each value rounded to the nearest integer (NaN: 0)
    std::int64_t ints[4];
    for (int k = 0; k < 4; ++k)
      ints[k] = std::isnan(rgba[k]) ? 0 : std::int64_t(std::nearbyint(std::clamp(double(rgba[k]), -0x1p40, 0x1p40)));
    return encode_integer_texel(f, ints, dst);
  }
  if (fi.packed()) {
    const std::uint32_t word = fi.type == ChannelType::kRgb9E5
                                   ? rgb9e5_from_float(rgba)
                                   : ufloat_from_float(rgba[0], 6) | ufloat_from_float(rgba[1], 6) << 11 |
                                         ufloat_from_float(rgba[2], 5) << 22;
    std::memcpy(dst, &word, 4);
    return;
  }
  for (int c = 0; c < fi.channels; ++c) {
    const float v = rgba[c];
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
      case ChannelType::kSnorm8: *dst++ = std::uint8_t(std::int8_t(snorm_from_float(v, 8))); break;
      case ChannelType::kSnorm16: {
        const auto k = std::int16_t(snorm_from_float(v, 16));
        std::memcpy(dst, &k, 2);
        dst += 2;
        break;
      }
      case ChannelType::kUfloat11_11_10: case ChannelType::kRgb9E5: case ChannelType::kUint10_10_10_2: break;
      // Integer formats: encode_integer_texel.
      case ChannelType::kSint8: case ChannelType::kSint16: case ChannelType::kSint32: case ChannelType::kUint8:
      case ChannelType::kUint16: case ChannelType::kUint32: break;
      case ChannelType::kUnorm24: {
        const std::uint32_t k = fixed::unorm_from_float(v, 24);
        const std::uint32_t word = (k << 8) | (f == TexelFormat::kDepth24 ? k >> 16 : 0u);
        std::memcpy(dst, &word, 4);
        dst += 4;
        break;
      }
    }
  }
}

void encode_integer_texel(TexelFormat f, const std::int64_t* rgba, std::uint8_t* dst) {
  const TexelFormatInfo& fi = info(f);
  std::int64_t v[4];
  for (int c = 0; c < 4; ++c) v[c] = std::clamp(rgba[c], fi.integer_min(c), fi.integer_max(c));
  if (fi.type == ChannelType::kUint10_10_10_2) {
    const auto word = std::uint32_t(v[0] | v[1] << 10 | v[2] << 20 | v[3] << 30);
    std::memcpy(dst, &word, 4);
    return;
  }
  // Little-endian two's complement, the bytes GL_BYTE .. GL_UNSIGNED_INT data hold.
  for (int c = 0; c < fi.channels; ++c)
    for (int b = 0; b < fi.bytes_per_channel(); ++b) *dst++ = std::uint8_t(std::uint64_t(v[c]) >> (8 * b));
}

void decode_texel(TexelFormat f, const std::uint8_t* src, float* dst) {
  const TexelFormatInfo& fi = info(f);
  if (fi.integer()) {
    std::int64_t v[4] = {0, 0, 0, 1};
    if (fi.type == ChannelType::kUint10_10_10_2) {
      std::uint32_t word;
      std::memcpy(&word, src, 4);
      v[0] = word & 1023u, v[1] = (word >> 10) & 1023u, v[2] = (word >> 20) & 1023u, v[3] = word >> 30;
    } else {
      const int bytes_per_channel = fi.bytes_per_channel();
      for (int c = 0; c < fi.channels; ++c) {
        std::uint64_t u = 0;
        for (int b = 0; b < bytes_per_channel; ++b) u |= std::uint64_t(*src++) << (8 * b);
        const int bits = 8 * bytes_per_channel;
        v[c] = fi.signed_integer() && (u >> (bits - 1)) ? std::int64_t(u) - (std::int64_t(1) << bits) : std::int64_t(u);
      }
    }
    for (int c = 0; c < 4; ++c) dst[c] = integer_bits(v[c]);
    return;
  }
  dst[0] = dst[1] = dst[2] = 0.0f;
  dst[3] = 1.0f;
  if (fi.packed()) {
    std::uint32_t word;
    std::memcpy(&word, src, 4);
    for (int c = 0; c < 3; ++c)
      dst[c] = fi.type == ChannelType::kRgb9E5 ? rgb9e5_channel(word, c)
                                               : ufloat_to_float((word >> (11 * c)) & (c < 2 ? 0x7ffu : 0x3ffu), c < 2 ? 6 : 5);
    return;
  }
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
      case ChannelType::kSnorm8: dst[c] = snorm_texel_to_float(std::int8_t(*src++), 8); break;
      case ChannelType::kSnorm16: {
        std::int16_t k;
        std::memcpy(&k, src, 2);
        dst[c] = snorm_texel_to_float(k, 16);
        src += 2;
        break;
      }
      case ChannelType::kUfloat11_11_10: case ChannelType::kRgb9E5: case ChannelType::kUint10_10_10_2: break;
      case ChannelType::kSint8: case ChannelType::kSint16: case ChannelType::kSint32: case ChannelType::kUint8:
      case ChannelType::kUint16: case ChannelType::kUint32: break;  // integer formats: above
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

std::vector<std::uint8_t> encode_texels(TexelFormat f, const float* rgba, std::size_t texels) {
  const std::size_t size = std::size_t(info(f).bytes_per_texel());
  std::vector<std::uint8_t> out(texels * size);
  for (std::size_t t = 0; t < texels; ++t) encode_texel(f, rgba + 4 * t, out.data() + t * size);
  return out;
}

std::vector<std::uint8_t> encode_integer_texels(TexelFormat f, const std::int64_t* rgba, std::size_t texels) {
  const std::size_t size = std::size_t(info(f).bytes_per_texel());
  std::vector<std::uint8_t> out(texels * size);
  for (std::size_t t = 0; t < texels; ++t) encode_integer_texel(f, rgba + 4 * t, out.data() + t * size);
  return out;
}

std::vector<float> decode_texels(TexelFormat f, const std::vector<std::uint8_t>& bytes) {
  const std::size_t size = std::size_t(info(f).bytes_per_texel());
  const std::size_t texels = bytes.size() / size;
  std::vector<float> out(texels * 4);
  for (std::size_t t = 0; t < texels; ++t) decode_texel(f, bytes.data() + t * size, out.data() + 4 * t);
  return out;
}

}  // namespace tessref::texture
