#include "common/srgb.h"

#include <algorithm>
#include <iterator>

namespace tessref {
namespace {

#include "common/srgb_tables.inc"

}  // namespace

float srgb_decode(std::uint8_t k) { return kSrgbDecode[k]; }

std::uint8_t srgb_encode(float linear) {
  if (!(linear > 0.0f)) return 0;  // NaN and negatives: 0, as equation 17.1 clamps
  return static_cast<std::uint8_t>(std::upper_bound(std::begin(kSrgbThreshold), std::end(kSrgbThreshold), linear) -
                                   std::begin(kSrgbThreshold));
}

}  // namespace tessref
