#pragma once
// `tessref render --check-range NAME=LO,HI`: a range test on a named output, reported like a NaN
// (docs/check.md). Names:
//   gl_Position[.x|.y|.z|.w]         the evaluation shader's gl_Position (every component, or one)
//   OUT[.x|.y|.z|.w]                 an evaluation shader output variable by its GLSL name
//                                    (the built-in programs: their twins' v_world_position, v_world_normal)
//   length(gl_Position | OUT)        the Euclidean length of its components
//   gl_TessLevelOuter[i], gl_TessLevelInner[i]   one level the control shader wrote
//   levels                           the levels a triangle domain uses: outer 0..2 and inner 0
#include <string>
#include <vector>

namespace tessref {

struct CheckSource;  // check/check.h

// An evaluation shader output: its name and where it lies among the vertex's floats (0..3
// gl_Position, 4 + k varying k; location L starts at varying 4L).
struct CheckOutput {
  std::string name;
  int first = 0;
  int components = 4;
};

struct CheckRange {
  std::string spec;  // as given ("gl_Position.w=0.001,1e6"), for the report
  float lo = 0.0f, hi = 0.0f;
  bool level = false;   // control shader levels; else evaluation shader outputs
  bool length = false;  // length(...): one value, the Euclidean length of the floats
  // The floats tested: a vertex's (0..3 gl_Position, 4 + k varying k), or the levels (0..3 outer,
  // 4..5 inner), and each one's name (length: one name, "length(NAME)").
  std::vector<int> index;
  std::vector<std::string> names;
};

// The evaluation shader's outputs: for GLSL, its `layout(location = L) out TYPE NAME;`
// declarations (float, vecN); for the built-in programs (no file), the twins' names.
std::vector<CheckOutput> evaluation_output_names(const CheckSource& tes);

// Parses one --check-range value. InputError (naming --check-range and the rule) for a missing
// '=', bounds that are not two numbers, a NaN bound, LO > HI, or an unknown name (the message
// lists the names this scene has).
CheckRange parse_check_range(const std::string& spec, const std::vector<CheckOutput>& outputs);

}  // namespace tessref
