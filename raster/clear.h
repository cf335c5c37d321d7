#pragma once
// glClear of the colour and depth buffers (GL 4.5, 17.4.3): only pixels inside the scissor box
// (with GL_SCISSOR_TEST enabled) change, and only the channels glColorMask and glDepthMask let
// through; the viewport does not apply.
#include <optional>

#include <glm/glm.hpp>

#include "raster/framebuffer.h"
#include "raster/rasterizer.h"

namespace tessref {

void clear_buffers(Framebuffer& fb, const RasterState& state, const std::optional<glm::vec4>& color,
                   const std::optional<float>& depth);

}  // namespace tessref
