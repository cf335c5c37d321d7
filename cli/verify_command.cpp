// `tessref verify [SCENE] --ref DIR`: tessref's rendering of a scene against a GL driver's capture
// of it (`tessref capture`), every comparison of verify/verify_scene.h. Exit 0 when every
// tolerance holds, 1 when one does not, 2 for bad input.
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "common/error.h"
#include "pipeline/output_files.h"
#include "verify/verify_scene.h"

namespace tessref::cli {
namespace {

struct VerifyArgs {
  std::string scene, ref, json, heat, images;
  std::vector<std::string> sets;
  int threads = 0;
  VerifyLimits limits;
  bool allow_cracks = false;
};

void run(VerifyArgs a) {
  a.limits.cracks_fail = !a.allow_cracks;
  OutputFiles outputs;
  std::filesystem::path json_tmp, heat_tmp;
  if (!a.json.empty()) json_tmp = outputs.add("--json", a.json);
  if (!a.heat.empty()) {
    check_image_path(a.heat, ImageKind::Color);
    heat_tmp = outputs.add("--heat", a.heat);
  }
  static const char* kImages[4] = {"tessref.png", "reference.png", "difference.png", "heat.png"};
  std::filesystem::path image_tmp[4];
  if (!a.images.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(a.images, ec);
    if (ec) throw InputError(a.images + ": cannot create the folder: " + ec.message());
    for (int k = 0; k < 4; ++k) image_tmp[k] = outputs.add("--images", std::filesystem::path(a.images) / kImages[k]);
  }

  const VerifyResult r = verify_scene(a.scene, a.sets, a.ref, a.limits, Parallel(a.threads));
  for (const auto& w : r.report["warnings"]) std::fprintf(stderr, "tessref: warning: %s\n", w.get<std::string>().c_str());
  std::fputs(verify_summary(r.report).c_str(), stdout);

  if (!a.json.empty()) {
    std::ofstream out(json_tmp);
    out << r.report.dump(2) << "\n";
    if (!out.flush()) throw InputError(a.json + ": cannot write");
  }
  if (!a.heat.empty()) write_rgb8_image(r.heat, heat_tmp);
  if (!a.images.empty()) {
    const Rgb8Image* images[4] = {&r.tessref, &r.reference, &r.difference, &r.heat};
    for (int k = 0; k < 4; ++k) write_rgb8_image(*images[k], image_tmp[k]);
  }
  outputs.commit();
  if (!r.pass()) set_exit_code(1);
}

}  // namespace

void add_verify_command(CLI::App& app) {
  auto args = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "verify", "Compare tessref's rendering of a scene with a GL driver's capture of it (`tessref capture`): "
                "gl_TessCoord streams, surface distances and silhouettes by Embree ray casting, cracks, colour. "
                "Exit 0 when every tolerance holds, 1 when one does not");
  add_scene_options(cmd, args->scene, args->sets);
  cmd->add_option("--ref", args->ref, "the capture folder")->required();
  cmd->add_option("--json", args->json, "also write the report as JSON");
  cmd->add_option("--heat", args->heat, "also write the silhouette heat map (yellow: within the limit, red: beyond)");
  cmd->add_option("--images", args->images,
                  "also write tessref.png, reference.png, difference.png (x8) and heat.png into this folder");
  cmd->add_option("--max-distance", args->limits.max_distance,
                  "largest Hausdorff distance and position difference, as a share of the bounding-box diagonal")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--silhouette-px", args->limits.silhouette_px,
                  "a coverage mismatch whose pixel centre is farther than this from the silhouette fails")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--color-share", args->limits.color_share,
                  "percent of pixels that must be within 2/255 of the reference")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_flag("--allow-cracks", args->allow_cracks, "report cracks between patches without failing");
  cmd->add_option("--threads", args->threads, "worker threads (0: all hardware threads)")
      ->check(kInteger)
      ->check(CLI::Range(0, 4096));
  cmd->callback([args] { run(*args); });
}

}  // namespace tessref::cli
