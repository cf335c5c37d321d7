// Generates one patch, renders the default scene through the installed library and writes it as
// a PNG (argv[1]) through the installed image I/O module, then reads the image back.
#include <cstdio>
#include <string>

#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "stages/tpg.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer OUTPUT.png\n");
    return 2;
  }
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
  try {
    tessref::write_color_image(result.framebuffer, argv[1]);
    const tessref::Rgb8Image back = tessref::read_rgb8_image(argv[1]);
    if (back.pixels != tessref::to_rgb8(result.framebuffer).pixels) {
      std::fprintf(stderr, "%s: read back different pixels\n", argv[1]);
      return 1;
    }
    std::printf("image I/O module: %s\n", tessref::image_io_module_path().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("%zu triangles, %llu fragments\n", points.primitive_count(),
              static_cast<unsigned long long>(result.stats.raster.fragments_shaded));
  return points.primitive_count() == 37 && result.stats.raster.fragments_shaded > 0 ? 0 : 1;
}
