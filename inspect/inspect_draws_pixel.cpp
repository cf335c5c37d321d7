// tessref inspect --pixel on a scene of draws (inspect/inspect_pixel.h): the fragments of every
// draw at one pixel, and GL's per-fragment operations replayed there.
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "common/error.h"
#include "inspect/fragment_tags.h"
#include "inspect/inspect_pixel.h"
#include "inspect/pixel_recorder.h"
#include "inspect/tagged_draw.h"
#include "render/draw_scene.h"
#include "render/initial_images.h"
#include "render/render.h"

namespace tessref {
namespace {

// The recorder's program until the first draw names its own (never shaded: no batch comes first).
struct NoProgram final : FragmentProgram {
  FragmentOutput shade(const FragmentInput&) const override { return {}; }
};

// The draw's state for the tagged redraw: the same coverage (viewport, scissor, culling, clipping,
// depth range and clamp), but no depth test, writes or blending, so that every fragment arrives.
RasterState redraw_state(const RasterState& s) {
  RasterState r = s;
  r.depth_test = false;
  r.depth_write = false;
  r.blend.enabled = false;
  r.color_mask = ColorMask{};
  return r;
}

bool inside_scissor(const ScissorState& s, int x, int y) {
  return !s.enabled || (x >= s.x && x < s.x + s.width && y >= s.y && y < s.y + s.height);
}

// GL 4.6 chapter 17 at one pixel, draw by draw: the clear, then each fragment in arrival order
// through the depth test and write (in the depth buffer's format), blending and the colour mask
// (in each draw buffer's). Fills each fragment's verdict; returns the last fragment that wrote.
std::optional<std::size_t> replay(const Scene& scene, const Framebuffer& initial, std::size_t idx, int x, int y,
                                  std::vector<PixelFragment>& fragments, std::vector<glm::vec4>& colors, float& depth) {
  const int buffers = int(colors.size());
  for (int k = 0; k < buffers; ++k) colors[std::size_t(k)] = (*initial.draw_buffer(k))[idx];
  depth = initial.depth[idx];
  std::optional<std::size_t> writer;      // the fragment whose depth is stored (none: cleared or initial)
  std::optional<std::size_t> last_color;  // the last fragment that wrote colour
  std::size_t next = 0;
  for (std::size_t d = 0; d < scene.draws.size(); ++d) {
    const DrawSetting& draw = scene.draws[d];
    const RasterState& s = draw.raster;
    if ((draw.clear_color || draw.clear_depth) && inside_scissor(s.scissor, x, y)) {
      if (draw.clear_color)
        for (int k = 0; k < buffers; ++k)
          colors[std::size_t(k)] = s.color_mask.apply(
              stored_color(initial.color_format[std::size_t(k)], s.framebuffer_srgb, *draw.clear_color), colors[std::size_t(k)]);
      if (draw.clear_depth && s.depth_write) {
        depth = stored_depth(initial.depth_format, float(*draw.clear_depth));
        writer.reset();
      }
    }
    for (; next < fragments.size() && fragments[next].draw == d; ++next) {
      PixelFragment& f = fragments[next];
      f.depth_before = depth;
      f.depth_from = writer;
      if (s.depth_test) {
        float z = f.frag_coord.z;
        if (s.depth_clamp)  // before the test (raster/tile_raster.h)
          z = std::clamp(z, float(std::min(s.depth_range_near, s.depth_range_far)),
                         float(std::max(s.depth_range_near, s.depth_range_far)));
        z = stored_depth(initial.depth_format, z);
        f.passed = depth_passes(s.depth_func, z, depth);
        if (!f.passed) continue;
        if (s.depth_write) {
          depth = z;
          writer = next;
        }
      } else {
        f.passed = true;  // no test, and no depth written (GL 4.6 17.3.4)
      }
      for (int k = 0; k < buffers; ++k) {
        glm::vec4& stored = colors[std::size_t(k)];
        const ColorFormat format = initial.color_format[std::size_t(k)];
        const glm::vec4 c = s.blend.enabled ? blended_color(format, s.framebuffer_srgb, s.blend, f.outputs[std::size_t(k)], stored)
                                            : stored_color(format, s.framebuffer_srgb, f.outputs[std::size_t(k)]);
        stored = s.color_mask.apply(c, stored);
      }
      if (last_color) fragments[*last_color].hidden_by = next;
      last_color = next;
    }
  }
  return last_color;
}

}  // namespace

PixelInspectResult inspect_draws_pixel(const Scene& scene, int x, int y, const Parallel& parallel, bool trace) {
  PixelInspectResult r = pixel_result_for(scene, x, y);
  refuse_geometry_shaders(scene, "--pixel");
  r.program = "glsl, each draw's program (executor)";
  // The fragment shaders' sources, per draw, for --trace.
  std::vector<std::vector<shader::ShaderSource>> sources(scene.draws.size());
  if (trace) {
    SceneDraws programs(scene);
    for (std::size_t d = 0; d < scene.draws.size(); ++d) sources[d] = programs.sources(d);
  }
  const auto fragment_source = [&](std::size_t d) -> const shader::ShaderSource* {
    for (const shader::ShaderSource& s : sources[d])
      if (s.stage == shader::Stage::Fragment) return &s;
    return nullptr;
  };

  const int buffers = int(scene.framebuffer.color.size());
  const NoProgram none;
  PixelRecorder recorder(none, x, r.window_y, nullptr, buffers);
  Framebuffer scratch;  // the redraw's: nobody reads it
  scratch.reset(scene.width, scene.height, scene.background, parallel);
  std::size_t draw = 0;
  std::uint32_t primitives_in_draw = 0;  // untessellated primitives so far, numbering them
  RasterState state;
  DrawOptions options;
  options.begin_draw = [&](std::size_t d) {
    draw = d;
    primitives_in_draw = 0;
    state = redraw_state(scene.draws[d].raster);
  };
  options.fragment_program = [&](const FragmentProgram& fs) {
    // The tagged redraw shades the draw's fragments a second time: side effects would happen
    // twice and the outputs that depend on them would differ from the draw's.
    if (fs.has_side_effects())
      throw InputError("draws." + std::to_string(draw) + ": inspect --pixel shades a draw's fragments again to record "
                       "them, and this fragment shader writes memory (storage blocks, images or atomics), which "
                       "would happen twice; tessref does not replay side effects (render --storage-buffers and "
                       "--images show what they left)");
    recorder.set_draw(fs, fragment_source(draw), draw);
  };
  options.tess_surface = [&](const std::vector<TessDumpRecord>& records, const TriangleBatch& batch) {
    draw_triangles(tagged_triangles(records, batch), state, recorder, scratch, parallel);
  };
  // Fragments recorded since `before` came from `primitive`s, untessellated ones numbered in the
  // draw (calls and instances in order) rather than within a patch.
  const auto name_fragments = [&](std::size_t before, const char* primitive, bool from_patch) {
    for (std::size_t i = before; i < recorder.fragments.size(); ++i) {
      PixelFragment& f = recorder.fragments[i];
      f.primitive = primitive;
      if (from_patch) continue;
      f.from_patch = false;
      f.triangle = f.patch;
      f.patch = 0;
    }
  };
  options.untessellated_triangles = [&](const TriangleBatch& batch) {
    // Each triangle tagged as a "patch" of its own: its number in the draw.
    std::vector<TessDumpRecord> records(batch.vertices.size() / std::size_t(batch.records()));
    for (std::size_t v = 0; v < records.size(); ++v) records[v].patch_id = primitives_in_draw + std::uint32_t(v / 3);
    primitives_in_draw += std::uint32_t(records.size() / 3);
    const std::size_t before = recorder.fragments.size();
    draw_triangles(tagged_triangles(records, batch), state, recorder, scratch, parallel);
    name_fragments(before, "triangle", false);
  };
  // Lines and points: tessellated ones numbered within their patch, the others in the draw.
  const auto lines_or_points = [&](const auto& batch, const std::vector<TessDumpRecord>* records,
                                   const std::vector<std::uint32_t>* emitted) {
    constexpr bool lines = std::decay_t<decltype(batch)>::kCorners == 2;
    const std::size_t before = recorder.fragments.size();
    if constexpr (lines)
      draw_lines(tagged_lines(batch, records, emitted, primitives_in_draw), state, recorder, scratch, parallel);
    else
      draw_points(tagged_points(batch, records, emitted, primitives_in_draw), state, recorder, scratch, parallel);
    if (!records) primitives_in_draw += std::uint32_t(batch.primitive_count());
    name_fragments(before, lines ? "line" : "point", records != nullptr);
  };
  options.line_batch = lines_or_points;
  options.point_batch = lines_or_points;
  Framebuffer fb;
  render_scene(scene, Mesh{}, parallel, fb, options);

  r.fragments = std::move(recorder.fragments);
  Framebuffer initial(scene.width, scene.height, scene.background);
  set_up_framebuffer(scene, load_initial_images(scene), initial);
  const std::size_t idx = fb.index(x, r.window_y);
  std::vector<glm::vec4> colors(static_cast<std::size_t>(buffers));
  float depth = 1.0f;
  r.winner = replay(scene, initial, idx, x, r.window_y, r.fragments, colors, depth);
  for (int k = 0; k < buffers; ++k) r.pixel_outputs.push_back((*fb.draw_buffer(k))[idx]);
  r.pixel_color = r.pixel_outputs.at(0);
  r.pixel_depth = fb.depth[idx];
  // The replay must leave what the draw left; if not, this tool is wrong, not the input.
  if (colors != r.pixel_outputs || depth != r.pixel_depth)
    throw std::logic_error("inspect --pixel: the per-fragment operations replayed at the pixel disagree with the draw");
  return r;
}

}  // namespace tessref
