#include "inspect/pixel_recorder.h"

#include <cstdio>
#include <memory>

#include "inspect/fragment_tags.h"

namespace tessref {

PixelRecorder::PixelRecorder(const FragmentProgram& inner, int x, int window_y, const shader::ShaderSource* source,
                             int outputs)
    : inner_(&inner), cx_(float(x) + 0.5f), cy_(float(window_y) + 0.5f), source_(source), outputs_(outputs) {}

void PixelRecorder::set_draw(const FragmentProgram& inner, const shader::ShaderSource* source, std::size_t draw) {
  inner_ = &inner;
  source_ = source;
  draw_ = draw;
}

void PixelRecorder::shade_batch(FragmentBatch& b) const {
  bool any = false;
  for (int l = 0; l < b.lanes(); ++l) any |= at_pixel(b, l);
  if (!any) return;
  inner_->shade_batch(b);
  std::lock_guard<std::mutex> lock(mutex_);  // one tile holds the pixel, but be safe
  for (int l = 0; l < b.lanes(); ++l) {  // lanes in arrival order (raster/tile_raster.h)
    if (!at_pixel(b, l)) continue;  // not there, or discarded by the program
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
    f.draw = draw_;
    if (draw_)
      for (int k = 0; k < outputs_; ++k)
        f.outputs.emplace_back(b.output(k, 0)[l], b.output(k, 1)[l], b.output(k, 2)[l], b.output(k, 3)[l]);
    for (int v = 0; v < tags; ++v) f.inputs.push_back(b.varyings[v][l]);
    if (source_) f.trace = trace_lane(b, l);
    fragments.push_back(f);
  }
}

InspectTrace PixelRecorder::trace_lane(const FragmentBatch& b, int lane) const {
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
  return run_traced(*source_, where, lane - first, [&] { inner_->shade_batch(*quad); });
}

}  // namespace tessref
