#pragma once
// The internal formats a framebuffer attachment can have, and what storing a fragment's colour in
// one does: conversion, GL_FRAMEBUFFER_SRGB encoding and blending in the format's arithmetic.
// An attachment keeps each pixel as four floats equal to what the format holds (k / 255 for 8-bit
// channels, sRGB-encoded for SRGB8_ALPHA8, a half's value for RGBA16F).
#include <cstdint>

#include <glm/glm.hpp>

#include "common/fixed_point.h"
#include "common/srgb.h"
#include "raster/fragment_ops.h"

namespace tessref {

// glTexStorage2D / glRenderbufferStorage internal formats of colour attachments.
enum class ColorFormat { kRgba32F, kRgba16F, kRgba8, kSrgb8Alpha8 };
// Depth attachments: GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT24.
enum class DepthFormat { k32F, k24 };

const char* gl_name(ColorFormat f);
const char* gl_name(DepthFormat f);
inline bool is_fixed_point(ColorFormat f) { return f == ColorFormat::kRgba8 || f == ColorFormat::kSrgb8Alpha8; }

// The value an attachment of format f holds after storing c (no blending): clamped and rounded
// for 8-bit channels (sRGB-encoded when srgb_write, i.e. GL_FRAMEBUFFER_SRGB is enabled and the
// format is SRGB8_ALPHA8), rounded toward zero for RGBA16F, unchanged for RGBA32F.
glm::vec4 stored_color(ColorFormat f, bool srgb_write, const glm::vec4& c);

// What a depth buffer of format f holds for window depth z in [0, 1] (GL 4.6 13.8.1: converted to
// its format; 24 bits: common/fixed_point.h).
inline float stored_depth(DepthFormat f, float z) { return f == DepthFormat::k24 ? fixed::quantize_depth24(z) : z; }

// GL 4.6 17.3.6: blends source s with what the attachment holds (d) and returns the value it
// holds afterwards. Fixed-point formats clamp s and the constant colour to [0, 1] and blend 8-bit
// channels as llvmpipe does (fixed::unorm8_mul); with srgb_write on an SRGB8_ALPHA8 attachment the
// destination is decoded, blending is in float, and the result encoded; float formats blend in
// float.
glm::vec4 blended_color(ColorFormat f, bool srgb_write, const BlendState& b, const glm::vec4& s,
                        const glm::vec4& d);

}  // namespace tessref
