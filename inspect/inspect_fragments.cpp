#include "inspect/inspect_fragments.h"

#include <algorithm>
#include <mutex>
#include <tuple>

#include "inspect/fragment_tags.h"
#include "inspect/tagged_draw.h"

namespace tessref {
namespace {

// Sees every fragment of the tagged redraw (depth test off) and keeps the patch's. Nothing is
// shaded: only coverage, depth and tags are asked.
class PatchRecorder final : public FragmentProgram {
 public:
  PatchRecorder(std::size_t patch, int height) : patch_(float(patch)), height_(height) {}
  FragmentOutput shade(const FragmentInput&) const override { return {}; }
  void shade_batch(FragmentBatch& b) const override {
    const int tags = b.num_varyings - kFragmentTagCount;
    std::vector<PatchFragment> mine;
    for (int l = 0; l < b.lanes(); ++l) {
      if (!b.live[l] || b.varyings[tags + kTagPatch][l] != patch_) continue;
      PatchFragment f;
      f.x = int(b.frag_coord[0][l]);
      f.y = height_ - 1 - int(b.frag_coord[1][l]);
      f.triangle = std::size_t(b.varyings[tags + kTagTriangle][l]);
      f.tess_coord = {b.varyings[tags + kTagTessU][l], b.varyings[tags + kTagTessV][l], b.varyings[tags + kTagTessW][l]};
      f.depth = b.frag_coord[2][l];
      mine.push_back(f);
    }
    if (mine.empty()) return;
    std::lock_guard<std::mutex> lock(mutex_);
    fragments.insert(fragments.end(), mine.begin(), mine.end());
  }
  mutable std::vector<PatchFragment> fragments;  // arrival order differs by thread: sorted after

 private:
  float patch_;
  int height_;
  mutable std::mutex mutex_;
};

}  // namespace

PatchFragments patch_fragments(const Scene& scene, const Mesh& mesh, std::size_t patch,
                               std::size_t triangles, const std::optional<glm::vec3>& near,
                               const Parallel& parallel) {
  PatchRecorder recorder(patch, scene.height);
  TaggedRedraw redraw;
  redraw.depth_test = false;
  redraw.fs = &recorder;
  Framebuffer fb;
  draw_with_tagged_redraw(scene, mesh, parallel, fb, redraw, "--patch");

  std::vector<PatchFragment>& all = recorder.fragments;
  // A fixed order whatever the thread count: by pixel, then triangle, then depth.
  std::sort(all.begin(), all.end(), [](const PatchFragment& a, const PatchFragment& b) {
    return std::tie(a.y, a.x, a.triangle, a.depth) < std::tie(b.y, b.x, b.triangle, b.depth);
  });
  PatchFragments r;
  r.per_triangle.assign(triangles, 0);
  const glm::vec3 target = near.value_or(glm::vec3(1.0f / 3.0f));
  float best = 0.0f;
  for (PatchFragment& f : all) {
    f.visible = fb.depth[fb.index(f.x, scene.height - 1 - f.y)] == f.depth;
    ++r.count;
    r.visible += f.visible;
    if (f.triangle < r.per_triangle.size()) ++r.per_triangle[f.triangle];
    if (r.max_x < r.min_x) {
      r.min_x = r.max_x = f.x;
      r.min_y = r.max_y = f.y;
    }
    r.min_x = std::min(r.min_x, f.x);
    r.max_x = std::max(r.max_x, f.x);
    r.min_y = std::min(r.min_y, f.y);
    r.max_y = std::max(r.max_y, f.y);
    const glm::vec3 d = f.tess_coord - target;
    // Visible fragments first: an invisible one wins only when none is visible.
    const float score = glm::dot(d, d) + (f.visible ? 0.0f : 16.0f);
    if (!r.nearest || score < best) {
      r.nearest = f;
      best = score;
    }
  }
  return r;
}

}  // namespace tessref
