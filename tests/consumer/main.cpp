// Generates one patch and renders the default scene through the installed library.
#include <cstdio>

#include "pipeline/mesh_source.h"
#include "pipeline/render.h"
#include "pipeline/scene_loader.h"
#include "stages/tpg.h"

int main() {
  tessref::TessLevels levels;
  levels.outer = {4, 4, 4, 0};
  levels.inner = {4, 0};
  const tessref::TessLayout layout{tessref::TessDomain::Triangles,
                                   tessref::TessSpacing::FractionalOdd, tessref::TessWinding::Ccw,
                                   false};
  const auto points = tessref::generate_tessellation(layout, levels);
  tessref::Scene scene = tessref::load_scene("", {"image.width=64", "image.height=64"});
  std::vector<std::string> warnings;
  const auto result =
      tessref::render_scene(scene, tessref::build_mesh(scene.mesh, warnings), tessref::Parallel(1));
  std::printf("%zu triangles, %llu fragments\n", points.primitive_count(),
              static_cast<unsigned long long>(result.stats.raster.fragments_shaded));
  return points.primitive_count() == 37 && result.stats.raster.fragments_shaded > 0 ? 0 : 1;
}
