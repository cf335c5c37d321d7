#pragma once
// Coverage probe: triangles given in clip space drawn by the GL driver into an offscreen target,
// read back as, per pixel, the set of triangles that covered it and what the last one wrote.
// For comparing tessref's rasterizer with the driver's pixel for pixel.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace tessref::glref {

class GlContext;

// Triangle ids per draw: 8 float channels of additively blended powers of two, 24 bits each
// (float adds of distinct powers of two below 2^24 are exact).
inline constexpr int kProbeMaxTriangles = 192;

struct CoverageProbe {
  int width = 0, height = 0;
  // Per pixel (row 0 at the bottom): bit i of the 192-bit set is triangle i.
  std::vector<std::array<std::uint64_t, 3>> mask;
  // Per pixel: the last triangle (submission order) that wrote it, or -1, and that fragment's
  // gl_FragCoord (x, y, z).
  std::vector<int> last;
  std::vector<glm::vec3> frag_coord;
  std::vector<float> depth;  // the GL_DEPTH_COMPONENT32F buffer, cleared to 1
};

// Owns the program, buffers and a width x height target, reused across draws.
class CoverageProber {
 public:
  CoverageProber(GlContext& context, int width, int height);
  ~CoverageProber();
  CoverageProber(const CoverageProber&) = delete;
  CoverageProber& operator=(const CoverageProber&) = delete;

  // Clears, then draws consecutive vertex triples (gl_Position as given, viewport the whole
  // target, depth range [0, 1]) as GL_TRIANGLES, no culling, depth test with depth_func
  // (GL_LESS by default; 0 turns the test off). At most kProbeMaxTriangles primitives.
  // mode GL_LINES or GL_POINTS: vertex pairs or single vertices (1 pixel wide, size 1).
  // polygon_mode GL_LINE or GL_POINT (glPolygonMode for triangles): a triangle's edges may cover
  // a pixel twice, so only `last` and `frag_coord` are read back (mask stays empty).
  // Throws GlError on GL failure.
  CoverageProbe draw(const std::vector<glm::vec4>& clip_positions,
                     unsigned depth_func = 0x0201 /* GL_LESS */,
                     unsigned mode = 0x0004 /* GL_TRIANGLES */,
                     unsigned polygon_mode = 0x1B02 /* GL_FILL */);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tessref::glref
