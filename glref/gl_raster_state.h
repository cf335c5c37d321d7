#pragma once
// The rasterizer's fixed-function state (RasterState) as the GL calls that set it.
#include "raster/rasterizer.h"

namespace tessref::glref {

// glEnable/glDisable and the state calls for the viewport (none: width x height, the
// framebuffer), depth range, depth, culling, polygon mode, scissor, blending and the colour mask.
// The context must be current.
void apply_raster_state(const RasterState& state, int width, int height);
// Back to GL's initial state for all of them.
void reset_raster_state(int width, int height);

}  // namespace tessref::glref
