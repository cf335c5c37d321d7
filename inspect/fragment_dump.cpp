#include "inspect/fragment_dump.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "inspect/fragment_tags.h"
#include "io/image_output.h"
#include "inspect/tagged_draw.h"

namespace tessref {
namespace {

constexpr int kChannels = 12;

// Writes each live lane's tags to its pixel, in lane (arrival) order, as the rasterizer writes
// colours: the last fragment to pass stays. A pixel belongs to one tile, which one thread draws at
// a time, so threads never write the same pixel.
class DumpRecorder final : public FragmentProgram {
 public:
  explicit DumpRecorder(FragmentDump& dump) : dump_(dump) {}
  FragmentOutput shade(const FragmentInput&) const override { return {}; }
  void shade_batch(FragmentBatch& b) const override {
    const int tags = b.num_varyings - kFragmentTagCount;
    for (int l = 0; l < b.lanes(); ++l) {
      if (!b.live[l]) continue;
      const std::size_t x = std::size_t(b.frag_coord[0][l]), y = std::size_t(b.frag_coord[1][l]);
      float* px = dump_.pixels.data() + (y * std::size_t(dump_.width) + x) * kChannels;
      const auto tag = [&](int k) { return b.varyings[tags + k][l]; };
      const int order[] = {kTagPositionX, kTagPositionY, kTagPositionZ, kTagNormalX, kTagNormalY,
                           kTagNormalZ, kTagPatch, kTagTriangle, kTagTessU, kTagTessV, kTagTessW};
      for (int c = 0; c < kChannels - 1; ++c) px[c] = tag(order[c]);
      px[kChannels - 1] = b.frag_coord[2][l];
    }
  }

 private:
  FragmentDump& dump_;
};

}  // namespace

FragmentDump dump_fragments(const Scene& scene, const Mesh& mesh, const Parallel& parallel) {
  static_assert(kChannels == 12);
  FragmentDump dump;
  dump.width = scene.width;
  dump.height = scene.height;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  dump.pixels.assign(std::size_t(dump.width) * std::size_t(dump.height) * kChannels, nan);
  for (std::size_t i = 0; i < dump.pixels.size(); i += kChannels) dump.pixels[i + 6] = dump.pixels[i + 7] = -1.0f;
  DumpRecorder recorder(dump);
  TaggedRedraw redraw;
  redraw.fs = &recorder;
  Framebuffer fb;
  draw_with_tagged_redraw(scene, mesh, parallel, fb, redraw, "--dump-fragments");
  return dump;
}

void write_fragment_dump(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                         const std::filesystem::path& path) {
  if (path.extension() != ".exr")
    throw InputError("--dump-fragments: '" + path.string() + "': the dump needs an .exr file (" +
                     std::to_string(kChannels) + " float channels)");
  const FragmentDump dump = dump_fragments(scene, mesh, parallel);
  std::vector<float> rows(dump.pixels.size());
  const std::size_t row = std::size_t(dump.width) * kChannels;
  for (int y = 0; y < dump.height; ++y)  // files are written top row first
    std::copy_n(dump.pixels.data() + std::size_t(y) * row, row,
                rows.data() + std::size_t(dump.height - 1 - y) * row);
  write_float_channels(path, dump.width, dump.height, kFragmentDumpChannels, rows);
}

}  // namespace tessref
