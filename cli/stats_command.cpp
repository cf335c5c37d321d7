// `tessref stats [--table N] [--json FILE]`: seed 004's surface interrogation statistics (Tables
// 3-6 of Boschiroli et al.) as tessref measures them, in the paper's layout; `tessref stats SCENE`
// (or --set over the default scene) measures the scene's mesh the same way. docs/stats.md has the tables beside the paper's and the
// conventions recovered from its numbers.
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/scene_name.h"
#include "cli/stats_images.h"
#include "common/error.h"
#include "mesh/mesh_source.h"
#include "io/output_files.h"
#include "scene/scene_loader.h"
#include "stats/seed004_tables.h"

namespace tessref::cli {
namespace {

struct StatsArgs {
  std::string scene, json;
  std::vector<std::string> sets;
  int table = 0;  // 0: all four
  double nagata_eps = 0.0;
  int threads = 0;
  StatsImageArgs image;  // --image: cli/stats_images.h
};

void print(const char* title, const std::string& table) {
  std::printf("%s\n%s\n", title, table.c_str());
}

nlohmann::json run_tables(const StatsArgs& a, const Parallel& parallel) {
  nlohmann::json report = nlohmann::json::object();
  auto wants = [&](int n) { return a.table == 0 || a.table == n; };
  if (wants(3)) {
    const auto rows = stats::seed004_table3(parallel);
    print("Table 3: signed distance to the sphere and torus (std dev: the paper's, docs/stats.md)",
          stats::format_table3(rows));
    report["table3"] = stats::to_json(rows);
  }
  if (wants(4)) {
    const auto rows = stats::seed004_table4();
    print("Table 4: meshes (cosine between vertex and face normals; edges by shape, and as the paper counts them)",
          stats::format_table4(rows));
    report["table4"] = stats::to_json(rows);
  }
  if (wants(5)) {
    const auto rows = stats::seed004_table5(parallel);
    print("Table 5: Gaussian curvature (interior points of the 21-a-side grid)", stats::format_table5(rows));
    report["table5"] = stats::to_json(rows);
  }
  if (wants(6)) {
    const auto rows = stats::seed004_table6(parallel);
    print("Table 6: cosine between adjacent patches' normals (21 points an edge)", stats::format_table6(rows));
    report["table6"] = stats::to_json(rows);
  }
  return report;
}

nlohmann::json run_scene(const StatsArgs& a, const Parallel& parallel) {
  const Scene scene = load_scene(a.scene, a.sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
  const stats::MeshReport r = stats::measure_mesh("mesh", mesh, a.nagata_eps, parallel);
  std::printf("%s (model space)\n\n", drawn_scene_name(scene, a.sets).c_str());
  print("Mesh", stats::format_table4({r.mesh}));
  print("Gaussian curvature", stats::format_table5(r.curvature));
  print("Cosine between adjacent patches' normals", stats::format_table6(r.edge_normals));
  return {{"scene", drawn_scene_name(scene, a.sets)},
          {"mesh", stats::to_json(std::vector<stats::MeshRow>{r.mesh})[0]},
          {"gaussian_curvature", stats::to_json(r.curvature)},
          {"adjacent_normal_cosine", stats::to_json(r.edge_normals)}};
}

void run(const StatsArgs& a) {
  check_stats_image_args(a.image, a.table != 0);
  // A SCENE or a --set (over the default scene) asks for the scene's mesh.
  const bool scene_mode = !a.scene.empty() || !a.sets.empty();
  if (scene_mode && a.table != 0)
    throw InputError("--table prints one of seed 004's tables; it does not combine with a SCENE or --set");
  OutputFiles outputs;
  std::filesystem::path json_tmp;
  std::filesystem::path image_tmp;
  if (!a.image.kind.empty()) image_tmp = outputs.add("-o", a.image.output);
  if (!a.json.empty()) json_tmp = outputs.add("--json", a.json);
  const Parallel parallel(a.threads);
  const nlohmann::json report = !a.image.kind.empty() ? run_stats_image(a.scene, a.sets, a.image, parallel, image_tmp)
                                : scene_mode           ? run_scene(a, parallel)
                                                       : run_tables(a, parallel);
  if (!a.json.empty()) write_text_file(json_tmp, a.json, report.dump(2) + "\n");
  outputs.commit();
}

}  // namespace

void add_stats_command(CLI::App& app) {
  auto args = std::make_shared<StatsArgs>();
  CLI::App* cmd = app.add_subcommand(
      "stats",
      "Seed 004's surface statistics (Boschiroli et al., Tables 3-6) as tessref measures them: distances of the "
      "four interpolants (Phong, Nagata, NLSA, PN) to the sphere and torus, mesh statistics, Gaussian curvature, "
      "normals across shared edges; with a SCENE or --set, the same for the scene's mesh (docs/stats.md)");
  add_scene_options(cmd, args->scene, args->sets);
  cmd->add_option("--table", args->table, "print only seed 004's Table N (3, 4, 5 or 6)")
      ->check(kInteger)
      ->check(CLI::IsMember({3, 4, 5, 6}));
  cmd->add_option("--json", args->json, "also write the numbers as JSON");
  cmd->add_option("--nagata-eps", args->nagata_eps,
                  "for a scene's mesh: Nagata's threshold eps (seed 004 used 0 to 0.06)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.5));
  cmd->add_option("--threads", args->threads, "worker threads (0: all); the results do not depend on it")
      ->check(kInteger)
      ->check(CLI::Range(0, 4096));
  add_stats_image_options(cmd, args->image);
  cmd->callback([args] { run(*args); });
}

}  // namespace tessref::cli
