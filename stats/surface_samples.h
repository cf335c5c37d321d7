#pragma once
// The exact surface behind every pixel of a drawn scene: the draw's winning fragment names its
// patch and gl_TessCoord (render --dump-fragments, inspect/fragment_dump.h), and the scheme's
// Bézier net (stages/schemes/bezier_nets.h) is evaluated there, in double, for the position, the
// analytic normal and the Gaussian curvature. Surface images (surface_images.h) colour these.
// Each pixel is computed on its own into its own slot: nothing depends on the thread count.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "stages/schemes/bezier_nets.h"

namespace tessref::stats {

struct SurfaceSample {
  bool covered = false;       // a fragment of the draw won this pixel
  std::uint32_t patch = 0;    // gl_PrimitiveID: the mesh triangle
  glm::dvec3 tess_coord{0.0}; // gl_TessCoord, the weights of the patch's corners 0, 1, 2
  glm::dvec3 position{0.0};   // the exact surface point s(u, v), world space
  // normalize(du x dv), turned to the side of the fragment's own normal (a mesh's winding does
  // not always agree with its normals); zero where du x dv vanishes.
  glm::dvec3 normal{0.0};
  // The fragment's own normal, normalized: the draw's normal field (tessellation.normal_mode)
  // interpolated across its tessellated triangle.
  glm::dvec3 fragment_normal{0.0};
  double gaussian_curvature = 0.0;  // NaN where du x dv vanishes
  // |s(u, v) - the fragment's world position|: the fragment's position is interpolated across a
  // tessellated triangle, so this is the tessellation's chord error there (0 at its vertices). A
  // wrong patch or coordinate mapping would show as deviations of the patch's size.
  double position_deviation = 0.0;
};

struct SurfaceSamples {
  int width = 0, height = 0;
  std::vector<SurfaceSample> pixels;  // GL rows (row 0 at the bottom)
  glm::dvec3 eye{0.0};     // the camera's position (world)
  glm::dvec3 centre{0.0};  // the world-space mesh's bounding box centre
  double radius = 0.0;     // the largest distance of a world-space vertex from centre
};


// The scheme's patch of every mesh triangle as the draw builds it: corners and normals through
// the scene's vertex shader (world space, float), normals normalized as the control programs do,
// the nets in float as they compute them. Flat: the triangle itself (Phong with alpha 0).
std::vector<schemes::CubicNet<float>> world_patches(const Scene& scene, const Mesh& mesh,
                                                    const Parallel& parallel);

// Draws the scene (its camera already fitted) and samples the exact surface at every pixel.
// InputError naming `option` when the scene's surface is not one Bézier net per patch: GLSL
// programs (shaders.program), Scalar Tagged PN, displacement, or no tessellation.
SurfaceSamples sample_surface(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                              const char* option);

}  // namespace tessref::stats
