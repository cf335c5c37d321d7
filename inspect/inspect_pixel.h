#pragma once
// tessref inspect --pixel: every fragment the scene's draw made at one pixel, in the order the
// rasterizer made them, with its patch, triangle and gl_TessCoord, its fragment inputs, the
// fragment program's output and the depth test's verdict. The fragments come from the draw's own
// rasterizer and fragment program (inspect/tagged_draw.h): nothing is interpolated here.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "inspect/inspect_trace.h"
#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref {

struct PixelFragment {
  std::size_t patch = 0;     // gl_PrimitiveID
  std::size_t triangle = 0;  // within the patch, emission order (as inspect --patch numbers them)
  // What made it: a "triangle" (filled, or its edges and corners in polygon mode line or point),
  // a "line" or a "point" (GL_LINES and GL_POINTS and their strips, isolines, point mode); the
  // number above counts these.
  std::string primitive = "triangle";
  glm::vec3 tess_coord{0.0f};  // gl_TessCoord, interpolated from the triangle's corners' coordinates
  glm::vec4 frag_coord{0.0f};  // gl_FragCoord: window x, y (GL rows, from the bottom), depth, 1/w
  bool front_facing = true;
  glm::vec3 position{0.0f}, normal{0.0f};  // world position and normal (the fragment's inputs)
  std::vector<float> inputs;  // every interpolated varying the fragment program read
  glm::vec4 color{0.0f};  // the fragment program's output (location 0)
  // A scene of draws: the draw that made it, whether it came from a patch (else from an
  // untessellated triangle, numbered within its call's batch), and every output location's value.
  std::optional<std::size_t> draw;
  bool from_patch = true;
  std::vector<glm::vec4> outputs;
  std::optional<InspectTrace> trace;  // the fragment shader's source trace (asked for)
  // Depth test LESS as the draw applies it, in arrival order: the stored depth it met and which
  // fragment stored it (none: the cleared depth, 1).
  bool passed = false;
  float depth_before = 1.0f;
  std::optional<std::size_t> depth_from;
  std::optional<std::size_t> hidden_by;  // passed, then a later fragment passed over it
};

struct PixelInspectResult {
  int x = 0, y = 0;         // as asked: x right, y down from the image's top row
  int width = 0, height = 0;
  int window_y = 0;         // the GL window row (from the bottom): height - 1 - y
  std::string program;
  bool traced_twins = false;             // the built-in programs, traced through their GLSL twins
  std::vector<PixelFragment> fragments;  // arrival order
  std::optional<std::size_t> winner;     // the last to pass: its colour is the pixel's
  glm::vec4 pixel_color{0.0f};           // what the draw left in the framebuffer there
  float pixel_depth = 1.0f;
  std::vector<glm::vec4> pixel_outputs;  // a scene of draws: every draw buffer's value there
};

// The result's pixel and image fields for (x, y) (y down from the top row); InputError naming
// --pixel and the image size unless the pixel is on the image.
PixelInspectResult pixel_result_for(const Scene& scene, int x, int y);

// Runs the scene's draw (the camera already fitted, as render does). InputError naming --pixel
// and the image size for a pixel off the image, or for a scene that does not tessellate.
// trace: each fragment's fragment shader traced at source level (its 2x2 quad shaded again alone
// on the executor); the built-in programs are traced by drawing the scene with their GLSL twins,
// which must leave the same pixel (logic_error otherwise).
PixelInspectResult inspect_pixel(const Scene& scene, const Mesh& mesh, int x, int y,
                                 const Parallel& parallel, bool trace = false);

// The same for a scene of draws: every draw's filled triangles (tessellated or not) redrawn
// tagged with depth test, blending and masks off, so that every fragment at the pixel arrives;
// then GL's per-fragment operations replayed there in order (each draw's clear, depth test and
// write in the depth buffer's format, blending and masks in each draw buffer's), which must leave
// what the draw left (logic_error otherwise). InputError for a draw of lines or points (GL_LINES,
// GL_POINTS, polygon mode line or point, isolines, point mode): their fragments are not followed.
PixelInspectResult inspect_draws_pixel(const Scene& scene, int x, int y, const Parallel& parallel, bool trace = false);

}  // namespace tessref
