#include "inspect/inspect_pixel.h"

#include <cstdio>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/error.h"
#include "inspect/fragment_tags.h"
#include "render/glsl_scene.h"
#include "render/render.h"
#include "inspect/tagged_draw.h"

namespace tessref {
namespace {

// Wraps the scene's fragment program in the tagged redraw (depth test off, so that every fragment
// at the pixel arrives, losers included): a batch with a lane at the pixel is shaded by the
// scene's program, and those lanes are kept; other batches are not shaded at all (their colours
// land only in the redraw's own framebuffer, which nobody reads).
class PixelRecorder final : public FragmentProgram {
 public:
  // source: the fragment shader's GLSL, to trace each fragment at the pixel (null: no trace).
  PixelRecorder(const FragmentProgram& inner, int x, int window_y, const shader::ShaderSource* source)
      : inner_(inner), cx_(float(x) + 0.5f), cy_(float(window_y) + 0.5f), source_(source) {}
  FragmentOutput shade(const FragmentInput& in) const override { return inner_.shade(in); }
  bool may_discard() const override { return inner_.may_discard(); }
  void shade_batch(FragmentBatch& b) const override {
    bool any = false;
    for (int l = 0; l < b.lanes(); ++l) any |= at_pixel(b, l);
    if (!any) return;
    inner_.shade_batch(b);
    std::lock_guard<std::mutex> lock(mutex_);  // one tile holds the pixel, but be safe
    for (int l = 0; l < b.lanes(); ++l) {  // lanes in arrival order (raster/tile_raster.h)
      if (!at_pixel(b, l)) continue;
      PixelFragment f;
      const int tags = b.num_varyings - kFragmentTagCount;  // they follow the draw's varyings
      const auto tag = [&](int k) { return b.varyings[tags + k][l]; };
      f.patch = std::size_t(tag(kTagPatch));
      f.triangle = std::size_t(tag(kTagTriangle));
      f.tess_coord = {tag(kTagTessU), tag(kTagTessV), tag(kTagTessW)};
      f.position = {tag(kTagPositionX), tag(kTagPositionY), tag(kTagPositionZ)};
      f.normal = {tag(kTagNormalX), tag(kTagNormalY), tag(kTagNormalZ)};
      f.frag_coord = {b.frag_coord[0][l], b.frag_coord[1][l], b.frag_coord[2][l], b.frag_coord[3][l]};
      f.front_facing = b.front_facing[l] != 0;
      f.color = {b.color[0][l], b.color[1][l], b.color[2][l], b.color[3][l]};
      for (int v = 0; v < tags; ++v) f.inputs.push_back(b.varyings[v][l]);
      if (source_) f.trace = trace_lane(b, l);
      fragments.push_back(f);
    }
  }
  mutable std::vector<PixelFragment> fragments;

 private:
  bool at_pixel(const FragmentBatch& b, int l) const {
    return b.live[l] && b.frag_coord[0][l] == cx_ && b.frag_coord[1][l] == cy_;
  }
  // The lane's 2x2 quad (derivatives difference its lanes) shaded again alone, tracing the lane.
  InspectTrace trace_lane(const FragmentBatch& b, int lane) const {
    auto quad = std::make_unique<FragmentBatch>();
    quad->quads = 1;
    quad->num_varyings = b.num_varyings;
    const int first = lane & ~3;
    for (int k = 0; k < 4; ++k) {
      for (int c = 0; c < 4; ++c) quad->frag_coord[c][k] = b.frag_coord[c][first + k];
      for (int v = 0; v < b.num_varyings; ++v) quad->varyings[v][k] = b.varyings[v][first + k];
      quad->live[k] = b.live[first + k];
      quad->front_facing[k] = b.front_facing[first + k];
    }
    char where[64];
    std::snprintf(where, sizeof where, "gl_FragCoord (%.9g, %.9g)", double(cx_), double(cy_));
    return run_traced(*source_, where, lane - first, [&] { inner_.shade_batch(*quad); });
  }
  const FragmentProgram& inner_;
  float cx_, cy_;
  const shader::ShaderSource* source_;
  mutable std::mutex mutex_;
};

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

PixelInspectResult inspect_pixel(const Scene& scene, const Mesh& mesh, int x, int y,
                                 const Parallel& parallel, bool trace) {
  if (x < 0 || y < 0 || x >= scene.width || y >= scene.height)
    throw InputError("--pixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") is off the " +
                     std::to_string(scene.width) + "x" + std::to_string(scene.height) + " image (X 0.." +
                     std::to_string(scene.width - 1) + ", Y 0.." + std::to_string(scene.height - 1) +
                     ", from the top row)");
  if (trace && scene.shaders.program == ShaderProgram::Builtin) {
    // The built-in C++ fragment program has no source lines: draw with its GLSL twins, which give
    // the same bytes, and show theirs.
    Scene twins = scene;
    twins.shaders.program = ShaderProgram::Twins;
    PixelInspectResult t = inspect_pixel(twins, mesh, x, y, parallel, true);
    PixelInspectResult r = inspect_pixel(scene, mesh, x, y, parallel, false);
    if (t.fragments.size() != r.fragments.size() || t.pixel_color != r.pixel_color)
      throw std::logic_error("inspect --pixel --trace: the GLSL twins drew this pixel differently from the built-in programs");
    for (std::size_t i = 0; i < r.fragments.size(); ++i) r.fragments[i].trace = std::move(t.fragments[i].trace);
    r.traced_twins = true;
    return r;
  }
  PixelInspectResult r;
  r.x = x;
  r.y = y;
  r.width = scene.width;
  r.height = scene.height;
  r.window_y = scene.height - 1 - y;
  // The scene's fragment program, as the draw builds it.
  std::optional<BuiltinFragmentProgram> builtin;
  SceneProgram glsl;
  std::unique_ptr<FragmentProgram> glsl_fs;
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
