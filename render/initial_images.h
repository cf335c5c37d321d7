#pragma once
// A scene of draws' framebuffer (scene key `framebuffer`): its attachments' formats and the
// images they hold before the first draw, as rows from the bottom (GL's window order). What
// render starts its framebuffer from and the GL runner uploads.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "raster/framebuffer.h"
#include "scene/scene.h"

namespace tessref {

struct InitialPixels {
  // Per colour attachment: the values it holds (converted to its format), or none (the background).
  std::vector<std::optional<std::vector<glm::vec4>>> color;
  std::optional<std::vector<float>> depth;  // converted to the depth format
};

// InputError naming framebuffer.color.K / framebuffer.depth for a file that cannot be read, of
// another size than the image, or (depth) with a value outside [0, 1] or not a number.
InitialPixels load_initial_images(const Scene& scene);

// Gives fb (already the image's size) the scene's attachments and formats, every colour
// attachment the background (glClear of a new framebuffer), then the initial images.
void set_up_framebuffer(const Scene& scene, const InitialPixels& images, Framebuffer& fb);

}  // namespace tessref
