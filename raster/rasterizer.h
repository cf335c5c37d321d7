#pragma once
// Clipping, perspective divide, viewport, triangle setup and rasterization by GL's rules.
#include <algorithm>
#include <cstdint>
#include <optional>

#include "common/parallel.h"
#include "raster/fragment_ops.h"
#include "raster/framebuffer.h"
#include "raster/vertex.h"

namespace tessref {

struct FragmentInput {
  glm::vec4 frag_coord;  // gl_FragCoord: window x, y (pixel centers at .5), depth z, 1/w
  bool front_facing;     // gl_FrontFacing (CCW in window space is front)
  const float* varyings;  // TriangleBatch::num_varyings perspective-correct values
};

struct FragmentOutput {
  glm::vec4 color{0.0f};
  glm::vec4 aux{0.0f};
};

// Fragments in 2x2 quads, as structure of arrays: lane 4q + k is pixel (x + (k & 1), y + (k >> 1))
// of quad q, whose lower-left pixel (x, y) has even coordinates. A lane is live when its pixel is
// covered and passed the depth test; only live lanes' outputs are written. Other lanes hold no
// meaningful inputs (helper invocations, which derivatives need, are for a later program kind).
inline constexpr int kFragmentQuads = 16;
inline constexpr int kFragmentLanes = 4 * kFragmentQuads;
struct FragmentBatch {
  int quads = 0;
  int num_varyings = 0;
  alignas(32) float frag_coord[4][kFragmentLanes];  // gl_FragCoord x, y, z, 1/w
  alignas(32) float varyings[kMaxVaryings][kFragmentLanes];
  alignas(32) float color[4][kFragmentLanes];       // outputs: location 0
  alignas(32) float aux[4][kFragmentLanes];         // location 1
  alignas(32) float more[kMaxDrawBuffers - 2][4][kFragmentLanes];  // locations 2 to 7
  alignas(32) float frag_depth[kFragmentLanes];     // gl_FragDepth, when writes_depth()
  std::uint8_t live[kFragmentLanes];
  std::uint8_t front_facing[kFragmentLanes];
  int lanes() const { return 4 * quads; }
  // Channel c of the output at `location` (0 to kMaxDrawBuffers - 1).
  float* output(int location, int c) {
    return location == 0 ? color[c] : location == 1 ? aux[c] : more[location - 2][c];
  }
};

// A fragment shader: a plain struct with shade(); it runs on many threads at once, so it must not
// mutate shared state.
struct FragmentProgram {
  virtual ~FragmentProgram() = default;
  virtual FragmentOutput shade(const FragmentInput& in) const = 0;
  // What the rasterizer calls: a whole batch. The default runs shade() for each live lane; an
  // override (SIMD kernels, the GLSL executor) must give the same bits for live lanes.
  virtual void shade_batch(FragmentBatch& batch) const;
  // Whether shade_batch may clear a lane's live flag (GLSL discard). The rasterizer then tests
  // depth again and writes it only after shading, in arrival order.
  virtual bool may_discard() const { return false; }
  // Whether shade_batch writes gl_FragDepth (batch.frag_depth): the depth test then takes it, after
  // shading, instead of the interpolated depth.
  virtual bool writes_depth() const { return false; }
  // Whether shade_batch reads other lanes of a quad (derivatives). Only then do the lanes that
  // cover nothing need their own inputs (helper invocations); otherwise nothing can see them.
  virtual bool reads_quads() const { return false; }
  // Whether the two quads llvmpipe shades as one vector (4 x 2 pixels, aligned) must reach
  // shade_batch together, the one that covers nothing (or fails the depth test) as helper
  // invocations while the other has a live lane: llvmpipe runs every lane of such a vector, and
  // some texture lookups depend on all of them (Invocations::set_sampling_vectors).
  virtual bool shades_whole_vectors() const { return false; }
  // Whether shade_batch writes memory (storage blocks, atomics): every covered fragment must then
  // run it, those that will fail the depth test too (GL 4.6 14.9: the depth test follows the
  // shader), unless the shader asks for early_fragment_tests.
  virtual bool has_side_effects() const { return false; }
  virtual bool early_fragment_tests() const { return false; }
};

// glPolygonMode(GL_FRONT_AND_BACK, GL_FILL / GL_LINE / GL_POINT).
enum class PolygonMode { kFill, kLine, kPoint };

// glViewport's rectangle, in window pixels (y up from the bottom row).
struct ViewportRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// Where the vertices reaching the rasterizer carry gl_ClipDistance[] and gl_CullDistance[]: among
// their varyings, after the fragment shader's inputs, so that clipping interpolates them like any
// varying. clip_count, cull_count: the array sizes the last stage before the rasterizer writes.
// Without clip distances, glClipPlane's planes (compatibility profile) are tested against the
// clip vertex: the 4 varyings from clip_vertex_first (gl_ClipVertex), or gl_Position (-1).
struct DistanceVaryings {
  int clip_first = 0, clip_count = 0;
  int cull_first = 0, cull_count = 0;
  int clip_vertex_first = -1;
};

struct RasterState {
  // glEnable(GL_CULL_FACE) with glCullFace(GL_BACK) (and GL_FRONT: both set is GL_FRONT_AND_BACK);
  // front faces counter-clockwise in window space (glFrontFace(GL_CCW)) unless front_face_cw.
  bool cull_back_faces = false;
  bool cull_front_faces = false;
  bool front_face_cw = false;
  // glPolygonMode(GL_FRONT_AND_BACK, ...): triangles filled, or drawn as their edges or corners
  // (raster::setup_triangle_outline).
  PolygonMode polygon_mode = PolygonMode::kFill;
  // glEnable(GL_DEPTH_TEST) with glDepthFunc and glDepthMask; disabled: no test, no depth writes.
  bool depth_test = true;
  DepthFunc depth_func = DepthFunc::kLess;
  bool depth_write = true;
  ScissorState scissor;
  BlendState blend;
  ColorMask color_mask;
  // glEnable(GL_FRAMEBUFFER_SRGB): fragments written to SRGB8_ALPHA8 attachments are encoded
  // (and blending decodes what is there); without it those attachments act as RGBA8.
  bool framebuffer_srgb = false;
  // glEnable(GL_DEPTH_CLAMP) (GL 4.6 13.7.1): the near and far planes do not clip; the window z of
  // each fragment is clamped to the depth range instead.
  bool depth_clamp = false;
  // glEnable(GL_CLIP_DISTANCEi) (GL 4.6 13.7): bit i clips against gl_ClipDistance[i].
  std::uint8_t clip_distances = 0;
  // glClipPlane(GL_CLIP_PLANEi, ...) (compatibility profile), in the coordinates of the clip vertex:
  // used for an enabled plane when the program writes no gl_ClipDistance.
  std::array<glm::vec4, 8> clip_planes{};
  // The draw's program: where its vertices carry the distances (run_draw sets it).
  DistanceVaryings distances;
  // The enabled planes the program writes a gl_ClipDistance for (an enabled plane without one is
  // undefined in GL and does not clip).
  std::uint32_t clipping_distances() const {
    return clip_distances & ((1u << std::clamp(distances.clip_count, 0, 8)) - 1u);
  }
  // glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS) (GL 4.6 8.14.2): cube maps filtered across face edges.
  // Texture state rather than the rasterizer's, kept with the draw's other capabilities.
  bool cube_map_seamless = false;
  // glViewport(x, y, width, height); none: the whole framebuffer. glDepthRange(near, far), kept
  // as GL keeps it (a double).
  std::optional<ViewportRect> viewport;
  double depth_range_near = 0.0;
  double depth_range_far = 1.0;
};

// GL's initial state (every capability off, GL_LESS, depth writes on, GL_BACK, GL_CCW, GL_FILL):
// a scene's draw before its keys, and what the GL runner resets to. RasterState's own default
// has the depth test on, as the mesh path draws.
inline RasterState gl_initial_state() {
  RasterState r;
  r.depth_test = false;
  return r;
}

// Counts of primitives: triangles, or lines and points for draw_lines and draw_points.
struct RasterStats {
  std::uint64_t triangles_in = 0;
  std::uint64_t triangles_clipped_away = 0;  // wholly outside the view volume
  std::uint64_t triangles_culled = 0;        // back-facing or zero area
  std::uint64_t triangles_rasterized = 0;    // set up and scanned (after clipping: pieces count)
  std::uint64_t fragments_shaded = 0;        // passed the depth test and ran the fragment shader
  std::uint64_t fragments_depth_failed = 0;  // covered a pixel centre but failed the depth test
  RasterStats& operator+=(const RasterStats& o);
};

// Draws one batch into fb with state's culling, depth test, scissor, blending and colour mask
// (blending and the mask apply to every draw buffer fb has; output location k goes to draw buffer k). Several calls in a row behave as one draw of the
// concatenated batches. The framebuffer bytes do not depend on parallel.threads().
RasterStats draw_triangles(const TriangleBatch& batch, const RasterState& state,
                           const FragmentProgram& fs, Framebuffer& fb, const Parallel& parallel);

// GL_LINES (1 pixel wide, diamond-exit rule) and GL_POINTS (size 1), with llvmpipe's coverage
// (raster/line_setup.h); the same depth test, order and determinism as draw_triangles.
// state.cull_back_faces and polygon_mode do not apply (lines and points have no face).
RasterStats draw_lines(const LineBatch& batch, const RasterState& state, const FragmentProgram& fs,
                       Framebuffer& fb, const Parallel& parallel);
RasterStats draw_points(const PointBatch& batch, const RasterState& state,
                        const FragmentProgram& fs, Framebuffer& fb, const Parallel& parallel);

}  // namespace tessref
