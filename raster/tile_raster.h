#pragma once
// Scan conversion of one set-up triangle inside one screen rectangle (a tile).
#include <cstdint>

#include "raster/setup.h"

namespace tessref::raster {

struct PixelRect {
  int x0, y0, x1, y1;  // inclusive
};

// Shades the pixels of rect whose centers the triangle covers (fill rule in common/fixed_point.h)
// and that pass the depth test LESS; returns how many were shaded. varyings: the triangle's
// 3 * num_varyings values as SetupTriangle stores them. The result for a pixel does not depend
// on rect.
std::uint64_t raster_triangle(const SetupTriangle& t, const float* varyings, int num_varyings,
                              const PixelRect& rect, const FragmentProgram& fs, Framebuffer& fb);

// False when no pixel center of rect can be inside t (every center is outside one edge): lets the
// binner skip tiles that a large triangle's bounding box overlaps but the triangle misses. Exact
// and conservative: true whenever raster_triangle would cover a pixel of rect.
bool triangle_may_cover(const SetupTriangle& t, const PixelRect& rect);

}  // namespace tessref::raster
