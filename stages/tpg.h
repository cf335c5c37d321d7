#pragma once
// The tessellation primitive generator (GL 4.6 core, section 11.2.2): tessellation levels in,
// domain points (gl_TessCoord) and primitives out, in emission order.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessref {

enum class TessDomain { Triangles, Quads, Isolines };
enum class TessSpacing { Equal, FractionalOdd, FractionalEven };
enum class TessWinding { Ccw, Cw };

// The TES input layout qualifiers that drive the generator.
struct TessLayout {
  TessDomain domain = TessDomain::Triangles;
  TessSpacing spacing = TessSpacing::Equal;
  TessWinding winding = TessWinding::Ccw;
  bool point_mode = false;
};

// gl_TessLevelOuter / gl_TessLevelInner as written by a TCS (raw: may be NaN, negative, huge).
struct TessLevels {
  std::array<float, 4> outer{1.0f, 1.0f, 1.0f, 1.0f};
  std::array<float, 2> inner{1.0f, 1.0f};
};

// Choices the GL spec leaves to the implementation, gathered in one place so that a profile
// measured on another driver can sit beside the llvmpipe one.
struct TessProfile {
  std::string name = "llvmpipe";
  int max_level = 64;  // GL_MAX_TESS_GEN_LEVEL; the generator supports 1..64
  // llvmpipe converts clamped levels to 16.16 fixed point before rounding, so a fractional_odd
  // level in (1, 1 + 2^-17] becomes exactly 1. The literal spec text rounds any level > 1 up to 3:
  // with this false, such levels are kept just above one (one fixed-point unit).
  bool odd_level_collapses_near_one = true;

  static TessProfile llvmpipe() { return TessProfile{}; }
  static TessProfile spec_literal() {
    TessProfile p;
    p.name = "spec-literal";
    p.odd_level_collapses_near_one = false;
    return p;
  }
};

// One patch's generated domain: the points in generation order and the primitives as indices into
// them (3 per triangle, 2 per isoline segment, 1 per point in point mode), in emission order.
struct TessDomainPoints {
  std::vector<glm::vec3> coords;        // gl_TessCoord (z = 0 for quads and isolines)
  std::vector<std::uint32_t> indices;   // emission order; empty when the patch is discarded
  int vertices_per_primitive = 3;       // 3 triangles, 2 lines, 1 points
  bool discarded = false;
  std::size_t primitive_count() const { return indices.size() / vertices_per_primitive; }
};

// Runs the generator for one patch. Never throws: NaN, negative and huge levels follow the spec
// (discard or clamp). The result depends only on (layout, levels, profile).
void generate_tessellation(const TessLayout& layout, const TessLevels& levels,
                           const TessProfile& profile, TessDomainPoints& out);
TessDomainPoints generate_tessellation(const TessLayout& layout, const TessLevels& levels,
                                       const TessProfile& profile = TessProfile::llvmpipe());

// Parsing and naming helpers shared by the CLI, scene files and the GL runner.
const char* to_string(TessDomain d);
const char* to_string(TessSpacing s);
const char* to_string(TessWinding w);
// GLSL layout qualifiers: "triangles", "fractional_odd_spacing", "ccw".
const char* glsl_name(TessDomain d);
const char* glsl_name(TessSpacing s);
const char* glsl_name(TessWinding w);
bool parse(const std::string& s, TessDomain& out);   // "triangles" | "quads" | "isolines"
bool parse(const std::string& s, TessSpacing& out);  // "equal" | "fractional_odd" | "fractional_even"
bool parse(const std::string& s, TessWinding& out);  // "ccw" | "cw"

}  // namespace tessref
