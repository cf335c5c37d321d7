// Lines, points and polygon-mode outlines of a batch: clip, then line_setup.h's setup.
#include <algorithm>
#include <optional>

#include "raster/clip.h"
#include "raster/line_setup.h"

namespace tessref::raster {
namespace {

LineVertex line_vertex(const ProjectedVertex& p, const float* varyings) {
  return LineVertex{p.xf, p.yf, p.z, p.inv_w, varyings};
}

const VaryingMask* flat_mask(const VaryingMask& m) { return m.any() ? &m : nullptr; }

// A line between two clip-space records (already clipped or known inside).
bool setup_clipped_line(const ClipRecord& a, bool a_generated, const ClipRecord& b,
                        bool b_generated, const Viewport& vp, int num_varyings,
                        const VaryingMask* flat, std::vector<SetupQuad>& quads,
                        std::vector<float>& varyings) {
  const ProjectedVertex pa = project_position(a.position, vp, a_generated);
  const ProjectedVertex pb = project_position(b.position, vp, b_generated);
  return setup_line(line_vertex(pa, a.varyings.data()), line_vertex(pb, b.varyings.data()), vp,
                    num_varyings, flat, quads, varyings);
}

}  // namespace

SetupOutcome setup_line(const LineBatch& batch, std::size_t index, const ProjectedVertex* projected,
                        const Viewport& vp, std::vector<SetupQuad>& quads,
                        std::vector<float>& varyings, int& pieces_out) {
  pieces_out = 0;
  const std::size_t i0 = batch.vertex_index(index, 0), i1 = batch.vertex_index(index, 1);
  const int nv = std::clamp(batch.num_varyings, 0, kMaxVaryings);
  const float* d0 = batch.vertex_data(i0);
  const float* d1 = batch.vertex_data(i1);
  const VaryingMask* flat = flat_mask(batch.flat_varyings);
  if (vp.culled({d0 + 4, d1 + 4})) return SetupOutcome::kCulled;
  const std::uint32_t c0 = projected[i0].code, c1 = projected[i1].code;
  if ((c0 | c1) & outcode::kNonFinite) return SetupOutcome::kClippedAway;
  if (c0 & c1 & ~outcode::kNonPositiveW) return SetupOutcome::kClippedAway;
  if (outcode_projectable(c0) && outcode_projectable(c1)) {
    if (setup_line(line_vertex(projected[i0], d0 + 4), line_vertex(projected[i1], d1 + 4), vp, nv,
                   flat, quads, varyings))
      pieces_out = 1;
    return SetupOutcome::kRasterized;
  }
  ClipRecord ends[2];
  bool generated[2];
  switch (clip_line(d0, d1, nv, vp.guard_x(), vp.guard_y(), ends, generated, vp.outcode_mask(), vp.user)) {
    case ClipResult::kInvalid:
    case ClipResult::kRejected: return SetupOutcome::kClippedAway;
    case ClipResult::kKept: break;
  }
  if (setup_clipped_line(ends[0], generated[0], ends[1], generated[1], vp, nv, flat, quads,
                         varyings))
    pieces_out = 1;
  return SetupOutcome::kRasterized;
}

SetupOutcome setup_point(const PointBatch& batch, std::size_t index,
                         const ProjectedVertex* projected, const Viewport& vp,
                         std::vector<SetupQuad>& quads, std::vector<float>& varyings,
                         int& pieces_out) {
  pieces_out = 0;
  const std::size_t i = batch.vertex_index(index, 0);
  if (vp.culled({batch.vertex_data(i) + 4})) return SetupOutcome::kCulled;
  if (!outcode_projectable(projected[i].code)) return SetupOutcome::kClippedAway;
  const int nv = std::clamp(batch.num_varyings, 0, kMaxVaryings);
  if (setup_point(line_vertex(projected[i], batch.vertex_data(i) + 4), vp, nv, quads, varyings))
    pieces_out = 1;
  return SetupOutcome::kRasterized;
}

SetupOutcome setup_triangle_outline(const TriangleBatch& batch, std::size_t index,
                                    const ProjectedVertex* projected, const Viewport& vp,
                                    FaceRule faces, PolygonMode mode,
                                    std::vector<SetupQuad>& quads, std::vector<float>& varyings,
                                    int& pieces_out) {
  pieces_out = 0;
  const std::size_t idx[3] = {batch.vertex_index(index, 0), batch.vertex_index(index, 1),
                              batch.vertex_index(index, 2)};
  const int nv = std::clamp(batch.num_varyings, 0, kMaxVaryings);
  const float* d[3] = {batch.vertex_data(idx[0]), batch.vertex_data(idx[1]),
                       batch.vertex_data(idx[2])};
  if (vp.culled({d[0] + 4, d[1] + 4, d[2] + 4})) return SetupOutcome::kCulled;
  const ClipTest test =
      classify_outcodes(projected[idx[0]].code, projected[idx[1]].code, projected[idx[2]].code);
  if (test == ClipTest::kInvalid || test == ClipTest::kRejected) return SetupOutcome::kClippedAway;
  // The draw module's cull stage: det = (v0 - v2) x (v1 - v2) of the window positions;
  // counter-clockwise is det > 0 with y up; zero area is culled when culling. The sign is also
  // gl_FrontFacing of the lines and points. Without every w > 0 it means nothing: such triangles
  // go on to the clipper, and their pieces' facing comes from the clipped polygon.
  // An inside triangle's corners are the batch's projected vertices; a clipped one's are
  // projected here when every w > 0.
  const bool inside = test == ClipTest::kInside;
  bool positive_w = inside;
  ProjectedVertex w[3];
  if (inside) {
    for (int k = 0; k < 3; ++k) w[k] = projected[idx[k]];
  } else {
    positive_w = d[0][3] > 0.0f && d[1][3] > 0.0f && d[2][3] > 0.0f;
    if (positive_w)
      for (int k = 0; k < 3; ++k) w[k] = project_position(glm::vec4(d[k][0], d[k][1], d[k][2], d[k][3]), vp, false);
  }
  auto winding = [](const ProjectedVertex& a, const ProjectedVertex& b, const ProjectedVertex& c) {
    return (a.xf - c.xf) * (b.yf - c.yf) - (a.yf - c.yf) * (b.xf - c.xf);
  };
  std::optional<float> det;
  if (positive_w) {
    det = winding(w[0], w[1], w[2]);
    if ((faces.cull_front || faces.cull_back) && (!(*det != 0.0f) || faces.culled(*det > 0.0f)))
      return SetupOutcome::kCulled;
  }
  // The polygon to outline: the triangle itself, or what clipping leaves of it.
  ClipPolygon poly;
  if (inside) {
    poly.count = 3;
    for (int k = 0; k < 3; ++k) {
      poly.v[k].position = glm::vec4(d[k][0], d[k][1], d[k][2], d[k][3]);
      std::copy_n(d[k] + 4, nv, poly.v[k].varyings.begin());
    }
    poly.generated = {};
    poly.boundary.fill(true);
  } else if (clip_triangle(d[0], d[1], d[2], nv, vp.guard_x(), vp.guard_y(), poly, vp.outcode_mask(), vp.user) !=
             ClipResult::kKept) {
    return SetupOutcome::kClippedAway;
  }
  // Flat varyings: the draw module's flatshade stage has already given every corner the provoking
  // vertex's (v2's) values, so the lines and points carry them unchanged.
  if (batch.flat_varyings.any())
    for (int k = 0; k < poly.count; ++k)
      for (int j = 0; j < nv; ++j)
        if (batch.flat_varyings[std::size_t(j)]) poly.v[std::size_t(k)].varyings[std::size_t(j)] = d[2][4 + j];
  // Each corner's window position, once.
  ProjectedVertex pv[kMaxClipVertices];
  for (int k = 0; k < poly.count; ++k)
    pv[k] = inside ? w[k] : project_position(poly.v[std::size_t(k)].position, vp, poly.generated[std::size_t(k)]);
  if (!det) det = winding(pv[0], pv[1], pv[2]);  // the clipped polygon's own (all its w > 0)
  const bool front = faces.front(*det > 0.0f);
  const std::size_t first_quad = quads.size();
  // The lines and points of a polygon face as it does (Mesa passes the facing on to them).
  auto set_facing = [&] {
    for (std::size_t q = first_quad; q < quads.size(); ++q) quads[q].t.front_facing = front;
  };
  if (mode == PolygonMode::kPoint) {
    // A vertex is drawn with the edge flag of the edge it starts: a cut vertex where the polygon
    // leaves a clip plane is not (measured against llvmpipe).
    for (int k = 0; k < poly.count; ++k) {
      if (!poly.boundary[std::size_t(k)]) continue;
      if (setup_point(line_vertex(pv[k], poly.v[k].varyings.data()), vp, nv, quads, varyings))
        ++pieces_out;
    }
    set_facing();
    return SetupOutcome::kRasterized;
  }
  // The last edge (back to the first vertex) first, then in order, as Mesa's unfilled stage does.
  for (int e = 0; e < poly.count; ++e) {
    const int from = (e + poly.count - 1) % poly.count, to = (from + 1) % poly.count;
    if (!poly.boundary[std::size_t(from)]) continue;
    if (setup_line(line_vertex(pv[from], poly.v[std::size_t(from)].varyings.data()),
                   line_vertex(pv[to], poly.v[std::size_t(to)].varyings.data()), vp, nv, nullptr, quads,
                   varyings))
      ++pieces_out;
  }
  set_facing();
  return SetupOutcome::kRasterized;
}

}  // namespace tessref::raster
