#pragma once
// Captures what a real driver's tessellation primitive generator emits: for each patch (one level
// set each), gl_TessCoord of every vertex the TES produces, in emission order, bit for bit.
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "glref/draw_split.h"
#include "glref/gl_program.h"
#include "glref/glsl_rewrite.h"  // tes_layout_qualifier
#include "stages/tpg.h"

namespace tessref::glref {

class GlContext;

struct CaptureOptions {
  // Draws are split so that each generates at most this many domain points (upper bound): see
  // draw_split.h for the llvmpipe trap this avoids.
  std::size_t max_points_per_draw = kSafePointsPerDraw;
  std::size_t max_patches_per_draw = 16384;
  // Level sets uploaded at once; 0 = as many as GL_MAX_SHADER_STORAGE_BLOCK_SIZE allows (up to 2^20).
  std::size_t max_patches_per_upload = 0;
};

struct CaptureStats {
  std::size_t patches = 0;
  std::size_t draws = 0;
  std::size_t vertices = 0;  // captured (emitted) vertices
  double seconds = 0.0;      // wall time inside capture()
};

// Emitted vertices per primitive: 3 triangles (triangles and quads), 2 isolines, 1 point mode.
int vertices_per_primitive(const TessLayout& layout);
// Upper bound on the distinct domain points (TES invocations) one patch generates: 0 when the
// spec requires a discard (a relevant outer level <= 0 or NaN), else (m+1)^2 with m >= every
// relevant level after clamping and rounding up.
std::size_t domain_point_bound(const TessLayout& layout, const TessLevels& levels);
// Upper bound on the vertices one patch emits (what transform feedback captures).
std::size_t emitted_vertex_bound(const TessLayout& layout, const TessLevels& levels);

// Owns the GL objects and a program per layout; reuse one for many captures.
class TessCapture {
 public:
  explicit TessCapture(GlContext& context, const CaptureOptions& options = {});
  ~TessCapture();
  TessCapture(const TessCapture&) = delete;
  TessCapture& operator=(const TessCapture&) = delete;

  // result[i] = the gl_TessCoord of each vertex emitted for levels[i] (vec3 exactly as captured;
  // z is whatever the driver wrote: 0 for quads and isolines on llvmpipe). Empty when discarded.
  // Throws GlError on any GL error, a transform-feedback overflow or a vertex tagged with the
  // wrong patch.
  std::vector<std::vector<glm::vec3>> capture(const TessLayout& layout,
                                              const std::vector<TessLevels>& levels);
  const CaptureStats& last_stats() const { return stats_; }

 private:
  void capture_slice(const TessLayout& layout, const TessLevels* levels, std::size_t count,
                     std::vector<glm::vec3>* result);
  const Program& program_for(const TessLayout& layout);
  void ensure_buffer(unsigned target, unsigned buffer, std::size_t bytes, std::size_t& capacity);

  GlContext& context_;
  CaptureOptions options_;
  CaptureStats stats_;
  std::map<int, Program> programs_;  // keyed by packed layout
  unsigned vao_ = 0, level_buffer_ = 0, feedback_buffer_ = 0;
  unsigned query_generated_ = 0, query_written_ = 0;
  std::size_t level_capacity_ = 0, feedback_capacity_ = 0;
  std::size_t max_patches_per_upload_ = 1;
};

// One-shot convenience over TessCapture.
std::vector<std::vector<glm::vec3>> capture_tess_coords(GlContext& context, const TessLayout& layout,
                                                        const std::vector<TessLevels>& levels);

}  // namespace tessref::glref
