#pragma once
// What tessref draws for a scene of draws, in the form `tessref verify` compares with a capture:
// nothing is read from the user's outputs but gl_Position and gl_TessCoord. Surfaces are in
// normalized device coordinates with z toward the viewer, (x/w, y/w, -z/w), where the rays of
// every pixel are parallel; a triangle with a corner at w <= 0 is left out of them.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/draw.h"
#include "render/draw_scene.h"
#include "scene/scene.h"
#include "verify/surface.h"

namespace tessref {

struct DrawnSurfaces {
  // Every evaluation shader record in patch order, gl_Position kept as a capture keeps it
  // (io/tess_dump.h as_clip_records), and the vertices emitted as indices into them.
  std::vector<TessDumpRecord> tess;
  std::vector<std::uint32_t> emitted;
  // The patch ids of the tessellated triangles (triangles and quads domains).
  std::vector<bool> triangle_patch;
  TessSurface tessellated;  // the evaluation shaders' triangles
  TessSurface triangles;    // and the untessellated draws' triangles: what the depth image shows
  std::uint64_t behind_eye = 0;  // triangles left out (a corner at w <= 0)
  // Empty when the depth image is the union of `triangles` (every draw that writes depth draws
  // filled triangles unscissored with a test that passes over the clear depth, all culled alike);
  // else why the silhouette cannot be compared. Set by finish_observing.
  std::string silhouette_unavailable;
  bool cull_back = false;  // the culling the silhouette's rays apply

  // While drawing: the draw being drawn, which draws write depth, which emitted lines or points.
  std::size_t draw = 0;
  std::vector<bool> writes_depth, lines_or_points;
  std::vector<bool> user_clipped;  // clipped against a user plane or culled by a cull distance
};

// The point of a clip-space position in the surfaces' space.
glm::vec3 surface_point(const glm::vec4& clip);

// Sets the options' observers so that drawing the scene fills `out`; only the triangles of draws
// that write depth join out.triangles. finish_observing after the draw.
void observe_draws(const Scene& scene, const std::vector<std::vector<CallPatches>>& numbering, DrawOptions& options,
                   DrawnSurfaces& out);
void finish_observing(const Scene& scene, DrawnSurfaces& out);

// A capture's emitted records (as_clip_records form) of the patches marked in triangle_patch, as a
// surface in the same space.
TessSurface captured_triangles(const std::vector<TessDumpRecord>& emitted, const std::vector<bool>& triangle_patch);

}  // namespace tessref
