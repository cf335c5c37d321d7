// Storage images (GL 4.6 8.26): imageLoad, imageStore, imageSize and the image atomics, on level 0
// of the texture bound to the image's unit, whose internal format is the one the image declares
// (layout(rgba32f) ...). A store converts the value as glTexSubImage would for that format
// (texture::encode_texel) and keeps the texel the sampler reads in step (decode_texel).
#include <algorithm>
#include <cstring>

#include <spirv/unified1/spirv.hpp>

#include "shader/executor_runner.h"
#include "texture/texel_format.h"

namespace tessref::shader {
namespace {

using texture::Target;

// A texel's place in a level: its index (layer after layer, rows from the bottom), or -1 outside.
std::int64_t texel_index(const texture::Level& level, Target target, const std::int32_t c[3]) {
  std::int32_t x = c[0], y = 0, layer = 0;
  switch (target) {
    case Target::k1D: case Target::kBuffer: break;
    case Target::k1DArray: layer = c[1]; break;
    case Target::k2D: case Target::kRectangle: y = c[1]; break;
    default: y = c[1]; layer = c[2]; break;  // 2D arrays, 3D
  }
  if (x < 0 || y < 0 || layer < 0 || x >= level.width || y >= level.height || layer >= level.layers) return -1;
  return (std::int64_t(layer) * level.height + y) * level.width + x;
}

// imageSize: width, then height or layers, then depth or layers (GLSL 4.60 8.12).
void image_size(const texture::Level& level, Target target, std::uint32_t out[3]) {
  out[0] = std::uint32_t(level.width);
  out[1] = target == Target::k1DArray ? std::uint32_t(level.layers) : std::uint32_t(level.height);
  out[2] = std::uint32_t(level.layers);
}

}  // namespace

std::optional<texture::TexelFormat> image_texel_format(std::uint32_t spv_format) {
  using F = texture::TexelFormat;
  switch (spv::ImageFormat(spv_format)) {
    case spv::ImageFormatRgba32f: return F::kRgba32F;
    case spv::ImageFormatRgba16f: return F::kRgba16F;
    case spv::ImageFormatR32f: return F::kR32F;
    case spv::ImageFormatRgba8: return F::kRgba8;
    case spv::ImageFormatRgba8Snorm: return F::kRgba8Snorm;
    case spv::ImageFormatRg32f: return F::kRg32F;
    case spv::ImageFormatRg16f: return F::kRg16F;
    case spv::ImageFormatR11fG11fB10f: return F::kR11fG11fB10f;
    case spv::ImageFormatR16f: return F::kR16F;
    case spv::ImageFormatRgba16: return F::kRgba16;
    case spv::ImageFormatRg16: return F::kRg16;
    case spv::ImageFormatRg8: return F::kRg8;
    case spv::ImageFormatR16: return F::kR16;
    case spv::ImageFormatR8: return F::kR8;
    case spv::ImageFormatRgba16Snorm: return F::kRgba16Snorm;
    case spv::ImageFormatRg16Snorm: return F::kRg16Snorm;
    case spv::ImageFormatRg8Snorm: return F::kRg8Snorm;
    case spv::ImageFormatR16Snorm: return F::kR16Snorm;
    case spv::ImageFormatR8Snorm: return F::kR8Snorm;
    case spv::ImageFormatRgba32i: return F::kRgba32I;
    case spv::ImageFormatRgba16i: return F::kRgba16I;
    case spv::ImageFormatRgba8i: return F::kRgba8I;
    case spv::ImageFormatR32i: return F::kR32I;
    case spv::ImageFormatRg32i: return F::kRg32I;
    case spv::ImageFormatRg16i: return F::kRg16I;
    case spv::ImageFormatRg8i: return F::kRg8I;
    case spv::ImageFormatR16i: return F::kR16I;
    case spv::ImageFormatR8i: return F::kR8I;
    case spv::ImageFormatRgba32ui: return F::kRgba32Ui;
    case spv::ImageFormatRgba16ui: return F::kRgba16Ui;
    case spv::ImageFormatRgba8ui: return F::kRgba8Ui;
    case spv::ImageFormatR32ui: return F::kR32Ui;
    case spv::ImageFormatRgb10a2ui: return F::kRgb10A2Ui;
    case spv::ImageFormatRg32ui: return F::kRg32Ui;
    case spv::ImageFormatRg16ui: return F::kRg16Ui;
    case spv::ImageFormatRg8ui: return F::kRg8Ui;
    case spv::ImageFormatR16ui: return F::kR16Ui;
    case spv::ImageFormatR8ui: return F::kR8Ui;
    default: return std::nullopt;
  }
}

void Runner::image(const XIns& x) {
  using Kind = TexOp::Kind;
  const TexOp& op = p.textures[x.aux];
  const std::uint32_t* unit = row<std::uint32_t>(op.image);
  // Lanes in order: where two write one texel, the later lane's value stays.
  for (int l = 0; l < n; ++l) {
    if (!mask[l]) continue;
    texture::Texture* t = unit[l] < inv.images_.size() ? inv.images_[unit[l]] : nullptr;
    texture::Level* level = t && t->target == op.target && !t->levels.empty() ? &t->levels[0] : nullptr;
    if (op.kind == Kind::QuerySize) {
      std::uint32_t size[3] = {0, 0, 0};
      if (level) image_size(*level, op.target, size);
      for (std::uint32_t c = 0; c < x.n && c < 3; ++c) row<std::uint32_t>(x.dst, c)[l] = size[c];
      continue;
    }
    std::int32_t c[3] = {0, 0, 0};
    for (std::uint32_t k = 0; k < op.coord_comps && k < 3; ++k) c[k] = std::int32_t(row<std::uint32_t>(op.coord, k)[l]);
    const std::int64_t index = level ? texel_index(*level, op.target, c) : -1;
    // Outside the image (or none bound): loads and atomics read 0, stores and atomics change nothing.
    float* texel = index < 0 ? nullptr : level->texels.data() + 4 * index;
    const texture::TexelFormatInfo& format = texture::info(t ? t->format : texture::TexelFormat::kRgba32F);
    const bool writes = texel && !inv.helper_[l];
    switch (op.kind) {
      case Kind::ImageRead:
        for (std::uint32_t k = 0; k < x.n; ++k) row<float>(x.dst, k)[l] = texel ? texel[k] : 0.0f;
        break;
      case Kind::ImageWrite: {
        if (!writes) break;
        // Stored in the format, then read back as the sampler will read it.
        std::uint8_t* stored = level->stored.data() + index * std::int64_t(format.bytes_per_texel());
        if (format.integer()) {
          std::int64_t v[4];
          for (int k = 0; k < 4; ++k) {
            const std::uint32_t w = row<std::uint32_t>(op.texel, std::uint32_t(k))[l];
            v[k] = format.signed_integer() ? std::int64_t(std::int32_t(w)) : std::int64_t(w);
          }
          texture::encode_integer_texel(t->format, v, stored);
        } else {
          float v[4];
          for (int k = 0; k < 4; ++k) v[k] = row<float>(op.texel, std::uint32_t(k))[l];
          texture::encode_texel(t->format, v, stored);
        }
        texture::decode_texel(t->format, stored, texel);
        break;
      }
      case Kind::ImageAtomic: {  // r32i and r32ui images only (the decoder checks)
        std::uint32_t before = 0;
        if (texel) std::memcpy(&before, level->stored.data() + 4 * index, 4);
        const std::uint32_t operand = op.texel == kNone ? 0u : row<std::uint32_t>(op.texel)[l];
        const std::uint32_t comparator = op.comparator == kNone ? 0u : row<std::uint32_t>(op.comparator)[l];
        const std::uint32_t after = atomic_value(op.atomic, before, operand, comparator);
        if (writes) {
          std::memcpy(level->stored.data() + 4 * index, &after, 4);
          std::memcpy(texel, &after, 4);  // an integer texel's red channel: its bits
        }
        if (x.dst != kNone) row<std::uint32_t>(x.dst)[l] = before;
        break;
      }
      default: break;
    }
  }
}

}  // namespace tessref::shader
