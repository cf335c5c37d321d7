#pragma once
// Rewrites of GLSL sources for a given tessellation setup: tessref's GLSL twins carry one default
// layout line that the runner replaces with the scene's.
#include <string>

#include "stages/tpg.h"

namespace tessref::glref {

// "layout(triangles, fractional_odd_spacing, ccw[, point_mode]) in;\n"
std::string tes_layout_qualifier(const TessLayout& layout);

// Replaces the TES input layout line (a "layout(...) in;" naming triangles, quads or isolines)
// with tes_layout_qualifier(layout), and for quads and isolines defines TESSREF_QUADS or
// TESSREF_ISOLINES after #version. Throws GlError if there is no such line.
std::string set_tes_layout(const std::string& source, const TessLayout& layout);

// Replaces "layout(vertices = N) out;" in a TCS. Throws GlError if there is no such line.
std::string set_tcs_vertices(const std::string& source, int vertices);

}  // namespace tessref::glref
