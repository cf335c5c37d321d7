#pragma once
// Rewrites of GLSL sources for a given tessellation setup: tessref's GLSL twins carry one default
// layout line that the runner replaces with the scene's.
#include <string>
#include <vector>

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

// A scalar uniform turned into a compile-time constant: `uniform TYPE NAME;` becomes
// `const TYPE NAME = VALUE;` (VALUE is GLSL text, e.g. "1", "true", "0.5").
struct UniformConstant {
  std::string name;
  std::string value;
};

// Specializes the twins as an application compiles its shaders for one configuration (a light
// count, a normal mode): the driver's compiler then folds the loops and branches those uniforms
// drive. Only the declarations that exist in `source` are rewritten (a stage that does not
// declare a name is left as it is); the rewritten uniforms are no longer active, so setting them
// by name is skipped as for any optimized-away uniform.
std::string specialize_uniforms(const std::string& source, const std::vector<UniformConstant>& constants);

}  // namespace tessref::glref
