#include "verify/verify_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>

#include "common/error.h"
#include "mesh/camera.h"
#include "render/draw_scene.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "verify/compare.h"
#include "verify/cracks.h"
#include "verify/drawn_surfaces.h"
#include "verify/feedback_compare.h"
#include "verify/silhouette.h"
#include "verify/surface_distance.h"

namespace tessref {
namespace {

nlohmann::json histogram_json(const UlpHistogram& h) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t b = 0; b < h.size(); ++b)
    if (h[b]) j[ulp_bucket_name(b)] = h[b];
  return j;
}

nlohmann::json vec_json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// Without tessellation the surface is the mesh's triangles in world space, one patch each.
TessSurface mesh_surface(const Scene& scene, const Mesh& mesh) {
  TessSurface s;
  const glm::mat4 model = model_matrix(scene.transform);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.indices[3 * t + k];
      TessDumpRecord r;
      r.patch_id = std::uint32_t(t);
      r.position = glm::vec3(model * glm::vec4(mesh.positions[v], 1.0f));
      r.normal = glm::vec3(glm::transpose(glm::inverse(model)) * glm::vec4(mesh.normals[v], 0.0f));
      s.indices.push_back(std::uint32_t(s.points.size()));
      s.points.push_back(r);
    }
  return s;
}

Rgb8Image difference_image(const Rgb8Image& a, const Rgb8Image& b) {
  Rgb8Image d{a.width, a.height, std::vector<std::uint8_t>(a.pixels.size())};
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    d.pixels[i] = std::uint8_t(std::min(255, 8 * std::abs(int(a.pixels[i]) - int(b.pixels[i]))));
  return d;
}

Rgb8Image heat_image(const SilhouetteComparison& s, const FloatImage& depth, double limit) {
  Rgb8Image img{depth.width, depth.height, std::vector<std::uint8_t>(depth.pixels.size() * 3, 0)};
  for (std::size_t i = 0; i < depth.pixels.size(); ++i) {
    std::uint8_t* p = &img.pixels[3 * i];
    if (s.distance[i] < 0.0f) {
      if (depth.pixels[i] < 1.0f) p[0] = p[1] = p[2] = 64;
      continue;
    }
    p[0] = 255;
    p[1] = s.distance[i] <= limit ? 255 : 0;
  }
  return img;
}

// The scene as compared with the capture's: file paths (the mesh, shaders, textures) are resolved
// against the folder the command ran in, so only their file names are compared.
nlohmann::json without_folders(nlohmann::json scene) {
  const auto name_only = [](nlohmann::json& v) {
    if (v.is_string() && v.get<std::string>().rfind("twin:", 0) != 0)
      v = std::filesystem::path(v.get<std::string>()).filename().string();
  };
  if (scene.contains("mesh") && scene["mesh"].contains("path")) name_only(scene["mesh"]["path"]);
  if (scene.contains("shaders")) {
    nlohmann::json& s = scene["shaders"];
    for (const char* stage : {"vertex", "tess_control", "tess_evaluation", "geometry", "fragment"})
      if (s.contains(stage)) name_only(s[stage]);
    if (s.contains("textures") && s["textures"].is_object())
      for (auto& [name, t] : s["textures"].items()) name_only(t.is_object() && t.contains("path") ? t["path"] : t);
  }
  return scene;
}

// The records of the patches whose positions are all finite (`records` itself when every one
// is): a NaN corner has no distance to anything, and an infinite maximum would leave the report's
// figures null. Those patches fail on their own (nonfinite_records, or their coordinates).
const std::vector<TessDumpRecord>& finite_patches(const std::vector<TessDumpRecord>& records,
                                                  std::vector<TessDumpRecord>& copy) {
  const auto finite = [](const TessDumpRecord& r) {
    return std::isfinite(r.position.x) && std::isfinite(r.position.y) && std::isfinite(r.position.z);
  };
  if (std::all_of(records.begin(), records.end(), finite)) return records;
  std::vector<std::uint32_t> bad;
  for (const TessDumpRecord& r : records)
    if (!finite(r)) bad.push_back(r.patch_id);
  std::sort(bad.begin(), bad.end());
  std::copy_if(records.begin(), records.end(), std::back_inserter(copy),
               [&](const TessDumpRecord& r) { return !std::binary_search(bad.begin(), bad.end(), r.patch_id); });
  return copy;
}

// A record or digest of a patch past the last one tessref tessellated: the driver numbered its
// primitives otherwise (gl_PrimitiveID), or the file was edited.
std::uint64_t check_patch_range(const Reference& ref, const std::vector<TessDumpRecord>& mine,
                                std::vector<std::string>& failures) {
  std::uint64_t count = 0;
  for (const TessDumpRecord& r : mine) count = std::max<std::uint64_t>(count, std::uint64_t(r.patch_id) + 1);
  std::uint64_t beyond = 0;
  std::uint32_t first = 0;
  const auto check = [&](std::uint32_t patch) {
    if (patch < count) return;
    if (!beyond++) first = patch;
  };
  for (const TessDumpRecord& r : ref.tess) check(r.patch_id);
  const std::uint64_t records = beyond;
  for (const TessPatchDigest& d : ref.digests) check(d.patch_id);
  if (!beyond) return 0;
  const std::string tessellated = count ? "patches 0 to " + std::to_string(count - 1) : "no patch";
  failures.push_back(std::to_string(records) + " records of tess.bin and " + std::to_string(beyond - records) +
                     " digests of tess_patches.bin name a patch the scene does not have (first: patch " +
                     std::to_string(first) + "; tessref tessellated " + tessellated + ")");
  return beyond;
}

// Triangles wound the other way round than tessref's (compare.h winding_differs): a failure, as
// the cw/ccw layout fixes the orientation.
std::uint64_t check_winding(const std::vector<TessDumpRecord>& reference, const std::vector<TessDumpRecord>& mine,
                   const std::vector<std::uint32_t>& emitted, const std::function<bool(std::uint32_t)>& triangles,
                   nlohmann::json& report, std::vector<std::string>& failures) {
  const WindingDifference w = winding_differs(reference, mine, emitted, triangles);
  report["winding_differs_patches"] = w.patches.size();
  report["winding_differs_triangles"] = w.triangles;
  if (w.patches.empty()) return 0;
  failures.push_back(std::to_string(w.triangles) + " triangles in " + std::to_string(w.patches.size()) +
                     " patches are wound the other way round than tessref's (first: patch " +
                     std::to_string(w.patches[0]) + ", " + std::to_string(w.first_patch_triangles) + " of its " +
                     std::to_string(w.first_patch_total) + " triangles; the cw/ccw layout fixes the orientation)");
  return w.triangles;
}

}  // namespace

VerifyResult verify_scene(const std::string& scene_path, const std::vector<std::string>& sets,
                          const std::string& reference, const VerifyLimits& limits, const Parallel& parallel) {
  Scene scene = load_scene(scene_path, sets);
  const nlohmann::json scene_json = load_scene_json(scene_path, sets);
  const Reference ref = load_reference(reference);
  nlohmann::json j;
  j["scene"] = scene.source;
  j["sets"] = sets;  // the --set overrides: the report's commands must name the same scene
  j["reference"] = reference;
  j["driver"] = ref.manifest.value("gl_renderer", std::string("unknown driver"));
  j["driver_version"] = ref.manifest.value("gl_version", std::string());
  j["width"] = scene.width;
  j["height"] = scene.height;
  std::vector<std::string> warnings, failures;
  if (ref.manifest.contains("scene") && without_folders(ref.manifest["scene"]) != without_folders(scene_json))
    warnings.push_back(reference + " was captured from another scene than " + scene.source +
                       " (the manifest's scene differs); the comparison is of different scenes");
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  scene.camera = fitted_camera(scene, mesh);

  // A scene of draws is compared through gl_Position and gl_TessCoord alone (drawn_surfaces.h);
  // the mesh path through the world-space position and normal its programs output.
  const bool of_draws = !scene.draws.empty();
  TessSurface mine;
  DrawnSurfaces drawn;
  DrawOptions options;
  bool tessellates = scene.tessellation.enabled;
  if (of_draws) {
    const std::vector<std::vector<CallPatches>> numbering = patch_numbering(scene, load_buffers(scene));
    observe_draws(scene, numbering, options, drawn);
    tessellates = !drawn.triangle_patch.empty();
  } else if (scene.tessellation.enabled) {
    options.tess_surface = [&](const std::vector<TessDumpRecord>& r, const TriangleBatch& b) { mine.append(r, b); };
  }
  RenderResult result;
  std::vector<FeedbackBuffers> feedback;
  result.stats = render_scene(scene, mesh, parallel, result.framebuffer, options, &feedback);
  if (of_draws) {
    finish_observing(scene, drawn);
    mine = std::move(drawn.tessellated);
  }
  else if (!scene.tessellation.enabled) mine = mesh_surface(scene, mesh);
  const std::vector<TessDumpRecord>& my_records = of_draws ? drawn.tess : mine.points;
  const std::vector<std::uint32_t>& my_emitted = of_draws ? drawn.emitted : mine.indices;
  // Positions are compared in the records' own space (world, or clip for draws), surfaces in theirs.
  double diagonal = of_draws ? (drawn.triangles.indices.empty() ? 1.0 : drawn.triangles.diagonal()) : mine.diagonal();
  double record_diagonal = diagonal;
  if (of_draws && !drawn.tess.empty()) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const TessDumpRecord& r : drawn.tess) lo = glm::min(lo, glm::dvec3(r.position)), hi = glm::max(hi, glm::dvec3(r.position));
    record_diagonal = glm::length(hi - lo) > 0.0 ? glm::length(hi - lo) : 1.0;
  }
  j["diagonal"] = diagonal;
  if (of_draws) {
    j["space"] = "normalized device coordinates (gl_Position / w); tessellation records in clip space";
    j["triangles_behind_eye"] = drawn.behind_eye;
  }
  double severity = 0.0;  // the largest measured / limit; above 1 fails
  const auto rate = [&](double measured, double limit) { severity = std::max(severity, measured / limit); };

  // gl_TessCoord streams and the values at them: in full for the patches tess.bin holds, by
  // digest for every patch.
  const bool tessellated = tessellates && (!ref.tess.empty() || !ref.digests.empty());
  if (tessellated) {
    std::vector<TessDumpRecord> compared_points;
    if (ref.patch_stride > 1)
      std::copy_if(my_records.begin(), my_records.end(), std::back_inserter(compared_points),
                   [&](const TessDumpRecord& r) { return ref.sampled(r.patch_id); });
    TessComparison t = compare_tess(ref.tess, ref.patch_stride > 1 ? compared_points : my_records);
    if (!ref.digests.empty()) {
      const std::vector<TessPatchDigest> digests = digest_patches(my_records, my_emitted);
      // Either finding counts: the digests cover every patch, the records the sampled ones (and
      // a tess.bin edited without its digests).
      std::vector<std::uint32_t> differ, by_digest = compare_digests(ref.digests, digests);
      std::set_union(by_digest.begin(), by_digest.end(), t.mismatched_patches.begin(), t.mismatched_patches.end(),
                     std::back_inserter(differ));
      differ.erase(std::unique(differ.begin(), differ.end()), differ.end());
      t.patches = std::max(ref.digests.size(), digests.size());
      t.patches_mismatched = differ.size();
      t.first_mismatched_patch = differ.empty() ? -1 : std::int64_t(differ.front());
      t.reference_vertices = 0;
      for (const TessPatchDigest& d : ref.digests) t.reference_vertices += d.emitted;
    }
    const double position = t.max_position_distance / record_diagonal;
    j["tessellation"] = {{"patches", t.patches}, {"patches_mismatched", t.patches_mismatched},
                         {"first_mismatched_patch", t.first_mismatched_patch},
                         {"emitted_vertices", t.reference_vertices}, {"unmatched_vertices", t.unmatched_vertices},
                         {"position_ulps", histogram_json(t.position_ulps)}, {"normal_ulps", histogram_json(t.normal_ulps)},
                         {"max_position_ulp", t.max_position_ulp}, {"worst_position_patch", t.worst_position_patch},
                         {"max_normal_ulp", t.max_normal_ulp}, {"max_position_difference_of_diagonal", position},
                         {"patch_stride", ref.patch_stride}, {"records_compared", ref.tess.size()}};
    j["tessellation"]["max_normal_difference"] = t.max_normal_difference;
    j["tessellation"]["worst_normal_patch"] = t.worst_normal_patch;
    j["tessellation"]["nonfinite_records"] = t.nonfinite_records;
    // Order is the implementation's choice: reported, not failed.
    const std::vector<std::uint32_t> order = emission_order_differs(ref.tess, my_records, my_emitted);
    std::size_t compared = 0;
    for (std::size_t i = 0; i < ref.tess.size(); ++i) compared += i == 0 || ref.tess[i].patch_id != ref.tess[i - 1].patch_id;
    j["tessellation"]["order_compared_patches"] = compared;
    j["tessellation"]["order_differs_patches"] = order.size();
    j["tessellation"]["first_order_differs_patch"] = order.empty() ? -1 : std::int64_t(order.front());
    // Each a failure whatever its size: severity above 1.
    if (const std::uint64_t n = check_patch_range(ref, my_records, failures)) rate(1.0 + double(n), 1.0);
    const auto triangles = [&](std::uint32_t patch) {
      return !of_draws || (patch < drawn.triangle_patch.size() && drawn.triangle_patch[patch]);
    };
    if (const std::uint64_t n = check_winding(ref.tess, my_records, my_emitted, triangles, j["tessellation"], failures))
      rate(1.0 + double(n), 1.0);
    if (t.nonfinite_records) {
      failures.push_back("tess.bin: " + std::to_string(t.nonfinite_records) +
                         " records hold a NaN or infinite position or normal where tessref's is finite, or the reverse "
                         "(first: patch " + std::to_string(t.first_nonfinite_patch) + ")");
      rate(1.0 + double(t.nonfinite_records), 1.0);
    }
    // A scene of draws keeps gl_Position's w where the normal would be: no normal to compare.
    if (!of_draws) {
      if (t.max_normal_difference > limits.max_normal) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "normals differ by up to %.3g (|difference| / |longer normal|) at the same patch and "
                      "gl_TessCoord (limit %g; worst: patch %lld)",
                      t.max_normal_difference, limits.max_normal, static_cast<long long>(t.worst_normal_patch));
        failures.push_back(buf);
      }
      rate(t.max_normal_difference, limits.max_normal);
    }
    const std::vector<EmittedCountDifference> counts = emitted_counts_differ(ref.tess, my_records, my_emitted);
    j["tessellation"]["emitted_count_differs_patches"] = counts.size();
    if (!counts.empty()) {
      failures.push_back(std::to_string(counts.size()) + " patches emit another number of vertices than tessref's (first: patch " +
                         std::to_string(counts[0].patch) + ", " + std::to_string(counts[0].reference) + " in the capture, " +
                         std::to_string(counts[0].tessref) + " from tessref)");
      rate(1.0 + double(counts.size()), 1.0);
    }
    if (!t.coords_identical()) {
      failures.push_back("gl_TessCoord streams differ in " + std::to_string(t.patches_mismatched) + " of " +
                         std::to_string(t.patches) + " patches (first: patch " +
                         std::to_string(t.first_mismatched_patch) + ")");
      rate(1.0 + double(t.patches_mismatched), 1.0);
    }
    // The same patch and gl_TessCoord must evaluate to the same point: a capture whose records
    // moved between patches (permuted ids) keeps its coordinates and its surface, not its positions.
    if (position > limits.max_distance) {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "evaluated positions differ by up to %.3g of the diagonal at the same patch and gl_TessCoord "
                    "(limit %g; worst: patch %lld)",
                    position, limits.max_distance, static_cast<long long>(t.worst_distance_patch));
      failures.push_back(buf);
    }
    rate(position, limits.max_distance);
  }

  const SurfaceOracle mine_oracle(mine);
  // Two-sided distance between the surfaces.
  if (tessellated && !mine.indices.empty()) {
    std::vector<TessDumpRecord> finite_copy;
    const std::vector<TessDumpRecord>& finite = finite_patches(ref.tess, finite_copy);
    const TessSurface theirs = of_draws ? captured_triangles(finite, drawn.triangle_patch) : TessSurface::from_emitted(finite);
    const SurfaceOracle their_oracle(theirs);
    const SurfaceDistance d = surface_distance(
        theirs, their_oracle, mine, mine_oracle, parallel,
        [&](std::uint32_t patch) { return ref.sampled(patch); });
    const auto side = [&](const SurfaceDistance::Side& s) {
      return nlohmann::json{{"samples", s.samples}, {"max_of_diagonal", s.max / diagonal},
                            {"rms_of_diagonal", s.rms / diagonal}, {"worst_patch", s.worst_patch}};
    };
    nlohmann::json worst = nlohmann::json::array();
    for (const auto& [patch, dist] : d.worst_patches)
      worst.push_back({{"patch", patch}, {"distance_of_diagonal", dist / diagonal}});
    j["surface_distance"] = {{"hausdorff_of_diagonal", d.hausdorff / diagonal},
                             {"reference_to_tessref", side(d.reference_to_tessref)},
                             {"tessref_to_reference", side(d.tessref_to_reference)},
                             {"worst_patches", worst}};
    if (d.hausdorff > limits.max_distance * diagonal) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "Hausdorff distance %.3g of the diagonal (limit %g; worst: patch %u)",
                    d.hausdorff / diagonal, limits.max_distance, d.worst_patches.empty() ? 0u : d.worst_patches[0].first);
      failures.push_back(buf);
    }
    rate(d.hausdorff / diagonal, limits.max_distance);
  }

  // Silhouette: Embree's coverage of tessref's surface against the driver's.
  if (ref.depth.width != scene.width || ref.depth.height != scene.height)
    throw InputError(reference + ": the capture is " + std::to_string(ref.depth.width) + "x" +
                     std::to_string(ref.depth.height) + ", the scene renders " + std::to_string(scene.width) + "x" +
                     std::to_string(scene.height));
  SilhouetteComparison s;
  if (of_draws && !drawn.silhouette_unavailable.empty()) {
    j["silhouette"] = {{"examined", false}, {"why", drawn.silhouette_unavailable}};
  } else if (!of_draws && scene.shaders.program == ShaderProgram::Custom && !scene.shaders.geometry.empty()) {
    j["silhouette"] = {{"examined", false},
                       {"why", "shaders.geometry: the image holds what the geometry shader emits, the rays the "
                               "evaluation stage's surface"}};
  } else {
    // Draws: the surfaces' space seen along -z (NDC's z flipped), every pixel's ray parallel.
    const glm::mat4 view_projection =
        of_draws ? glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 0, 0, 1))
                 : projection_matrix(scene.camera, scene.width, scene.height) * view_matrix(scene.camera);
    const TessSurface& surface = of_draws ? drawn.triangles : mine;
    std::unique_ptr<SurfaceOracle> drawn_oracle;
    if (of_draws) drawn_oracle = std::make_unique<SurfaceOracle>(surface);
    const SurfaceOracle& oracle = of_draws ? *drawn_oracle : mine_oracle;
    s = compare_silhouette(ref.depth, surface, oracle, view_projection, of_draws ? drawn.cull_back : scene.cull_back_faces,
                           parallel);
    std::uint64_t beyond = 0;
    for (std::size_t i = 0; i < s.distance.size(); ++i) beyond += s.distance[i] > limits.silhouette_px;
    nlohmann::json buckets = nlohmann::json::object();
    for (std::size_t b = 0; b < s.by_distance.size(); ++b)
      if (s.by_distance[b]) buckets[kSilhouetteBuckets[b]] = s.by_distance[b];
    nlohmann::json worst = nlohmann::json::array();  // [x, y, distance in pixels], farthest first
    for (const auto& [x, y] : s.worst_pixels)
      worst.push_back({x, y, s.distance[std::size_t(y) * std::size_t(ref.depth.width) + std::size_t(x)]});
    j["silhouette"] = {{"examined", true}, {"covered_reference", s.covered_reference}, {"covered_rays", s.covered_rays},
                       {"mismatched", s.mismatched}, {"beyond_limit", beyond}, {"max_distance_px", s.max_distance},
                       {"by_distance_px", buckets}, {"silhouette_edges", s.silhouette_edges},
                       {"worst_pixels", worst}};
    if (beyond) {
      failures.push_back(std::to_string(beyond) + " coverage mismatches farther than " +
                         std::to_string(limits.silhouette_px).substr(0, 3) + " px from the silhouette (worst at pixel " +
                         std::to_string(s.worst_pixels[0][0]) + "," + std::to_string(s.worst_pixels[0][1]) + ", " +
                         std::to_string(s.max_distance) + " px)");
    }
    rate(s.max_distance, limits.silhouette_px);
  }

  // The rasterizer's coverage against the driver's, pixel for pixel.
  const CoverageComparison coverage = compare_coverage(ref.depth, result.framebuffer);
  j["coverage"] = {{"covered_reference", coverage.covered_reference}, {"covered_tessref", coverage.covered_tessref},
                   {"mismatched", coverage.mismatched}, {"off_silhouette", coverage.off_silhouette},
                   {"mismatched_by_distance", coverage.by_distance}};

  // Cracks between tessref's patches.
  if (tessellates && !mine.indices.empty()) {
    const CrackReport c = find_cracks(mine, mine_oracle, parallel);
    nlohmann::json worst = nlohmann::json::array();
    for (std::size_t k = 0; k < std::min<std::size_t>(10, c.cracked.size()); ++k)
      worst.push_back({{"patches", {c.cracked[k].patch_a, c.cracked[k].patch_b}},
                       {"from", vec_json(c.cracked[k].from)}, {"to", vec_json(c.cracked[k].to)},
                       {"gap_of_diagonal", c.cracked[k].gap / diagonal}, {"rays_through", c.cracked[k].rays_through}});
    j["cracks"] = {{"examined", c.triangles}, {"patches", c.patches}, {"shared_edges", c.shared_edges},
                   {"unshared_edges", c.unshared_edges}, {"rays", c.rays}, {"rays_through", c.rays_through},
                   {"grazing_misses", c.grazing_misses},
                   {"cracked_edges", c.cracked.size()}, {"max_gap_of_diagonal", c.max_gap / diagonal},
                   {"worst", worst}};
    if (!c.cracked.empty() && limits.cracks_fail) {
      failures.push_back(std::to_string(c.cracked.size()) + " cracked edges (" + std::to_string(c.rays_through) +
                         " rays through; widest between patches " + std::to_string(c.cracked[0].patch_a) + " and " +
                         std::to_string(c.cracked[0].patch_b) + ")");
      rate(1.0 + double(c.cracked.size()), 1.0);
    }
  }

  // Colour.
  VerifyResult out;
  out.reference = ref.color;
  out.tessref = to_rgb8(result.framebuffer);
  const ColorComparison color = compare_color(ref.color, out.tessref);
  const double share = 100.0 * double(color.within_2) / double(std::max<std::uint64_t>(color.pixels, 1));
  j["color"] = {{"within_1_255", color.within_1}, {"within_2_255", color.within_2}, {"pixels", color.pixels},
                {"max_difference_255", color.max_difference},
                {"psnr_db", std::isinf(color.psnr) ? nlohmann::json(nullptr) : nlohmann::json(color.psnr)}};
  if (share < limits.color_share) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.4f%% of pixels within 2/255 (required: %g%%; largest difference %d/255)", share,
                  limits.color_share, color.max_difference);
    failures.push_back(buf);
  }
  rate((100.0 - share) / std::max(1e-9, 100.0 - limits.color_share), 1.0);

  // Transform feedback, byte for byte.
  const FeedbackComparison fc = compare_feedback(reference, ref.manifest, feedback);
  if (!fc.report.empty()) j["transform_feedback"] = fc.report;
  failures.insert(failures.end(), fc.failures.begin(), fc.failures.end());
  if (!fc.failures.empty()) rate(2.0, 1.0);

  j["limits"] = {{"max_distance_of_diagonal", limits.max_distance}, {"max_normal_difference", limits.max_normal},
                 {"silhouette_px", limits.silhouette_px},
                 {"color_share_percent", limits.color_share}, {"cracks_fail", limits.cracks_fail}};
  j["pass"] = failures.empty();
  j["failures"] = failures;
  j["warnings"] = warnings;
  // JSON has no infinity (it would be written as null, and campaigns sort by this figure).
  j["severity"] = std::isfinite(severity) ? severity : std::numeric_limits<double>::max();
  out.report = std::move(j);
  out.difference = difference_image(ref.color, out.tessref);
  if (s.distance.empty()) s.distance.assign(ref.depth.pixels.size(), -1.0f);  // not examined
  out.heat = heat_image(s, ref.depth, limits.silhouette_px);
  return out;
}

std::string verify_summary(const nlohmann::json& j) {
  std::string out;
  char buf[512];
  std::snprintf(buf, sizeof buf, "tessref verify: %s against %s (%s), %dx%d: %s\n", j["scene"].get<std::string>().c_str(),
                j["reference"].get<std::string>().c_str(), j["driver"].get<std::string>().c_str(), j["width"].get<int>(),
                j["height"].get<int>(), j["pass"].get<bool>() ? "PASS" : "FAIL");
  out += buf;
  if (j.contains("tessellation")) {
    const auto& t = j["tessellation"];
    std::snprintf(buf, sizeof buf,
                  "  gl_TessCoord: %llu patches, %llu with streams that differ; %llu emitted vertices, %llu not "
                  "generated by tessref; largest ULP distance: position %u (patch %lld), normal %u\n",
                  t["patches"].get<unsigned long long>(), t["patches_mismatched"].get<unsigned long long>(),
                  t["emitted_vertices"].get<unsigned long long>(), t["unmatched_vertices"].get<unsigned long long>(),
                  t["max_position_ulp"].get<unsigned>(), t["worst_position_patch"].get<long long>(),
                  t["max_normal_ulp"].get<unsigned>());
    out += buf;
    std::snprintf(buf, sizeof buf, "  emission order (the driver's choice; reported only): the same in %llu of %llu patches\n",
                  t["order_compared_patches"].get<unsigned long long>() - t["order_differs_patches"].get<unsigned long long>(),
                  t["order_compared_patches"].get<unsigned long long>());
    out += buf;
    if (t.contains("max_normal_difference")) {
      std::snprintf(buf, sizeof buf,
                    "  normals: largest difference %.3g of the longer normal (patch %lld); %llu triangles wound the "
                    "other way round; %llu records with a NaN or infinity on one side only\n",
                    t["max_normal_difference"].get<double>(), t["worst_normal_patch"].get<long long>(),
                    t.value("winding_differs_triangles", 0ull), t["nonfinite_records"].get<unsigned long long>());
      out += buf;
    }
    if (t["patch_stride"].get<unsigned>() > 1)
      out += "    (coordinates of every patch by digest; values and distances on the patches whose id is a "
             "multiple of " + std::to_string(t["patch_stride"].get<unsigned>()) + ", the capture's sample)\n";
  }
  if (j.contains("surface_distance")) {
    const auto& d = j["surface_distance"];
    std::snprintf(buf, sizeof buf,
                  "  surface distance (of the diagonal): Hausdorff %.3g; driver -> tessref max %.3g rms %.3g, tessref "
                  "-> driver max %.3g rms %.3g\n",
                  d["hausdorff_of_diagonal"].get<double>(), d["reference_to_tessref"]["max_of_diagonal"].get<double>(),
                  d["reference_to_tessref"]["rms_of_diagonal"].get<double>(),
                  d["tessref_to_reference"]["max_of_diagonal"].get<double>(),
                  d["tessref_to_reference"]["rms_of_diagonal"].get<double>());
    out += buf;
  }
  const auto& s = j["silhouette"];
  if (!s["examined"].get<bool>()) {
    out += "  silhouette (Embree rays): not examined: " + s["why"].get<std::string>() + "\n";
  } else {
    std::snprintf(buf, sizeof buf,
                  "  silhouette (Embree rays): %llu pixels covered by the driver, %llu by the rays; %llu differ, the "
                  "farthest %.3f px from the silhouette, %llu beyond the limit\n",
                  s["covered_reference"].get<unsigned long long>(), s["covered_rays"].get<unsigned long long>(),
                  s["mismatched"].get<unsigned long long>(), s["max_distance_px"].get<double>(),
                  s["beyond_limit"].get<unsigned long long>());
    out += buf;
  }
  const auto& c = j["coverage"];
  std::snprintf(buf, sizeof buf, "  raster coverage: %llu pixels differ from the driver's, %llu more than one pixel from the silhouette\n",
                c["mismatched"].get<unsigned long long>(), c["off_silhouette"].get<unsigned long long>());
  out += buf;
  if (j.contains("cracks")) {
    const auto& k = j["cracks"];
    if (!k["examined"].get<bool>())
      out += "  cracks: not examined (not a triangle domain)\n";
    else {
      std::snprintf(buf, sizeof buf,
                    "  cracks: %llu shared edges, %llu rays, %llu through (%llu edges); largest gap %.3g of the "
                    "diagonal; %llu grazing misses where the boundaries coincide\n",
                    k["shared_edges"].get<unsigned long long>(), k["rays"].get<unsigned long long>(),
                    k["rays_through"].get<unsigned long long>(), k["cracked_edges"].get<unsigned long long>(),
                    k["max_gap_of_diagonal"].get<double>(), k["grazing_misses"].get<unsigned long long>());
      out += buf;
    }
  }
  const auto& col = j["color"];
  const double pixels = col["pixels"].get<double>();
  std::snprintf(buf, sizeof buf, "  colour: %.4f%% of pixels within 1/255, %.4f%% within 2/255, largest difference %d/255, PSNR %s dB\n",
                100.0 * col["within_1_255"].get<double>() / pixels, 100.0 * col["within_2_255"].get<double>() / pixels,
                col["max_difference_255"].get<int>(),
                col["psnr_db"].is_null() ? "inf" : std::to_string(col["psnr_db"].get<double>()).c_str());
  out += buf;
  if (j.contains("transform_feedback")) {
    std::size_t identical = 0, bytes = 0;
    for (const auto& b : j["transform_feedback"]) {
      identical += b["identical"].get<bool>();
      bytes += b["driver_bytes"].get<std::size_t>();
    }
    out += "  transform feedback: " + std::to_string(identical) + " of " + std::to_string(j["transform_feedback"].size()) +
           " buffers identical to the driver's (" + std::to_string(bytes) + " bytes)\n";
  }
  for (const auto& f : j["failures"]) out += "  FAIL: " + f.get<std::string>() + "\n";
  return out;
}

}  // namespace tessref
