#pragma once
// A draw's fixed-function state in the scene format: the keys named after GL's calls (enable,
// depth_func, depth_mask, cull_face, front_face, polygon_mode, scissor, color_mask, blend) read
// into the rasterizer's RasterState, with GL's defaults where a key is absent.
#include "scene/json_reader.h"
#include "raster/rasterizer.h"

namespace tessref {

// Reads the state keys of one draw object (the others are left to the caller).
RasterState read_raster_state(JsonObject& draw);

}  // namespace tessref
