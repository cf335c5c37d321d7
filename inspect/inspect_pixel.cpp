#include "inspect/inspect_pixel.h"

#include <cstdio>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/error.h"
#include "inspect/fragment_tags.h"
#include "inspect/pixel_recorder.h"
#include "render/glsl_scene.h"
#include "render/render.h"
#include "inspect/tagged_draw.h"

namespace tessref {
namespace {

// The depth test LESS with writes, replayed in arrival order on the fragments' own depths (the
// values the rasterizer tested): which passed, and what each met.
std::optional<std::size_t> depth_verdicts(std::vector<PixelFragment>& fragments) {
  float stored = 1.0f;  // the cleared depth
  std::optional<std::size_t> writer;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    PixelFragment& f = fragments[i];
    f.depth_before = stored;
    f.depth_from = writer;
    f.passed = f.frag_coord.z < stored;
    if (!f.passed) continue;
    if (writer) fragments[*writer].hidden_by = i;
    stored = f.frag_coord.z;
    writer = i;
  }
  return writer;
}

}  // namespace

PixelInspectResult pixel_result_for(const Scene& scene, int x, int y) {
  if (x < 0 || y < 0 || x >= scene.width || y >= scene.height)
    throw InputError("--pixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") is off the " +
                     std::to_string(scene.width) + "x" + std::to_string(scene.height) + " image (X 0.." +
                     std::to_string(scene.width - 1) + ", Y 0.." + std::to_string(scene.height - 1) +
                     ", from the top row)");
  PixelInspectResult r;
  r.x = x;
  r.y = y;
  r.width = scene.width;
  r.height = scene.height;
  r.window_y = scene.height - 1 - y;
  return r;
}

PixelInspectResult inspect_pixel(const Scene& scene, const Mesh& mesh, int x, int y,
                                 const Parallel& parallel, bool trace) {
  PixelInspectResult r = pixel_result_for(scene, x, y);
  if (trace && scene.shaders.program == ShaderProgram::Builtin) {
    // The built-in C++ fragment program has no source lines: draw with its GLSL twins, which give
    // the same bytes, and show theirs.
    Scene twins = scene;
    twins.shaders.program = ShaderProgram::Twins;
    PixelInspectResult t = inspect_pixel(twins, mesh, x, y, parallel, true);
    PixelInspectResult plain = inspect_pixel(scene, mesh, x, y, parallel, false);
    if (t.fragments.size() != plain.fragments.size() || t.pixel_color != plain.pixel_color)
      throw std::logic_error("inspect --pixel --trace: the GLSL twins drew this pixel differently from the built-in programs");
    for (std::size_t i = 0; i < plain.fragments.size(); ++i) plain.fragments[i].trace = std::move(t.fragments[i].trace);
    plain.traced_twins = true;
    return plain;
  }
  // The scene's fragment program, as the draw builds it.
  std::optional<BuiltinFragmentProgram> builtin;
  SceneProgram glsl;
  std::shared_ptr<const FragmentProgram> glsl_fs;
  std::vector<shader::ShaderSource> sources;
  const shader::ShaderSource* fs_source = nullptr;
  if (scene.shaders.program == ShaderProgram::Builtin) {
    builtin.emplace(builtin_fragment_program(scene));
    r.program = scene.shading == Shading::Phong ? "builtin phong" : "builtin normals";
  } else {
    glsl = build_scene_program(scene);
    glsl_fs = glsl.program->fragment();
    r.program = scene.shaders.program == ShaderProgram::Twins ? "glsl twins (executor)" : "glsl custom (executor)";
    sources = scene_sources(scene);
    for (const shader::ShaderSource& src : sources)
      if (trace && src.stage == shader::Stage::Fragment) fs_source = &src;
  }
  PixelRecorder recorder(builtin ? builtin->get() : *glsl_fs, x, r.window_y, fs_source);
  TaggedRedraw redraw;
  redraw.depth_test = false;
  redraw.fs = &recorder;
  Framebuffer fb;
  draw_with_tagged_redraw(scene, mesh, parallel, fb, redraw, "--pixel");

  r.fragments = std::move(recorder.fragments);
  r.winner = depth_verdicts(r.fragments);
  const std::size_t idx = fb.index(x, r.window_y);
  r.pixel_color = fb.color[idx];
  r.pixel_depth = fb.depth[idx];
  // The replay must agree with the draw; if not, this tool is wrong, not the input.
  const bool agrees = r.winner ? r.fragments[*r.winner].color == r.pixel_color &&
                                     r.fragments[*r.winner].frag_coord.z == r.pixel_depth
                               : r.pixel_depth == 1.0f;
  if (!agrees) throw std::logic_error("inspect --pixel: the recorded fragments disagree with the draw's pixel");
  return r;
}

}  // namespace tessref
