#include "scene/tessellation_settings.h"

namespace tessref {

const char* to_string(SurfaceScheme s) {
  switch (s) {
    case SurfaceScheme::Flat: return "flat";
    case SurfaceScheme::PN: return "pn";
    case SurfaceScheme::Phong: return "phong";
    case SurfaceScheme::NLSA: return "nlsa";
    case SurfaceScheme::Nagata: return "nagata";
    case SurfaceScheme::ScalarTaggedPN: return "scalar_tagged_pn";
  }
  return "?";
}

SchemeTwins scheme_twins(SurfaceScheme s) {
  switch (s) {
    case SurfaceScheme::Flat: return {"flat.tesc", "flat.tese"};
    case SurfaceScheme::PN: return {"pn_triangles.tesc", "pn_triangles.tese"};
    case SurfaceScheme::Phong: return {"phong.tesc", "quadratic_patch.tese"};
    case SurfaceScheme::NLSA: return {"nlsa.tesc", "quadratic_patch.tese"};
    case SurfaceScheme::Nagata: return {"nagata.tesc", "quadratic_patch.tese"};
    case SurfaceScheme::ScalarTaggedPN: return {"scalar_tagged_pn.tesc", "pn_triangles.tese"};
  }
  return {"flat.tesc", "flat.tese"};
}

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
  for (SurfaceScheme v : {SurfaceScheme::Flat, SurfaceScheme::PN, SurfaceScheme::Phong,
                          SurfaceScheme::NLSA, SurfaceScheme::Nagata, SurfaceScheme::ScalarTaggedPN})
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
