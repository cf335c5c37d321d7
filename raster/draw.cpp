// draw_triangles, draw_lines, draw_points: setup in fixed chunks, binning to tiles, tiles scanned
// in parallel, one generic draw (draw_batch) for every primitive kind.
//
// Determinism: the batch is cut into chunks of kChunkTriangles primitives (independent of the thread count);
// each chunk clips and sets up its triangles in order and bins them per tile. A tile is then owned
// by one task, which walks the chunks in order, so every pixel sees its triangles in submission
// order whatever the thread count. Statistics are integer sums of per-chunk and per-tile counts.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/fixed_point.h"
#include "raster/rasterizer.h"
#include "raster/setup.h"
#include "raster/tile_raster.h"
#include "raster/triage.h"

namespace tessref {

RasterStats& RasterStats::operator+=(const RasterStats& o) {
  triangles_in += o.triangles_in;
  triangles_clipped_away += o.triangles_clipped_away;
  triangles_culled += o.triangles_culled;
  triangles_rasterized += o.triangles_rasterized;
  fragments_shaded += o.fragments_shaded;
  fragments_depth_failed += o.fragments_depth_failed;
  return *this;
}

namespace {

using raster::SetupQuad;
using raster::SetupTriangle;

// What the binner and the tile scan need of each kind of set-up primitive.
const SetupTriangle& box_of(const SetupTriangle& t) { return t; }
const SetupTriangle& box_of(const SetupQuad& q) { return q.t; }
bool may_cover(const SetupTriangle& t, const raster::PixelRect& r) {
  return raster::triangle_may_cover(t, r);
}
bool may_cover(const SetupQuad& q, const raster::PixelRect& r) { return raster::quad_may_cover(q, r); }
void scan(const SetupTriangle& t, const float* varyings, int nv, const raster::PixelRect& r,
          raster::FragmentSink& sink) {
  raster::raster_triangle(t, varyings, nv, r, sink);
}
void scan(const SetupQuad& q, const float* varyings, int nv, const raster::PixelRect& r,
          raster::FragmentSink& sink) {
  raster::raster_quad(q, varyings, nv, r, sink);
}

constexpr int kTileSize = kFramebufferTileSize; // pixels (a deferred clear is kept per tile)
constexpr std::size_t kChunkTriangles = 1024;    // input triangles per setup task
constexpr std::size_t kMinBinnedForTasks = 256;  // fewer (triangle, tile) pairs: scan inline
// Bounds memory: about 170 bytes + 12 * num_varyings per triangle are held per pass. Each pass
// revisits the tiles it touches, so passes should not be too small either.
constexpr std::size_t kPassTriangles = 64 * 1024;
constexpr std::size_t kProjectVertices = 8192;  // vertices per projection task

template <class Setup>
struct Chunk {
  std::vector<Setup> prims;  // set-up primitives (triangles or quads)
  std::vector<float> varyings;
  std::vector<std::uint32_t> tile_begin;  // per tile: start in tile_tris; num_tiles + 1 entries
  std::vector<std::uint32_t> tile_tris;   // indices into prims, grouped by tile, in order
  std::vector<std::uint32_t> single_tile; // per triangle: its only tile, or ~0 (scratch)
  std::vector<std::uint32_t> fill;        // per tile: next slot in tile_tris (scratch)
  std::vector<raster::Triage> triage;     // per input primitive: what triage decided (scratch)
  RasterStats stats;
};

struct TileGrid {
  int tiles_x, tiles_y;
  std::size_t count() const { return std::size_t(tiles_x) * tiles_y; }
};

// setup_one(i, prims, varyings, pieces) sets up input primitive i (raster::setup_triangle and its
// kin). triage(first, last, verdicts) may decide primitives [first, last) beforehand (raster/triage.h;
// false: it decided nothing); those it culls or finds without fragments skip setup_one.
template <class Setup, class SetupOne, class TriageRange>
void setup_chunk(int num_varyings, std::size_t first, std::size_t last, const TileGrid& grid,
                 const SetupOne& setup_one, const TriageRange& triage, Chunk<Setup>& chunk) {
  chunk.prims.clear();
  chunk.varyings.clear();
  chunk.prims.reserve(last - first);
  chunk.varyings.reserve((last - first) * 3 * std::size_t(num_varyings));
  chunk.stats = RasterStats{};
  chunk.triage.resize(last - first);
  const bool triaged = triage(first, last, chunk.triage.data());
  for (std::size_t i = first; i < last; ++i) {
    int pieces = 0;
    ++chunk.stats.triangles_in;
    if (triaged) {
      const raster::Triage verdict = chunk.triage[i - first];
      if (verdict == raster::Triage::kCulled) {
        ++chunk.stats.triangles_culled;
        continue;
      }
      if (verdict == raster::Triage::kNoFragment) {
        ++chunk.stats.triangles_rasterized;
        continue;
      }
    }
    switch (setup_one(i, chunk.prims, chunk.varyings, pieces)) {
      case raster::SetupOutcome::kClippedAway: ++chunk.stats.triangles_clipped_away; break;
      case raster::SetupOutcome::kCulled: ++chunk.stats.triangles_culled; break;
      case raster::SetupOutcome::kRasterized: chunk.stats.triangles_rasterized += pieces; break;
    }
  }

  // Counting sort of (tile, triangle) pairs by tile; triangle order within a tile is kept.
  chunk.tile_begin.assign(grid.count() + 1, 0);
  auto for_tiles = [&](const Setup& prim, auto&& fn) {
    const SetupTriangle& t = box_of(prim);
    if (t.min_x > t.max_x || t.min_y > t.max_y) return;
    const int tx0 = t.min_x / kTileSize, tx1 = t.max_x / kTileSize;
    const int ty0 = t.min_y / kTileSize, ty1 = t.max_y / kTileSize;
    const bool single = tx0 == tx1 && ty0 == ty1;
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) {
        // Tiles of the bounding box that the triangle misses get no entry.
        const raster::PixelRect rect{std::max(tx * kTileSize, t.min_x),
                                     std::max(ty * kTileSize, t.min_y),
                                     std::min((tx + 1) * kTileSize - 1, t.max_x),
                                     std::min((ty + 1) * kTileSize - 1, t.max_y)};
        if (single || may_cover(prim, rect))
          fn(std::size_t(ty) * grid.tiles_x + tx);
      }
  };
  // Most triangles lie in one tile: remember it from the counting pass.
  constexpr std::uint32_t kSeveralTiles = ~0u;
  chunk.single_tile.resize(chunk.prims.size());
  for (std::size_t k = 0; k < chunk.prims.size(); ++k) {
    const SetupTriangle& t = box_of(chunk.prims[k]);
    const int tx0 = t.min_x / kTileSize, ty0 = t.min_y / kTileSize;
    if (t.min_x <= t.max_x && t.min_y <= t.max_y && tx0 == t.max_x / kTileSize &&
        ty0 == t.max_y / kTileSize) {
      const auto tile = std::uint32_t(ty0 * grid.tiles_x + tx0);
      chunk.single_tile[k] = tile;
      ++chunk.tile_begin[tile + 1];
    } else {
      chunk.single_tile[k] = kSeveralTiles;
      for_tiles(chunk.prims[k], [&](std::size_t tile) { ++chunk.tile_begin[tile + 1]; });
    }
  }
  for (std::size_t k = 1; k < chunk.tile_begin.size(); ++k)
    chunk.tile_begin[k] += chunk.tile_begin[k - 1];
  chunk.tile_tris.resize(chunk.tile_begin.back());
  chunk.fill.assign(chunk.tile_begin.begin(), chunk.tile_begin.end() - 1);
  for (std::uint32_t k = 0; k < chunk.prims.size(); ++k) {
    if (chunk.single_tile[k] != kSeveralTiles) {
      chunk.tile_tris[chunk.fill[chunk.single_tile[k]]++] = k;
      continue;
    }
    for_tiles(chunk.prims[k], [&](std::size_t tile) { chunk.tile_tris[chunk.fill[tile]++] = k; });
  }
}


// The draw of any primitive kind: Setup is what setup_one(i, prims, varyings, pieces) makes of
// input primitive i of batch.
// triage(projected, vp, first, last, verdicts): setup_chunk's triage, with the projected vertices.
template <class Setup, class Batch, class SetupOne, class TriageRange>
RasterStats draw_batch(const Batch& batch, const RasterState& state, const FragmentProgram& fs,
                       Framebuffer& fb, const Parallel& parallel, const SetupOne& setup_one,
                       const TriageRange& triage) {
  RasterStats total;
  const std::size_t n = batch.primitive_count();
  if (fb.width <= 0 || fb.height <= 0) {
    total.triangles_in = n;
    total.triangles_clipped_away = n;
    return total;
  }
  if (fb.width > fixed::kMaxViewportPixels || fb.height > fixed::kMaxViewportPixels)
    throw std::invalid_argument("draw_triangles: viewport larger than " +
                                std::to_string(fixed::kMaxViewportPixels) + " pixels");
  const std::size_t pixels = std::size_t(fb.width) * fb.height;
  if (fb.color.size() != pixels || fb.depth.size() != pixels ||
      (!fb.aux.empty() && fb.aux.size() != pixels))
    throw std::invalid_argument("draw_triangles: framebuffer attachments do not match its size");

  if (batch.indexed) {
    if (batch.indices.size() % Batch::kCorners != 0)
      throw std::invalid_argument("draw_triangles: index count not a multiple of " +
                                  std::to_string(Batch::kCorners));
    std::uint32_t largest = 0;  // a max reduction (vectorizes), then one test
    for (std::uint32_t i : batch.indices) largest = std::max(largest, i);
    if (!batch.indices.empty() && largest >= batch.vertex_count())
      throw std::invalid_argument("draw_triangles: index " + std::to_string(largest) +
                                  " past the vertex array (" +
                                  std::to_string(batch.vertex_count()) + " vertices)");
  }
  const raster::Viewport vp = raster::Viewport::of(fb.width, fb.height, state);
  const TileGrid grid{(fb.width + kTileSize - 1) / kTileSize,
                      (fb.height + kTileSize - 1) / kTileSize};
  const int num_varyings = std::clamp(batch.num_varyings, 0, kMaxVaryings);

  // Scratch kept per calling thread: reallocating (and page-faulting) tens of megabytes on every
  // draw would cost more than small draws themselves. Bound to a reference here, on the calling
  // thread: the tasks below run on other threads, whose own thread_local would be another object.
  thread_local std::vector<Chunk<Setup>> scratch;
  thread_local std::vector<raster::ProjectedVertex> projected_scratch;
  std::vector<Chunk<Setup>>& chunks = scratch;

  // Per-vertex clip-space work once per vertex (shared by the triangles that index it).
  std::vector<raster::ProjectedVertex>& projected = projected_scratch;
  const std::size_t vertex_count = batch.vertex_count();
  const int records = batch.records();
  projected.resize(vertex_count);
  const std::size_t vertex_tasks = (vertex_count + kProjectVertices - 1) / kProjectVertices;
  auto project = [&](std::size_t c) {
    const std::size_t first = c * kProjectVertices;
    raster::project_vertices(batch.vertices.data() + first * std::size_t(records),
                             std::min(kProjectVertices, vertex_count - first), records, vp,
                             projected.data() + first);
  };
  if (vertex_tasks == 1) project(0);
  else parallel.for_each(vertex_tasks, project);

  std::vector<std::size_t> active;            // tiles with triangles in this pass
  std::vector<std::uint64_t> tile_fragments, tile_depth_failed;  // per active tile
  for (std::size_t pass_first = 0; pass_first < n; pass_first += kPassTriangles) {
    const std::size_t pass_last = std::min(n, pass_first + kPassTriangles);
    const std::size_t num_chunks = (pass_last - pass_first + kChunkTriangles - 1) / kChunkTriangles;
    if (chunks.size() < num_chunks) chunks.resize(num_chunks);

    parallel.for_each(num_chunks, [&](std::size_t c) {
      const std::size_t first = pass_first + c * kChunkTriangles;
      setup_chunk(num_varyings, first, std::min(pass_last, first + kChunkTriangles), grid,
                  [&](std::size_t i, std::vector<Setup>& prims, std::vector<float>& varyings,
                      int& pieces) { return setup_one(projected.data(), vp, i, prims, varyings, pieces); },
                  [&](std::size_t first, std::size_t last, raster::Triage* verdicts) {
                    return triage(projected.data(), vp, first, last, verdicts);
                  },
                  chunks[c]);
    });

    // Only tiles that received triangles get a task.
    active.clear();
    std::size_t binned = 0;
    for (std::size_t tile = 0; tile < grid.count(); ++tile) {
      std::size_t in_tile = 0;
      for (std::size_t c = 0; c < num_chunks; ++c)
        in_tile += chunks[c].tile_begin[tile + 1] - chunks[c].tile_begin[tile];
      if (in_tile) active.push_back(tile);
      binned += in_tile;
    }
    tile_fragments.assign(active.size(), 0);
    tile_depth_failed.assign(active.size(), 0);
    auto scan_tile = [&](std::size_t a) {
      const std::size_t tile = active[a];
      const int tx = int(tile % grid.tiles_x), ty = int(tile / grid.tiles_x);
      raster::PixelRect rect{tx * kTileSize, ty * kTileSize,
                             std::min(fb.width, (tx + 1) * kTileSize) - 1,
                             std::min(fb.height, (ty + 1) * kTileSize) - 1};
      if (state.scissor.enabled) {  // GL 4.6 14.9.2: only pixels inside the scissor box are written
        rect.x0 = std::max(rect.x0, state.scissor.x);
        rect.y0 = std::max(rect.y0, state.scissor.y);
        rect.x1 = std::min(rect.x1, state.scissor.x + state.scissor.width - 1);
        rect.y1 = std::min(rect.y1, state.scissor.y + state.scissor.height - 1);
        if (rect.x0 > rect.x1 || rect.y0 > rect.y1) return;
      }
      fb.clear_tile(tx, ty);  // a deferred clear: the whole tile, whatever the scissor
      raster::FragmentSink sink(fs, fb, num_varyings, state, &batch.flat_varyings);
      for (std::size_t c = 0; c < num_chunks; ++c) {
        const Chunk<Setup>& chunk = chunks[c];
        for (std::uint32_t k = chunk.tile_begin[tile]; k < chunk.tile_begin[tile + 1]; ++k) {
          const Setup& prim = chunk.prims[chunk.tile_tris[k]];
          scan(prim, chunk.varyings.data() + box_of(prim).varying_offset, num_varyings, rect, sink);
        }
      }
      sink.flush();
      tile_fragments[a] = sink.shaded();
      tile_depth_failed[a] = sink.depth_failed();
    };
    // Starting tasks costs more than scanning a few hundred small triangles.
    if (binned < kMinBinnedForTasks) {
      for (std::size_t a = 0; a < active.size(); ++a) scan_tile(a);
    } else {
      parallel.for_each(active.size(), scan_tile);
    }

    for (std::size_t c = 0; c < num_chunks; ++c) total += chunks[c].stats;
    for (std::uint64_t f : tile_fragments) total.fragments_shaded += f;
    for (std::uint64_t f : tile_depth_failed) total.fragments_depth_failed += f;
  }
  return total;
}

// No triage: every primitive goes through setup.
bool no_triage(const raster::ProjectedVertex*, const raster::Viewport&, std::size_t, std::size_t,
               raster::Triage*) {
  return false;
}

// Filled triangles: the triage of whole chunks from their corners (cull distances, tested per
// triangle on its varyings, leave everything to setup).
bool triage_filled(const TriangleBatch& batch, const RasterState& state,
                   const raster::ProjectedVertex* projected, const raster::Viewport& vp,
                   std::size_t first, std::size_t last, raster::Triage* verdicts) {
  if (vp.cull_count > 0) return false;
  static_assert(kChunkTriangles <= raster::TriageCorners::kMax);
  const raster::TriageParams params{vp.width, vp.height, state.cull_front_faces,
                                    state.cull_back_faces, state.front_face_cw};
  raster::triage_triangles(projected, batch.indexed ? batch.indices.data() : nullptr, first,
                           int(last - first), params, verdicts);
  return true;
}

}  // namespace

RasterStats draw_triangles(const TriangleBatch& batch, const RasterState& state,
                           const FragmentProgram& fs, Framebuffer& fb, const Parallel& parallel) {
  if (state.polygon_mode == PolygonMode::kFill)
    return draw_batch<SetupTriangle>(
        batch, state, fs, fb, parallel,
        [&](const raster::ProjectedVertex* projected, const raster::Viewport& vp, std::size_t i,
            std::vector<SetupTriangle>& tris, std::vector<float>& varyings, int& pieces) {
          return raster::setup_triangle(batch, i, projected, vp, raster::FaceRule::of(state), tris,
                                        varyings, pieces);
        },
        [&](const raster::ProjectedVertex* projected, const raster::Viewport& vp, std::size_t first,
            std::size_t last, raster::Triage* verdicts) {
          return triage_filled(batch, state, projected, vp, first, last, verdicts);
        });
  return draw_batch<SetupQuad>(
      batch, state, fs, fb, parallel,
      [&](const raster::ProjectedVertex* projected, const raster::Viewport& vp, std::size_t i,
          std::vector<SetupQuad>& quads, std::vector<float>& varyings, int& pieces) {
        return raster::setup_triangle_outline(batch, i, projected, vp, raster::FaceRule::of(state),
                                              state.polygon_mode, quads, varyings, pieces);
      },
      no_triage);
}

RasterStats draw_lines(const LineBatch& batch, const RasterState& state, const FragmentProgram& fs,
                       Framebuffer& fb, const Parallel& parallel) {
  return draw_batch<SetupQuad>(
      batch, state, fs, fb, parallel,
      [&](const raster::ProjectedVertex* projected, const raster::Viewport& vp, std::size_t i,
          std::vector<SetupQuad>& quads, std::vector<float>& varyings, int& pieces) {
        return raster::setup_line(batch, i, projected, vp, quads, varyings, pieces);
      },
      no_triage);
}

RasterStats draw_points(const PointBatch& batch, const RasterState& state,
                        const FragmentProgram& fs, Framebuffer& fb, const Parallel& parallel) {
  return draw_batch<SetupQuad>(
      batch, state, fs, fb, parallel,
      [&](const raster::ProjectedVertex* projected, const raster::Viewport& vp, std::size_t i,
          std::vector<SetupQuad>& quads, std::vector<float>& varyings, int& pieces) {
        return raster::setup_point(batch, i, projected, vp, quads, varyings, pieces);
      },
      no_triage);
}

}  // namespace tessref
