#pragma once
// GL 4.6 equation 8.17 (sRGB to linear) for an 8-bit channel, and equation 17.1 (linear to sRGB)
// rounded to 8 bits, both exact to the equations (tables built in double precision by
// scripts/gen-srgb-tables.py). Textures decode with the first, framebuffers encode with the second.
#include <cstdint>

namespace tessref {

float srgb_decode(std::uint8_t k);
std::uint8_t srgb_encode(float linear);

}  // namespace tessref
