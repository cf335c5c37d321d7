#include "cli/tessellator_comparison.h"

#include <algorithm>
#include <cstdlib>

#include "render/render.h"
#include "stages/tpg_cache.h"
#include "stages/tpg_refinement.h"
#include "verify/compare.h"
#include "verify/surface.h"
#include "verify/surface_distance.h"

namespace tessref::cli {
namespace {

struct Drawn {
  TessSurface surface;
  RenderResult result;
};

Drawn draw(Scene scene, const Mesh& mesh, Tessellator tessellator, const Parallel& parallel) {
  scene.tessellation.tessellator = tessellator;
  Drawn d;
  DrawOptions options;
  options.tess_surface = [&](const std::vector<TessDumpRecord>& r, const TriangleBatch& b) {
    d.surface.append(r, b);
  };
  d.result = render_scene(scene, mesh, parallel, options);
  return d;
}

// The depth attachment as compare_coverage reads a captured one: top row first.
FloatImage depth_image(const Framebuffer& fb) {
  FloatImage img{fb.width, fb.height, 1, std::vector<float>(fb.depth.size())};
  for (int y = 0; y < fb.height; ++y)
    for (int x = 0; x < fb.width; ++x)
      img.pixels[std::size_t(y) * fb.width + x] = fb.depth[fb.index(x, fb.height - 1 - y)];
  return img;
}

// Grey where both cover, red where only the TPG's rendering does, cyan where only the uniform one.
Rgb8Image coverage_image(const Framebuffer& tpg, const Framebuffer& uniform) {
  Rgb8Image img{tpg.width, tpg.height, std::vector<std::uint8_t>(tpg.depth.size() * 3, 255)};
  for (int y = 0; y < tpg.height; ++y)
    for (int x = 0; x < tpg.width; ++x) {
      const std::size_t src = tpg.index(x, tpg.height - 1 - y);
      std::uint8_t* p = &img.pixels[3 * (std::size_t(y) * tpg.width + x)];
      const bool a = tpg.depth[src] < 1.0f, b = uniform.depth[src] < 1.0f;
      if (a && b) p[0] = p[1] = p[2] = 200;
      else if (a) p[0] = 220, p[1] = 0, p[2] = 0;
      else if (b) p[0] = 0, p[1] = 160, p[2] = 220;
    }
  return img;
}

std::uint64_t pattern_triangles(const Scene& scene, Tessellator t) {
  const TessLayout layout{TessDomain::Triangles, scene.tessellation.spacing, scene.tessellation.winding, false};
  return make_pattern(layout, scene.tessellation.levels, TessProfile::llvmpipe(), t)->points.primitive_count();
}

// Pixels whose 8-bit colours (a of fa, b of fb) differ, and the largest channel difference where
// both drew: shading only, since where one rendering shows background the difference is coverage's.
void compare_colours(const Framebuffer& fa, const Framebuffer& fb, const Rgb8Image& a, const Rgb8Image& b,
                     std::uint64_t& differs, int& most_where_both) {
  for (int y = 0; y < fa.height; ++y)
    for (int x = 0; x < fa.width; ++x) {
      const std::size_t i = 3 * (std::size_t(y) * fa.width + x), z = fa.index(x, fa.height - 1 - y);
      int most = 0;
      for (int k = 0; k < 3; ++k) most = std::max(most, std::abs(int(a.pixels[i + k]) - int(b.pixels[i + k])));
      differs += most > 0;
      if (fa.depth[z] < 1.0f && fb.depth[z] < 1.0f) most_where_both = std::max(most_where_both, most);
    }
}

// The refinement pattern's rendering against the TPG's: the same measures as the uniform grid's.
TessellatorComparison::Versus versus_tpg(const Drawn& tpg, const Drawn& other, const Parallel& parallel) {
  TessellatorComparison::Versus v;
  v.triangles = other.surface.triangle_count();
  {
    const SurfaceOracle tpg_oracle(tpg.surface), other_oracle(other.surface);
    const SurfaceDistance d = surface_distance(tpg.surface, tpg_oracle, other.surface, other_oracle, parallel);
    v.hausdorff = d.hausdorff;
    v.from_tpg_rms = d.reference_to_tessref.rms;
    v.to_tpg_rms = d.tessref_to_reference.rms;
  }
  const Framebuffer& fa = tpg.result.framebuffer;
  const Framebuffer& fb = other.result.framebuffer;
  const CoverageComparison cov = compare_coverage(depth_image(fa), fb);
  v.covered = cov.covered_tessref;
  v.coverage_differs = cov.mismatched;
  v.off_silhouette = cov.off_silhouette;
  v.image = to_rgb8(fb);
  compare_colours(fa, fb, to_rgb8(fa), v.image, v.colour_differs, v.max_colour_difference);
  v.coverage_image = coverage_image(fa, fb);
  return v;
}

}  // namespace

TessellatorComparison compare_tessellators(Scene scene, const Mesh& mesh, float level,
                                           const Parallel& parallel) {
  scene.tessellation.levels.outer.fill(level);
  scene.tessellation.levels.inner.fill(level);
  TessellatorComparison c;
  c.level = level;
  c.uniform_n = uniform_segments(scene.tessellation.levels, TessProfile::llvmpipe());
  c.tpg_pattern_triangles = pattern_triangles(scene, Tessellator::PrimitiveGenerator);
  c.uniform_pattern_triangles = pattern_triangles(scene, Tessellator::Uniform);

  const Drawn tpg = draw(scene, mesh, Tessellator::PrimitiveGenerator, parallel);
  const Drawn uni = draw(scene, mesh, Tessellator::Uniform, parallel);
  c.tpg_triangles = tpg.surface.triangle_count();
  c.uniform_triangles = uni.surface.triangle_count();
  c.diagonal = tpg.surface.diagonal();

  {
    const SurfaceOracle tpg_oracle(tpg.surface), uni_oracle(uni.surface);
    const SurfaceDistance d = surface_distance(tpg.surface, tpg_oracle, uni.surface, uni_oracle, parallel);
    c.hausdorff = d.hausdorff;
    c.tpg_to_uniform_max = d.reference_to_tessref.max;
    c.tpg_to_uniform_rms = d.reference_to_tessref.rms;
    c.uniform_to_tpg_max = d.tessref_to_reference.max;
    c.uniform_to_tpg_rms = d.tessref_to_reference.rms;
    if (!d.worst_patches.empty()) c.worst_patch = d.worst_patches[0].first;
  }

  const CoverageComparison cov = compare_coverage(depth_image(tpg.result.framebuffer), uni.result.framebuffer);
  c.covered_tpg = cov.covered_reference;
  c.covered_uniform = cov.covered_tessref;
  c.coverage_differs = cov.mismatched;
  c.off_silhouette = cov.off_silhouette;
  c.on_silhouette = cov.mismatched - cov.off_silhouette;

  c.tpg_image = to_rgb8(tpg.result.framebuffer);
  c.uniform_image = to_rgb8(uni.result.framebuffer);
  compare_colours(tpg.result.framebuffer, uni.result.framebuffer, c.tpg_image, c.uniform_image, c.colour_differs,
                  c.max_colour_difference);
  c.coverage_image = coverage_image(tpg.result.framebuffer, uni.result.framebuffer);

  c.refinement = versus_tpg(tpg, draw(scene, mesh, Tessellator::RefinementPattern, parallel), parallel);
  c.refinement.lod = refinement_lod(scene.tessellation.levels, TessProfile::llvmpipe());
  c.refinement.segments = refinement_segments(c.refinement.lod);
  c.refinement.pattern_triangles = pattern_triangles(scene, Tessellator::RefinementPattern);
  return c;
}

nlohmann::json TessellatorComparison::to_json() const {
  const double d = diagonal;
  return {{"level", level},
          {"uniform_n", uniform_n},
          {"triangles", {{"primitive_generator", tpg_triangles}, {"uniform", uniform_triangles}}},
          {"triangles_per_patch", {{"primitive_generator", tpg_pattern_triangles}, {"uniform", uniform_pattern_triangles}}},
          {"diagonal", diagonal},
          {"hausdorff_of_diagonal", hausdorff / d},
          {"tpg_to_uniform", {{"max_of_diagonal", tpg_to_uniform_max / d}, {"rms_of_diagonal", tpg_to_uniform_rms / d}}},
          {"uniform_to_tpg", {{"max_of_diagonal", uniform_to_tpg_max / d}, {"rms_of_diagonal", uniform_to_tpg_rms / d}}},
          {"worst_patch", worst_patch},
          {"coverage", {{"covered_primitive_generator", covered_tpg}, {"covered_uniform", covered_uniform},
                        {"differs", coverage_differs}, {"on_silhouette", on_silhouette},
                        {"off_silhouette", off_silhouette}}},
          {"colour_differs", colour_differs},
          {"max_colour_difference", max_colour_difference},
          {"refinement_pattern",
           {{"lod", refinement.lod},
            {"segments", refinement.segments},
            {"triangles", refinement.triangles},
            {"triangles_per_patch", refinement.pattern_triangles},
            {"hausdorff_of_diagonal", refinement.hausdorff / d},
            {"tpg_to_refinement_rms_of_diagonal", refinement.from_tpg_rms / d},
            {"refinement_to_tpg_rms_of_diagonal", refinement.to_tpg_rms / d},
            {"coverage", {{"covered", refinement.covered}, {"differs", refinement.coverage_differs},
                          {"off_silhouette", refinement.off_silhouette}}},
            {"colour_differs", refinement.colour_differs},
            {"max_colour_difference", refinement.max_colour_difference}}}};
}

}  // namespace tessref::cli
