#pragma once
// Seed 000's Figure 13, measured: the scene drawn twice, with 'fake' (quadratic, Vlachos et al.)
// and 'real' (analytic, du x dv) normals (tessellation.normal_mode), and compared pixel by pixel:
// the angle between the two fragments' normals (render --dump-fragments' N channels) where the
// same patch drew the pixel in both, and how many pixels' 8-bit colours differ. Seed 000 says the
// two "normal fields are the same" and that its difference image showed no difference.
#include <cstddef>

#include "common/parallel.h"
#include "io/image_output.h"
#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref::stats {

struct NormalModeDifference {
  NormalMode a = NormalMode::Quadratic, b = NormalMode::Analytic;
  std::size_t covered = 0;     // pixels drawn in either image
  std::size_t same_patch = 0;  // pixels drawn by the same patch in both (the angles' domain)
  double max_angle_deg = 0.0, mean_angle_deg = 0.0;  // over same_patch, summed in pixel order
  std::size_t angle_over_1deg = 0;  // same_patch pixels whose normals part by more than 1 degree
  std::size_t differing = 0;        // covered pixels whose 8-bit RGB differ in any channel
  int max_channel_difference = 0;   // in 8-bit steps
  // |colour a - colour b| * scale per channel (8-bit), top row first; background black.
  Rgb8Image image;
};

// Draws `scene` (its camera already fitted) with normal modes a and b; the rest of the scene as
// it is. InputError naming `option` when it does not tessellate with the built-in programs (the
// normal modes are theirs) or scale is not a positive finite number.
NormalModeDifference compare_normal_modes(const Scene& scene, const Mesh& mesh, NormalMode a,
                                          NormalMode b, double scale, const Parallel& parallel,
                                          const char* option);

}  // namespace tessref::stats
