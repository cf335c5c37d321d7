#include "verify/drawn_surfaces.h"

#include <algorithm>

#include "io/tess_dump.h"

namespace tessref {
namespace {

// A surface record: the NDC point as the position, the rest as captured.
TessDumpRecord surface_record(const TessDumpRecord& r) {
  TessDumpRecord s = r;
  s.position = surface_point(r.clip);
  return s;
}

// Appends triangle (a, b, c) of `records` (indices into them) unless a corner is behind the eye.
bool append_triangle(TessSurface& s, const TessDumpRecord& a, const TessDumpRecord& b, const TessDumpRecord& c) {
  if (!(a.clip.w > 0.0f && b.clip.w > 0.0f && c.clip.w > 0.0f)) return false;
  for (const TessDumpRecord* r : {&a, &b, &c}) {
    s.indices.push_back(std::uint32_t(s.points.size()));
    s.points.push_back(surface_record(*r));
  }
  return true;
}

// Why the depth image is not the union of the filled triangles the draws drew, or "".
std::string silhouette_rule(const Scene& scene, const DrawnSurfaces& drawn, bool& cull_back) {
  bool first = true;
  for (std::size_t i = 0; i < scene.draws.size(); ++i) {
    const DrawSetting& d = scene.draws[i];
    const RasterState& r = d.raster;
    if (!drawn.writes_depth[i]) continue;  // not in the depth image
    const auto why = [&](const std::string& w) { return d.key + " " + w; };
    if (d.mode == DrawMode::Lines || d.mode == DrawMode::LineStrip || d.mode == DrawMode::LineLoop ||
        d.mode == DrawMode::Points || drawn.lines_or_points[i])
      return why("draws lines or points into the depth image");
    if (drawn.user_clipped[i])
      return why("clips against gl_ClipDistance (GL_CLIP_DISTANCEi) or culls by gl_CullDistance: the rays see the "
                 "surface whole");
    if (!(d.shaders ? *d.shaders : scene.shaders).geometry.empty())
      return why("has a geometry shader: the depth image holds what it emits, the rays the evaluation stage's triangles");
    if (r.polygon_mode != PolygonMode::kFill) return why("draws with a polygon mode other than GL_FILL");
    if (r.scissor.enabled) return why("is scissored");
    if (r.viewport) return why("has a viewport other than the image (the ray caster frames the image)");
    if (r.depth_func == DepthFunc::kNever || r.depth_func == DepthFunc::kEqual ||
        r.depth_func == DepthFunc::kGreater || r.depth_func == DepthFunc::kGreaterEqual)
      return why("has a depth function that fails over the clear depth");
    if (r.cull_front_faces || (r.cull_back_faces && r.front_face_cw))
      return why("culls other than back faces with counter-clockwise front faces");
    if (!first && r.cull_back_faces != cull_back) return why("culls unlike the draws before it");
    cull_back = r.cull_back_faces;
    first = false;
  }
  return "";
}

}  // namespace

glm::vec3 surface_point(const glm::vec4& c) { return glm::vec3(c.x / c.w, c.y / c.w, -c.z / c.w); }

void observe_draws(const Scene& scene, const std::vector<std::vector<CallPatches>>& numbering, DrawOptions& options,
                   DrawnSurfaces& out) {
  out.writes_depth.clear();
  for (const DrawSetting& d : scene.draws) out.writes_depth.push_back(d.raster.depth_test && d.raster.depth_write);
  out.lines_or_points.assign(scene.draws.size(), false);
  out.user_clipped.assign(scene.draws.size(), false);
  options.begin_draw = [&out](std::size_t d) { out.draw = d; };
  options.raster_state = [&out](const RasterState& r) {
    if ((r.clipping_distances() || r.distances.cull_count > 0) && out.draw < out.user_clipped.size())
      out.user_clipped[out.draw] = true;
  };
  std::uint32_t patches = 0;
  for (const auto& draw : numbering)
    for (const CallPatches& c : draw) patches = std::max(patches, c.first_patch + c.per_instance * c.instances);
  out.triangle_patch.assign(patches, false);
  options.tess_surface = [&out](const std::vector<TessDumpRecord>& records, const TriangleBatch& batch) {
    const auto base = std::uint32_t(out.tess.size());
    const std::vector<TessDumpRecord> clip = as_clip_records(records);
    out.tess.insert(out.tess.end(), clip.begin(), clip.end());
    for (const TessDumpRecord& r : records)
      if (r.patch_id < out.triangle_patch.size()) out.triangle_patch[r.patch_id] = true;
    for (std::size_t t = 0; t < batch.triangle_count(); ++t) {
      const TessDumpRecord* v[3];
      for (int k = 0; k < 3; ++k) {
        const auto i = std::uint32_t(batch.vertex_index(t, k));
        out.emitted.push_back(base + i);
        v[k] = &records[i];
      }
      if (!append_triangle(out.tessellated, *v[0], *v[1], *v[2])) ++out.behind_eye;
      if (out.writes_depth[out.draw]) append_triangle(out.triangles, *v[0], *v[1], *v[2]);
    }
  };
  options.tess_lines_points = [&out](const std::vector<TessDumpRecord>& records, const std::vector<std::uint32_t>& emitted) {
    out.lines_or_points[out.draw] = true;
    const auto base = std::uint32_t(out.tess.size());
    const std::vector<TessDumpRecord> clip = as_clip_records(records);
    out.tess.insert(out.tess.end(), clip.begin(), clip.end());
    for (std::uint32_t i : emitted) out.emitted.push_back(base + i);
  };
  options.untessellated_triangles = [&out](const TriangleBatch& batch) {
    if (!out.writes_depth[out.draw]) return;
    for (std::size_t t = 0; t < batch.triangle_count(); ++t) {
      TessDumpRecord v[3];
      for (int k = 0; k < 3; ++k) {
        v[k].patch_id = UINT32_MAX;  // not a patch
        v[k].clip = batch.corner(t, k).position;
      }
      if (!append_triangle(out.triangles, v[0], v[1], v[2])) ++out.behind_eye;
    }
  };
}

void finish_observing(const Scene& scene, DrawnSurfaces& out) {
  out.silhouette_unavailable = silhouette_rule(scene, out, out.cull_back);
}

TessSurface captured_triangles(const std::vector<TessDumpRecord>& emitted, const std::vector<bool>& triangle_patch) {
  TessSurface s;
  std::vector<TessDumpRecord> run;
  for (const TessDumpRecord& r : emitted)
    if (r.patch_id < triangle_patch.size() && triangle_patch[r.patch_id]) run.push_back(r);
  for (std::size_t i = 0; i + 2 < run.size(); i += 3) {
    TessDumpRecord v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = run[i + std::size_t(k)];
      v[k].clip = glm::vec4(v[k].position, v[k].normal.x);  // back from the capture's form
    }
    append_triangle(s, v[0], v[1], v[2]);
  }
  return s;
}

}  // namespace tessref
