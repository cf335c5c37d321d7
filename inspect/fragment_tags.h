#pragma once
// Fragments that know where they came from: a chunk's tessellated triangles redrawn with extra
// varyings naming the triangle, its patch and gl_TessCoord, so that the rasterizer's own
// interpolation (coverage, perspective-correct weights, clipping) tells each fragment its origin.
// Used by `tessref inspect --pixel` and `render --dump-fragments` (inspect/inspect_pixel.h, inspect/fragment_dump.h).
#include <cstddef>
#include <vector>

#include "raster/vertex.h"
#include "stages/tess_stage.h"

namespace tessref {

// The tags follow the batch's own varyings (which keep their indices, so the scene's fragment
// program reads them unchanged): tag k is varying num_varyings + k of the tagged batch.
enum FragmentTag : int {
  kTagTriangle = 0,  // the triangle's index within its patch, emission order (flat)
  kTagPatch,         // gl_PrimitiveID of the patch (flat)
  kTagTessU, kTagTessV, kTagTessW,  // gl_TessCoord, interpolated from the triangle's corners
  kTagPositionX, kTagPositionY, kTagPositionZ,  // world position as --dump-tess records it
  kTagNormalX, kTagNormalY, kTagNormalZ,        // world normal, likewise
  kFragmentTagCount
};

// batch: one tess_surface chunk (indexed; vertex k is records[k]). The result holds the same
// triangles in the same order as consecutive triples (a triangle index per vertex needs vertices
// of its own; both forms draw the same bytes, raster/vertex.h). Triangles come in patch order
// (stages/tess_stage.h), which numbers them within their patch. Triangle indices and patch ids
// are stored as floats: exact below 2^24. InputError when the batch has too many varyings to
// take the tags.
TriangleBatch tagged_triangles(const std::vector<TessDumpRecord>& records, const TriangleBatch& batch);

// The same for a batch of lines or points, whose primitives are consecutive vertices. Isolines
// and point mode: vertex k of the batch is records[emitted[k]], and kTagTriangle numbers the
// primitive within its patch. Untessellated ones (records null): kTagPatch numbers the primitive
// from first_primitive on, and the other tags are zero.
LineBatch tagged_lines(const LineBatch& batch, const std::vector<TessDumpRecord>* records,
                       const std::vector<std::uint32_t>* emitted, std::uint32_t first_primitive);
PointBatch tagged_points(const PointBatch& batch, const std::vector<TessDumpRecord>* records,
                         const std::vector<std::uint32_t>* emitted, std::uint32_t first_primitive);

}  // namespace tessref
