#pragma once
// The rasterizer's fixed-function state (RasterState) as the GL calls that set it.
#include "raster/rasterizer.h"

namespace tessref::glref {

// glEnable/glDisable and the state calls for depth, culling, polygon mode, scissor, blending and
// the colour mask. The context must be current.
void apply_raster_state(const RasterState& state);
// Back to GL's initial state for all of them.
void reset_raster_state();

}  // namespace tessref::glref
