#pragma once
// The scene's tessellation block: what the tessellation stages (stages/) will be asked to do.
#include <filesystem>

#include "stages/schemes/displacement.h"
#include "stages/tpg.h"
#include "stages/tpg_uniform.h"

namespace tessref {

// How a triangle becomes a curved patch. Phong tessellation, NLSA and Nagata triangles are the
// quadratic schemes of seed 004 (stages/schemes/quadratic_patch.h, docs/schemes.md).
enum class SurfaceScheme { Flat, PN, Phong, NLSA, Nagata, ScalarTaggedPN };
// How the normal is evaluated across a PN patch (see /work/shared/notes/formulas.md):
// linear (interpolated corner normals), quadratic (Vlachos et al.), quadratic_corrected
// (the corrected mid-edge coefficient), analytic (cross product of the patch's tangents).
enum class NormalMode { Linear, Quadratic, QuadraticCorrected, Analytic };

struct AdaptiveTessellation {
  bool enabled = false;
  float pixels_per_segment = 8.0f;  // target edge segment length on screen
};

struct TessellationSettings {
  bool enabled = false;
  SurfaceScheme scheme = SurfaceScheme::PN;
  NormalMode normal_mode = NormalMode::Quadratic;
  TessSpacing spacing = TessSpacing::FractionalOdd;
  TessWinding winding = TessWinding::Ccw;
  // The GL primitive generator, or uniform subdivision on the barycentric grid (seed 000's CPU
  // tessellator; built-in programs and fixed levels only, docs/uniform-subdivision.md).
  Tessellator tessellator = Tessellator::PrimitiveGenerator;
  TessLevels levels;  // used as is when adaptive is off (triangles: outer[0..2], inner[0])
  AdaptiveTessellation adaptive;
  float phong_alpha = 0.75f;   // tessellation.phong_alpha: Phong tessellation's shape factor, >= 0
  float nagata_eps = 1e-4f;    // tessellation.nagata_eps: Nagata's threshold, in [0, 0.5]
  // tessellation.displacement: P + a sin(f |P|) N on top of the scheme (seed 001 Figure 4).
  DisplacementSettings displacement;
  // Scalar Tagged PN (docs/scalar-tagged-pn.md): the per-vertex sidecar file tessellation.tags
  // (resolved against the scene file; empty: none) and the default tension tessellation.tension.
  std::filesystem::path tags;
  float tension = 0.0f;
};

// The GLSL twins' u_normal_mode (pn_triangles.tesc/.tese): 0 linear, 1 quadratic,
// 2 quadratic_corrected, 3 analytic (the enum's order).
inline int glsl_index(NormalMode m) { return static_cast<int>(m); }

const char* to_string(SurfaceScheme s);  // "flat" | "pn" | "phong" | "nlsa" | "nagata"
const char* to_string(NormalMode m);     // "linear" | "quadratic" | ...
bool parse(const std::string& s, SurfaceScheme& out);
bool parse(const std::string& s, NormalMode& out);

// The file names of a scheme's GLSL twins (stages/schemes/, embedded as stages/glsl/twins.h), for
// shaders.program twins and the real-GL runner alike.
struct SchemeTwins {
  const char* tess_control;
  const char* tess_evaluation;
};
SchemeTwins scheme_twins(SurfaceScheme s);

}  // namespace tessref
