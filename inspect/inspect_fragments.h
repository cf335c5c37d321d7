#pragma once
// tessref inspect --patch N: the fragments the patch became. The scene is drawn as render draws
// it, with the tagged redraw (tagged_draw.h) telling every fragment its patch, triangle and
// gl_TessCoord; the patch's fragments are kept, and those whose depth is the pixel's final depth
// are the ones the image shows.
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref {

struct PatchFragment {
  int x = 0, y = 0;  // y down from the image's top row, as --pixel takes it
  std::size_t triangle = 0;
  glm::vec3 tess_coord{0.0f};
  float depth = 1.0f;
  bool visible = false;  // its depth is what the draw left at the pixel
};

struct PatchFragments {
  std::size_t count = 0, visible = 0;
  int min_x = 0, min_y = 0, max_x = -1, max_y = -1;  // the pixels they cover (empty: max < min)
  std::vector<std::size_t> per_triangle;              // fragments per triangle of the patch
  // The fragment nearest `near` in gl_TessCoord (visible ones first), if any.
  std::optional<PatchFragment> nearest;
};

// Draws the scene (camera already fitted) and gathers patch `patch`'s fragments. `near`: the
// coordinate whose nearest fragment to report (none: the patch's centre).
PatchFragments patch_fragments(const Scene& scene, const Mesh& mesh, std::size_t patch,
                               std::size_t triangles, const std::optional<glm::vec3>& near,
                               const Parallel& parallel);

}  // namespace tessref
