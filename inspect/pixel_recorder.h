#pragma once
// The fragment program of a tagged redraw (inspect/tagged_draw.h) that keeps the fragments at one
// pixel: a batch with a lane there is shaded by the draw's own program, and those lanes' inputs,
// tags and outputs are kept in arrival order; other batches are not shaded at all (their colours
// would land only in the redraw's framebuffer, which nobody reads).
#include <mutex>
#include <vector>

#include "inspect/inspect_pixel.h"
#include "raster/rasterizer.h"
#include "shader/source_trace.h"

namespace tessref {

class PixelRecorder final : public FragmentProgram {
 public:
  // source: the fragment shader's GLSL, to trace each fragment at the pixel (null: no trace).
  // outputs: how many output locations to keep per fragment (1 keeps colour alone).
  PixelRecorder(const FragmentProgram& inner, int x, int window_y, const shader::ShaderSource* source,
                int outputs = 1);
  FragmentOutput shade(const FragmentInput& in) const override { return inner_->shade(in); }
  bool may_discard() const override { return inner_->may_discard(); }
  bool reads_quads() const override { return inner_->reads_quads(); }
  void shade_batch(FragmentBatch& b) const override;
  // A scene of draws: the program and source of the draw being redrawn, and its index.
  void set_draw(const FragmentProgram& inner, const shader::ShaderSource* source, std::size_t draw);

  mutable std::vector<PixelFragment> fragments;

 private:
  bool at_pixel(const FragmentBatch& b, int l) const {
    return b.live[l] && b.frag_coord[0][l] == cx_ && b.frag_coord[1][l] == cy_;
  }
  // The lane's 2x2 quad (derivatives difference its lanes) shaded again alone, tracing the lane.
  InspectTrace trace_lane(const FragmentBatch& b, int lane) const;
  const FragmentProgram* inner_;
  float cx_, cy_;
  const shader::ShaderSource* source_;
  int outputs_;
  std::optional<std::size_t> draw_;
  mutable std::mutex mutex_;
};

}  // namespace tessref
