#pragma once
// Point generation and connectivity per domain, on processed (clamped, rounded, 16.16) levels.
#include <cstdint>
#include <vector>

#include "stages/tpg_subdivide.h"

namespace tessref::tpg {

// A generated point in 16.16: (u, v); w = 1 - u - v for triangles.
struct FxPoint {
  Fx16 u, v;
};

struct DomainOutput {
  std::vector<FxPoint> points;
  std::vector<std::uint32_t> indices;  // triangles (3 each) or line segments (2 each)
};

struct TriangleLevels {
  Fx16 outer[3];
  Parity outer_parity[3];
  Fx16 inner;
  Parity inner_parity;
};
struct QuadLevels {
  Fx16 outer[4];
  Parity outer_parity[4];
  Fx16 inner[2];
  Parity inner_parity[2];
};
struct IsolineLevels {
  Fx16 density;  // number of lines (always integer, even or odd parity)
  Parity density_parity;
  Fx16 detail;   // segments per line, with the layout's spacing
  Parity detail_parity;
};

// with_connectivity = false fills points only (point mode).
void generate_triangles(const TriangleLevels& levels, bool reverse, bool with_connectivity,
                        DomainOutput& out);
void generate_quads(const QuadLevels& levels, bool reverse, bool with_connectivity,
                    DomainOutput& out);
void generate_isolines(const IsolineLevels& levels, bool with_connectivity, DomainOutput& out);

}  // namespace tessref::tpg
