// `tessref compare-tessellators [SCENE] --levels 1,2,3 [--json FILE] [--images DIR]`: seed 000's
// open question. The scene's PN (or flat) surface tessellated by the GL primitive generator and
// by uniform subdivision at each level; per level the triangle counts, the two-sided Hausdorff
// and RMS distance between the surfaces (of the bounding-box diagonal) and the pixels whose
// coverage differs. docs/uniform-subdivision.md holds the measured table.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/tessellator_comparison.h"
#include "common/error.h"
#include "mesh/camera.h"
#include "mesh/mesh_source.h"
#include "io/output_files.h"
#include "scene/scene_loader.h"

namespace tessref::cli {
namespace {

struct CompareArgs {
  std::string scene, levels = "1,2,3,5,8,13,21,64", json, images;
  std::vector<std::string> sets;
  int threads = 0;
};

// "1,2,3.5": levels in [1, 64]; the uniform grid rounds a fraction up, the TPG keeps it.
std::vector<float> parse_levels(const std::string& text) {
  std::vector<float> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    float v = 0.0f;
    try {
      v = std::stof(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(v) || v < 1.0f || v > 64.0f)
      throw InputError("--levels: expected numbers from 1 to 64 separated by commas, got '" + item + "'");
    out.push_back(v);
  }
  if (out.empty()) throw InputError("--levels: expected at least one level");
  return out;
}

// The comparison sets the tessellator and the levels itself; the rest of the scene must allow both.
void check_scene(const Scene& s) {
  if (!s.tessellation.enabled)
    throw InputError(s.source + ": tessellation.enabled: compare-tessellators needs tessellation (it is false)");
  if (s.tessellation.adaptive.enabled)
    throw InputError(s.source + ": tessellation.adaptive.enabled: compare-tessellators needs fixed levels");
  if (s.shaders.program != ShaderProgram::Builtin)
    throw InputError(s.source + ": shaders.program: compare-tessellators runs the built-in programs only");
}

std::string level_name(float level) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(level));
  return buf;
}

void run(const CompareArgs& a) {
  const std::vector<float> levels = parse_levels(a.levels);
  Scene scene = load_scene(a.scene, a.sets);
  check_scene(scene);

  OutputFiles outputs;
  std::filesystem::path json_tmp;
  if (!a.json.empty()) json_tmp = outputs.add("--json", a.json);
  std::vector<std::filesystem::path> image_tmp;
  if (!a.images.empty()) {
    std::error_code e;
    std::filesystem::create_directories(a.images, e);
    if (e) throw InputError(a.images + ": cannot create the --images folder: " + e.message());
    for (float level : levels)
      for (const char* kind : {"tpg", "uniform", "coverage", "refinement", "coverage-refinement"})
        image_tmp.push_back(outputs.add(
            "--images", std::filesystem::path(a.images) / (std::string(kind) + "-" + level_name(level) + ".png")));
  }

  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
  scene.camera = fitted_camera(scene, mesh);
  const Parallel parallel(a.threads);

  nlohmann::json report = {{"scene", scene.source}, {"width", scene.width}, {"height", scene.height},
                           {"scheme", to_string(scene.tessellation.scheme)},
                           {"spacing", to_string(scene.tessellation.spacing)},
                           {"mesh_triangles", mesh.triangle_count()}, {"levels", nlohmann::json::array()}};
  std::printf("%6s %4s %10s %10s %11s %11s %11s %7s %9s %9s | %4s %10s %11s %9s %9s\n", "level", "n", "tris_tpg",
              "tris_unif", "hausdorff", "rms_t->u", "rms_u->t", "worst", "cov_diff", "off_silh", "rp_n", "tris_rp",
              "hausd_rp", "cov_rp", "off_rp");
  std::size_t next_image = 0;
  for (float level : levels) {
    const TessellatorComparison c = compare_tessellators(scene, mesh, level, parallel);
    report["levels"].push_back(c.to_json());
    const TessellatorComparison::Versus& rp = c.refinement;
    std::printf("%6g %4d %10llu %10llu %11.3e %11.3e %11.3e %7lld %9llu %9llu | %4d %10llu %11.3e %9llu %9llu\n",
                double(level), c.uniform_n, (unsigned long long)c.tpg_triangles,
                (unsigned long long)c.uniform_triangles, c.hausdorff / c.diagonal,
                c.tpg_to_uniform_rms / c.diagonal, c.uniform_to_tpg_rms / c.diagonal, (long long)c.worst_patch,
                (unsigned long long)c.coverage_differs, (unsigned long long)c.off_silhouette, rp.segments,
                (unsigned long long)rp.triangles, rp.hausdorff / c.diagonal, (unsigned long long)rp.coverage_differs,
                (unsigned long long)rp.off_silhouette);
    std::fflush(stdout);
    if (!a.images.empty())
      for (const Rgb8Image* img : {&c.tpg_image, &c.uniform_image, &c.coverage_image, &c.refinement.image,
                                   &c.refinement.coverage_image})
        write_rgb8_image(*img, image_tmp[next_image++]);
  }
  if (!a.json.empty()) write_text_file(json_tmp, a.json, report.dump(2) + "\n");
  outputs.commit();
}

}  // namespace

void add_compare_tessellators_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare-tessellators",
      "Tessellate the scene's patches with the GL primitive generator, with uniform subdivision and with seed "
      "001's refinement pattern at each level and compare each with the generator's: triangle counts, two-sided Hausdorff and RMS distance between the surfaces (of the "
      "bounding-box diagonal), pixels whose coverage differs (docs/uniform-subdivision.md)");
  add_scene_options(cmd, args->scene, args->sets);
  cmd->add_option("--levels", args->levels, "levels to compare, 1..64, comma separated (every outer and inner level)")
      ->capture_default_str();
  cmd->add_option("--json", args->json, "also write the report as JSON");
  cmd->add_option("--images", args->images,
                  "folder for tpg-L.png, uniform-L.png, coverage-L.png, refinement-L.png and "
                  "coverage-refinement-L.png per level (coverage: red where only the primitive generator's rendering "
                  "covers a pixel, cyan where only the other one does)");
  cmd->add_option("--threads", args->threads, "worker threads (0: all); the results do not depend on it")
      ->check(kInteger)
      ->check(CLI::Range(0, 4096));
  cmd->callback([args] { run(*args); });
}

}  // namespace tessref::cli
