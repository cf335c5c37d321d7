// Names of the TPG layout qualifiers, for the CLI, scene files and GLSL generation.
#include "stages/tpg.h"

namespace tessref {

const char* to_string(TessDomain d) {
  switch (d) {
    case TessDomain::Triangles: return "triangles";
    case TessDomain::Quads: return "quads";
    case TessDomain::Isolines: return "isolines";
  }
  return "?";
}
const char* to_string(TessSpacing s) {
  switch (s) {
    case TessSpacing::Equal: return "equal";
    case TessSpacing::FractionalOdd: return "fractional_odd";
    case TessSpacing::FractionalEven: return "fractional_even";
  }
  return "?";
}
const char* to_string(TessWinding w) { return w == TessWinding::Ccw ? "ccw" : "cw"; }

const char* glsl_name(TessDomain d) { return to_string(d); }
const char* glsl_name(TessSpacing s) {
  switch (s) {
    case TessSpacing::Equal: return "equal_spacing";
    case TessSpacing::FractionalOdd: return "fractional_odd_spacing";
    case TessSpacing::FractionalEven: return "fractional_even_spacing";
  }
  return "?";
}
const char* glsl_name(TessWinding w) { return to_string(w); }

bool parse(const std::string& s, TessDomain& out) {
  for (TessDomain d : {TessDomain::Triangles, TessDomain::Quads, TessDomain::Isolines})
    if (s == to_string(d)) return out = d, true;
  return false;
}
bool parse(const std::string& s, TessSpacing& out) {
  for (TessSpacing v : {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven})
    if (s == to_string(v) || s == glsl_name(v)) return out = v, true;
  return false;
}
bool parse(const std::string& s, TessWinding& out) {
  for (TessWinding v : {TessWinding::Ccw, TessWinding::Cw})
    if (s == to_string(v)) return out = v, true;
  return false;
}

}  // namespace tessref
