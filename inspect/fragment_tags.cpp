#include "inspect/fragment_tags.h"

#include <cstring>
#include <string>

#include "common/error.h"

namespace tessref {

TriangleBatch tagged_triangles(const std::vector<TessDumpRecord>& records, const TriangleBatch& batch) {
  const int n = batch.num_varyings;
  if (n + kFragmentTagCount > kMaxVaryings)
    throw InputError("fragment tags: the draw's " + std::to_string(n) + " varyings leave no room for " +
                     std::to_string(kFragmentTagCount) + " more (at most " + std::to_string(kMaxVaryings) + ")");
  TriangleBatch out;
  out.num_varyings = n + kFragmentTagCount;
  out.flat_varyings = batch.flat_varyings;
  out.flat_varyings.set(std::size_t(n + kTagTriangle));
  out.flat_varyings.set(std::size_t(n + kTagPatch));
  const std::size_t triangles = batch.triangle_count();
  const std::size_t out_records = std::size_t(out.records());
  out.vertices.resize(3 * triangles * out_records);
  std::size_t in_patch = 0;
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t patch = records.at(batch.vertex_index(t, 0)).patch_id;
    if (t > 0 && records.at(batch.vertex_index(t - 1, 0)).patch_id != patch) in_patch = 0;
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = batch.vertex_index(t, k);
      float* dst = reinterpret_cast<float*>(out.vertices.data() + (3 * t + std::size_t(k)) * out_records);
      std::memcpy(dst, batch.vertex_data(v), sizeof(float) * std::size_t(4 + n));
      const TessDumpRecord& r = records.at(v);
      float* tag = dst + 4 + n;
      tag[kTagTriangle] = float(in_patch);
      tag[kTagPatch] = float(r.patch_id);
      for (int c = 0; c < 3; ++c) {
        tag[kTagTessU + c] = r.tess_coord[c];
        tag[kTagPositionX + c] = r.position[c];
        tag[kTagNormalX + c] = r.normal[c];
      }
    }
    ++in_patch;
  }
  return out;
}

}  // namespace tessref
