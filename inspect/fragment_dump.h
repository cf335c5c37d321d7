#pragma once
// render --dump-fragments FILE.exr: the winning fragment's inputs at every pixel, one float
// channel each, from the tagged redraw (inspect/tagged_draw.h) with the scene's depth test, so
// that each pixel's last fragment to pass is the one whose colour the image holds.
#include <filesystem>
#include <string>
#include <vector>

#include "common/parallel.h"
#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref {

// Channel names in file order. Where nothing was drawn: patch_id and triangle -1, the rest NaN.
// triangle: within the patch, emission order (as inspect --patch numbers them).
inline const std::vector<std::string> kFragmentDumpChannels = {
    "P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "patch_id", "triangle",
    "tess_coord.u", "tess_coord.v", "tess_coord.w", "depth"};

struct FragmentDump {
  int width = 0, height = 0;
  std::vector<float> pixels;  // channels interleaved, GL rows (row 0 at the bottom)
};

// Draws the scene (the camera already fitted) and keeps each pixel's winning fragment.
// InputError when the scene does not tessellate.
FragmentDump dump_fragments(const Scene& scene, const Mesh& mesh, const Parallel& parallel);

// Checks that FILE can hold the channels (a float format with enough channels: .exr), draws and
// writes it top row first. InputError naming --dump-fragments.
void write_fragment_dump(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                         const std::filesystem::path& path);

}  // namespace tessref
