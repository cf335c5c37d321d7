#include "inspect/fragment_tags.h"

#include <cstring>
#include <string>

#include "common/error.h"

namespace tessref {
namespace {

// An empty batch of the same primitives with room for the tags after the batch's own varyings
// (the triangle and patch tags flat); InputError when there is no room.
template <int Corners>
PrimitiveBatch<Corners> with_tag_room(const PrimitiveBatch<Corners>& batch) {
  const int n = batch.num_varyings;
  if (n + kFragmentTagCount > kMaxVaryings)
    throw InputError("fragment tags: the draw's " + std::to_string(n) + " varyings leave no room for " +
                     std::to_string(kFragmentTagCount) + " more (at most " + std::to_string(kMaxVaryings) + ")");
  PrimitiveBatch<Corners> out;
  out.num_varyings = n + kFragmentTagCount;
  out.flat_varyings = batch.flat_varyings;
  out.flat_varyings.set(std::size_t(n + kTagTriangle));
  out.flat_varyings.set(std::size_t(n + kTagPatch));
  return out;
}

// The tags a tessellated vertex carries: its primitive's number in the patch and the record's
// patch, gl_TessCoord, world position and normal.
void write_record_tags(float* tag, std::size_t in_patch, const TessDumpRecord& r) {
  tag[kTagTriangle] = float(in_patch);
  tag[kTagPatch] = float(r.patch_id);
  for (int c = 0; c < 3; ++c) {
    tag[kTagTessU + c] = r.tess_coord[c];
    tag[kTagPositionX + c] = r.position[c];
    tag[kTagNormalX + c] = r.normal[c];
  }
}

template <int Corners>
PrimitiveBatch<Corners> tagged(const PrimitiveBatch<Corners>& batch, const std::vector<TessDumpRecord>* records,
                               const std::vector<std::uint32_t>* emitted, std::uint32_t first_primitive) {
  const int n = batch.num_varyings;
  PrimitiveBatch<Corners> out = with_tag_room(batch);
  const std::size_t primitives = batch.primitive_count();
  const std::size_t out_records = std::size_t(out.records());
  out.vertices.resize(std::size_t(Corners) * primitives * out_records);
  std::size_t in_patch = 0;
  std::uint32_t last_patch = 0;
  for (std::size_t p = 0; p < primitives; ++p) {
    const TessDumpRecord* first = records ? &records->at(emitted->at(std::size_t(Corners) * p)) : nullptr;
    if (first && p > 0 && first->patch_id != last_patch) in_patch = 0;
    for (int k = 0; k < Corners; ++k) {
      const std::size_t v = batch.vertex_index(p, k);
      float* dst = reinterpret_cast<float*>(out.vertices.data() + (std::size_t(Corners) * p + std::size_t(k)) * out_records);
      std::memcpy(dst, batch.vertex_data(v), sizeof(float) * std::size_t(4 + n));
      float* tag = dst + 4 + n;
      if (!records) {
        tag[kTagPatch] = float(first_primitive + p);
        continue;
      }
      write_record_tags(tag, in_patch, records->at(emitted->at(v)));
    }
    if (first) last_patch = first->patch_id;
    ++in_patch;
  }
  return out;
}

}  // namespace

LineBatch tagged_lines(const LineBatch& batch, const std::vector<TessDumpRecord>* records,
                       const std::vector<std::uint32_t>* emitted, std::uint32_t first_primitive) {
  return tagged(batch, records, emitted, first_primitive);
}

PointBatch tagged_points(const PointBatch& batch, const std::vector<TessDumpRecord>* records,
                         const std::vector<std::uint32_t>* emitted, std::uint32_t first_primitive) {
  return tagged(batch, records, emitted, first_primitive);
}

TriangleBatch tagged_triangles(const std::vector<TessDumpRecord>& records, const TriangleBatch& batch) {
  const int n = batch.num_varyings;
  TriangleBatch out = with_tag_room(batch);
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
      write_record_tags(dst + 4 + n, in_patch, records.at(v));
    }
    ++in_patch;
  }
  return out;
}

}  // namespace tessref
