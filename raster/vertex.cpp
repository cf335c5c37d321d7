#include "raster/vertex.h"

namespace tessref {

TriangleBatch expand_indices(const TriangleBatch& batch) {
  TriangleBatch out;
  out.num_varyings = batch.num_varyings;
  out.flat_varyings = batch.flat_varyings;
  const std::size_t n = batch.triangle_count();
  const std::size_t r = std::size_t(batch.records());
  out.vertices.reserve(3 * n * r);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const ClipVertex* v = &batch.corner(t, k);
      out.vertices.insert(out.vertices.end(), v, v + r);
    }
  return out;
}

template <int Corners>
void append_primitives(PrimitiveBatch<Corners>& dst, const PrimitiveBatch<Corners>& src) {
  dst.num_varyings = src.num_varyings;
  dst.flat_varyings = src.flat_varyings;
  if (!dst.indexed && !src.indexed) {
    dst.vertices.insert(dst.vertices.end(), src.vertices.begin(), src.vertices.end());
    return;
  }
  if (!dst.indexed) {  // turn dst's triples into an identity index list
    dst.indices.resize(dst.vertex_count());
    for (std::size_t k = 0; k < dst.indices.size(); ++k) dst.indices[k] = std::uint32_t(k);
    dst.indexed = true;
  }
  const auto base = std::uint32_t(dst.vertex_count());
  const std::size_t n = std::size_t(Corners) * src.primitive_count();
  for (std::size_t k = 0; k < n; ++k)
    dst.indices.push_back(base + std::uint32_t(src.vertex_index(k / Corners, int(k % Corners))));
  dst.vertices.insert(dst.vertices.end(), src.vertices.begin(), src.vertices.end());
}

template void append_primitives<1>(PointBatch&, const PointBatch&);
template void append_primitives<2>(LineBatch&, const LineBatch&);
template void append_primitives<3>(TriangleBatch&, const TriangleBatch&);

}  // namespace tessref
