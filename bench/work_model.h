#pragma once
// The work model behind the "share of the machine's limit" figures (scripts/bench.sh, bench/README.md):
// for each kind of item, the bytes that must reach memory and the fp32 flops that must be computed,
// as an implementation that did only the necessary work would pay them. Both sides of a comparison
// are credited the same work (tessref's counts for the same draw). A figure's share of a limit is
// (model bytes / time) / bandwidth or (model flops / time) / peak FMA rate, whichever is larger:
// that limit "binds" it. An FMA counts as 2 flops, a divide or square root as 1.
#include <cstdint>

namespace tessref::bench::work {

// One PN-triangle vertex (TES invocation), quadratic normals (stages/schemes/pn_triangles.cpp):
//   position: 20 products for the 10 cubic Bernstein weights + 10 control points x 3 FMAs = 80;
//   normal:   6 quadratic terms x 3 FMAs (weights shared with the position) + normalize (10) = 46;
//   gl_Position = view_proj * (p, 1): 12 FMAs = 24.
inline constexpr double kPnVertexFlops = 150;
// What a TES invocation hands to the rasterizer: one ClipVertex (raster/vertex.h: vec4 position and
// 12 float varyings), and 3 32-bit indices per triangle, written once.
inline constexpr double kClipVertexBytes = 64;
inline constexpr double kTriangleIndexBytes = 12;

// The primitive generator alone (bench/tpg_bench.cpp): per domain point its gl_TessCoord (vec3)
// and ~6 flops (the fractional-spacing interpolation), per triangle 3 indices. One patch's output
// (level 64: 3,169 points) stays in L2, so it is compared with the in-cache write rate.
inline constexpr double kTpgPointBytes = 12;
inline constexpr double kTpgPointFlops = 6;

// Rasterization of a clip-space triangle (bench/raster_bench.cpp): read 3 vec4 positions (48 B);
// setup ~60 flops (3 perspective divides, viewport transform, 3 edge functions, area, depth
// plane); per covered fragment ~8 flops (3 edge steps, depth interpolation, test).
inline constexpr double kRasterTriangleBytes = 48;
inline constexpr double kRasterTriangleFlops = 60;
inline constexpr double kFragmentFlops = 8;
// Phong fragment of the scenes: perspective-correct interpolation of 6 varyings (~30),
// normalizations of N, L and V (30), the diffuse and specular terms with pow (~45), colors (15).
inline constexpr double kPhongFragmentFlops = 120;
// Per pixel of the target, cleared and written back once: RGBA32F color + 32-bit depth; the
// scenes' frames also hold RGBA32F normals.
inline constexpr double kPixelBytesColorDepth = 20;
inline constexpr double kPixelBytesFrame = 36;

struct Work {
  double items = 0;  // what the figure counts (vertices, points, triangles; 1 for a frame)
  double bytes = 0;
  double flops = 0;
};

// PN tessellation: TES invocations and triangles out.
inline Work pn_tessellation(std::uint64_t domain_points, std::uint64_t triangles) {
  return {double(domain_points),
          kClipVertexBytes * double(domain_points) + kTriangleIndexBytes * double(triangles),
          kPnVertexFlops * double(domain_points)};
}

inline Work tpg(std::uint64_t points, std::uint64_t triangles) {
  return {double(points), kTpgPointBytes * double(points) + kTriangleIndexBytes * double(triangles),
          kTpgPointFlops * double(points)};
}

inline Work raster(std::uint64_t triangles, std::uint64_t fragments, std::uint64_t pixels) {
  return {double(triangles),
          kRasterTriangleBytes * double(triangles) + kPixelBytesColorDepth * double(pixels),
          kRasterTriangleFlops * double(triangles) + kFragmentFlops * double(fragments)};
}

// A PN-tessellated, Phong-shaded frame.
inline Work frame(std::uint64_t domain_points, std::uint64_t triangles, std::uint64_t fragments,
                  std::uint64_t pixels) {
  const Work t = pn_tessellation(domain_points, triangles);
  return {1.0, t.bytes + kPixelBytesFrame * double(pixels),
          t.flops + kRasterTriangleFlops * double(triangles) +
              (kFragmentFlops + kPhongFragmentFlops) * double(fragments)};
}

}  // namespace tessref::bench::work
