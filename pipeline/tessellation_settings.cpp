#include "pipeline/tessellation_settings.h"

namespace tessref {

const char* to_string(SurfaceScheme s) { return s == SurfaceScheme::Flat ? "flat" : "pn"; }

const char* to_string(NormalMode m) {
  switch (m) {
    case NormalMode::Linear: return "linear";
    case NormalMode::Quadratic: return "quadratic";
    case NormalMode::QuadraticCorrected: return "quadratic_corrected";
    case NormalMode::Analytic: return "analytic";
  }
  return "?";
}

bool parse(const std::string& s, SurfaceScheme& out) {
  for (SurfaceScheme v : {SurfaceScheme::Flat, SurfaceScheme::PN})
    if (s == to_string(v)) return out = v, true;
  return false;
}

bool parse(const std::string& s, NormalMode& out) {
  for (NormalMode v : {NormalMode::Linear, NormalMode::Quadratic, NormalMode::QuadraticCorrected,
                       NormalMode::Analytic})
    if (s == to_string(v)) return out = v, true;
  return false;
}

}  // namespace tessref
