#pragma once
// A FragmentBatch's columns as the shading kernels read them (the varying convention of
// stages/tess_stage.h: world position at kVaryingPosition, world normal at kVaryingNormal).
#include "raster/rasterizer.h"
#include "stages/programs/shading_batch.h"

namespace tessref::programs {

ShadingLanes shading_lanes(FragmentBatch& batch);  // defined in phong.cpp

}  // namespace tessref::programs
