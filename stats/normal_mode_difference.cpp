#include "stats/normal_mode_difference.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "common/error.h"
#include "inspect/fragment_dump.h"
#include "render/render.h"

namespace tessref::stats {
namespace {

constexpr std::size_t kDumpChannels = 12;  // kFragmentDumpChannels: P 0-2, N 3-5, patch_id 6

struct Drawn {
  Rgb8Image colour;    // top row first
  FragmentDump frags;  // GL rows
};

Drawn draw(Scene scene, const Mesh& mesh, NormalMode mode, const Parallel& parallel) {
  scene.tessellation.normal_mode = mode;
  Drawn d;
  d.colour = to_rgb8(render_scene(scene, mesh, parallel).framebuffer);
  d.frags = dump_fragments(scene, mesh, parallel);
  return d;
}

}  // namespace

NormalModeDifference compare_normal_modes(const Scene& scene, const Mesh& mesh, NormalMode a,
                                          NormalMode b, double scale, const Parallel& parallel,
                                          const char* option) {
  const std::string o(option);
  if (scene.shaders.program != ShaderProgram::Builtin || !scene.tessellation.enabled)
    throw InputError(o + ": needs a scene that tessellates with the built-in programs "
                     "(tessellation.enabled true, shaders.program builtin): the normal modes are theirs");
  if (!(std::isfinite(scale) && scale > 0.0))
    throw InputError("--difference-scale: must be a positive finite number (got " + std::to_string(scale) + ")");
  if (kFragmentDumpChannels.size() != kDumpChannels)
    throw std::logic_error("normal_mode_difference: the fragment dump's channels changed");
  NormalModeDifference r;
  r.a = a;
  r.b = b;
  const Drawn da = draw(scene, mesh, a, parallel), db = draw(scene, mesh, b, parallel);
  const int w = scene.width, h = scene.height;
  r.image = {w, h, std::vector<std::uint8_t>(std::size_t(w) * std::size_t(h) * 3, 0)};
  double angle_sum = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t gl = std::size_t(y) * std::size_t(w) + std::size_t(x);
      const float* fa = &da.frags.pixels[gl * kDumpChannels];
      const float* fb = &db.frags.pixels[gl * kDumpChannels];
      const bool in_a = fa[6] >= 0.0f, in_b = fb[6] >= 0.0f;
      if (!in_a && !in_b) continue;
      ++r.covered;
      const std::size_t top = (std::size_t(h - 1 - y) * std::size_t(w) + std::size_t(x)) * 3;
      bool differs = false;
      for (int k = 0; k < 3; ++k) {
        const int d = std::abs(int(da.colour.pixels[top + k]) - int(db.colour.pixels[top + k]));
        differs |= d != 0;
        r.max_channel_difference = std::max(r.max_channel_difference, d);
        r.image.pixels[top + k] = std::uint8_t(std::min(255.0, std::round(d * scale)));
      }
      r.differing += differs;
      if (!in_a || !in_b || fa[6] != fb[6]) continue;
      const glm::dvec3 na = glm::normalize(glm::dvec3(fa[3], fa[4], fa[5]));
      const glm::dvec3 nb = glm::normalize(glm::dvec3(fb[3], fb[4], fb[5]));
      // atan2 of |cross| and dot: accurate for small angles, where acos(dot) is not.
      const double deg = std::atan2(glm::length(glm::cross(na, nb)), glm::dot(na, nb)) * (180.0 / M_PI);
      if (!std::isfinite(deg)) continue;  // a zero normal: no direction to compare
      ++r.same_patch;
      angle_sum += deg;
      r.max_angle_deg = std::max(r.max_angle_deg, deg);
      r.angle_over_1deg += deg > 1.0;
    }
  if (r.same_patch) r.mean_angle_deg = angle_sum / double(r.same_patch);
  return r;
}

}  // namespace tessref::stats
