// `tessref verify [SCENE] --ref DIR`: tessref's rendering of a scene against a GL driver's capture
// of it (`tessref capture`), every comparison of verify/verify_scene.h. With a folder of scenes, a
// campaign (cli/verify_campaign.h); with --merge, the merge of campaigns' reports. Exit 0 when
// every tolerance holds, 1 when one does not, 2 for bad input.
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/shard.h"
#include "cli/verify_campaign.h"
#include "cli/verify_gpu.h"
#include "cli/verify_html.h"
#include "common/error.h"
#include "io/output_files.h"
#include "verify/verify_scene.h"

namespace tessref::cli {
namespace {

struct VerifyArgs {
  std::string scene, ref, gpu, json, heat, images, html, out, shard;
  std::vector<std::string> sets, merge;
  int threads = 0;
  VerifyLimits limits;
  bool allow_cracks = false;
};

// Options that belong to one mode only, given in another: name them rather than ignore them.
void refuse(const std::string& value, const std::string& option, const std::string& mode) {
  if (!value.empty()) throw InputError(option + " does not apply " + mode);
}

void run_merge(const VerifyArgs& a) {
  const std::string mode = "with --merge (it reads reports, not scenes)";
  refuse(a.scene, "a SCENE", mode);
  refuse(a.ref, "--ref", mode);
  refuse(a.out, "--out", mode);
  refuse(a.shard, "--shard", mode);
  refuse(a.heat, "--heat", mode);
  refuse(a.images, "--images", mode);
  if (a.json.empty() && a.html.empty()) throw InputError("--merge needs --json FILE or --html DIR (or both)");
  const std::vector<std::filesystem::path> folders(a.merge.begin(), a.merge.end());
  if (run_verify_merge(folders, a.json, a.html) > 0) set_exit_code(1);
}

void run_campaign(const VerifyArgs& a) {
  const std::string mode = "to a folder of scenes (each scene's report and images go under --out)";
  refuse(a.json, "--json", mode);
  refuse(a.heat, "--heat", mode);
  refuse(a.images, "--images", mode);
  if (a.ref.empty()) throw InputError("a folder of scenes needs --ref CAPTURES_DIR (one capture folder per scene)");
  if (a.out.empty()) throw InputError("a folder of scenes needs --out REPORTS_DIR");
  VerifyCampaign c;
  c.scenes = a.scene;
  c.captures = a.ref;
  c.reports = a.out;
  c.html = a.html;
  c.sets = a.sets;
  c.limits = a.limits;
  if (!a.shard.empty()) c.shard = parse_shard(a.shard);
  if (run_verify_campaign(c, Parallel(a.threads)) > 0) set_exit_code(1);
}

void run(VerifyArgs a) {
  a.limits.cracks_fail = !a.allow_cracks;
  if (!a.merge.empty()) return run_merge(a);
  if (!a.gpu.empty()) {
    const std::string mode = "with --gpu (it compares the image alone)";
    for (const auto& [value, option] : {std::pair{a.ref, "--ref"}, {a.json, "--json"}, {a.heat, "--heat"},
                                        {a.images, "--images"}, {a.html, "--html"}, {a.out, "--out"}})
      refuse(value, option, mode);
    std::error_code ec;
    if (a.scene.empty() && !std::filesystem::exists(std::filesystem::path(a.gpu) / "scene.json", ec)) {
      if (!a.sets.empty()) throw InputError("--set applies to one scene, not to a folder of imported frames");
      return set_exit_code(run_verify_gpu_folder(a.gpu, a.shard, a.threads));
    }
    refuse(a.shard, "--shard", "to one imported frame (give a folder of them to --gpu)");
    const std::string scene = a.scene.empty() ? (std::filesystem::path(a.gpu) / "scene.json").string() : a.scene;
    return set_exit_code(run_verify_gpu(scene, a.sets, a.gpu, a.threads));
  }
  std::error_code ec;
  if (!a.scene.empty() && std::filesystem::is_directory(a.scene, ec)) return run_campaign(a);
  const std::string mode = "to one scene (give a folder of scenes for a campaign)";
  refuse(a.out, "--out", mode);
  refuse(a.shard, "--shard", mode);
  if (a.ref.empty())
    throw InputError("--ref DIR is required: the capture folder (tessref capture); or --gpu DIR for an imported frame (tessref import)");
  OutputFiles outputs;
  std::filesystem::path json_tmp, heat_tmp;
  if (!a.json.empty()) json_tmp = outputs.add("--json", a.json);
  if (!a.heat.empty()) {
    check_image_path(a.heat, ImageKind::Color);
    heat_tmp = outputs.add("--heat", a.heat);
  }
  // Folders made for --images and --html are removed again if verify stops on bad input.
  std::optional<CreatedFolder> images_folder, html_folder;
  std::filesystem::path image_tmp[4];
  if (!a.images.empty()) {
    images_folder.emplace(a.images, "the --images folder");
    for (int k = 0; k < 4; ++k)
      image_tmp[k] = outputs.add("--images", std::filesystem::path(a.images) / kVerifyImageFiles[k]);
  }
  // --html DIR: DIR/index.html with the images embedded, and the PNGs beside it.
  VerifyImages html_images;
  std::filesystem::path html_tmp;
  if (!a.html.empty()) {
    html_folder.emplace(a.html, "the --html folder");
    for (int k = 0; k < 4; ++k)
      html_images[k] = outputs.add("--html", std::filesystem::path(a.html) / kVerifyImageFiles[k]);
    html_tmp = outputs.add("--html", std::filesystem::path(a.html) / "index.html");
  }

  const VerifyResult r = verify_scene(a.scene, a.sets, a.ref, a.limits, Parallel(a.threads));
  for (const auto& w : r.report["warnings"]) std::fprintf(stderr, "tessref: warning: %s\n", w.get<std::string>().c_str());
  std::fputs(verify_summary(r.report).c_str(), stdout);

  if (!a.json.empty()) write_text_file(json_tmp, a.json, r.report.dump(2) + "\n");
  if (!a.heat.empty()) write_as(heat_tmp, a.heat, [&] { write_rgb8_image(r.heat, heat_tmp); });
  const Rgb8Image* images[4] = {&r.tessref, &r.reference, &r.difference, &r.heat};
  for (int k = 0; k < 4 && !a.images.empty(); ++k)
    write_as(image_tmp[k], std::filesystem::path(a.images) / kVerifyImageFiles[k],
             [&] { write_rgb8_image(*images[k], image_tmp[k]); });
  if (!a.html.empty()) {
    for (int k = 0; k < 4; ++k)
      write_as(html_images[k], std::filesystem::path(a.html) / kVerifyImageFiles[k],
               [&] { write_rgb8_image(*images[k], html_images[k]); });
    write_text_file(html_tmp, a.html + "/index.html", verify_scene_page(r.report, html_images, ""));
  }
  outputs.commit();
  if (images_folder) images_folder->keep();
  if (html_folder) html_folder->keep();
  if (!r.pass()) set_exit_code(1);
}

}  // namespace

void add_verify_command(CLI::App& app) {
  auto args = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "verify", "Compare tessref's rendering of a scene with a GL driver's capture of it (`tessref capture`): "
                "gl_TessCoord streams, surface distances and silhouettes by Embree ray casting, cracks, colour. "
                "SCENE may be a folder of scenes (a campaign: --ref holds one capture folder per scene, named "
                "after its file, --out gets the reports). Exit 0 when every tolerance holds, 1 when one does not");
  add_scene_options(cmd, args->scene, args->sets);
  cmd->add_option("--ref", args->ref, "the capture folder (a campaign: the folder of capture folders)");
  cmd->add_option("--gpu", args->gpu,
                  "instead of --ref: the GPU's image of an imported frame (tessref import's DIR, for DIR/gpu.png and, "
                  "without SCENE, DIR/scene.json; or an image file); names the first pixel beyond 1/255, the draw and "
                  "patch tessref drew there and the inspect commands that open them. A folder of imported frames "
                  "(tessref import of a folder of captures) is a campaign, with --shard");
  cmd->add_option("--json", args->json, "also write the report as JSON (with --merge: the merged report)");
  cmd->add_option("--html", args->html,
                  "also write an HTML report into this folder: index.html (with --merge or a campaign: an index "
                  "of the scenes, worst first, and one SCENE.html each)");
  cmd->add_option("--out", args->out, "a campaign's reports folder: STEM.json and the images under STEM/ per scene");
  cmd->add_option("--shard", args->shard,
                  "a campaign's shard I/N (0-based: scenes whose index in the name-sorted folder is I mod N); "
                  "'auto' or 'auto/N' reads I (and N) from SLURM_ARRAY_TASK_ID/_COUNT or JOB_COMPLETION_INDEX "
                  "(with TESSREF_SHARD_COUNT)");
  cmd->add_option("--merge", args->merge,
                  "merge the reports of campaigns (their --out folders, e.g. one per shard) into --json and/or "
                  "--html; exit 1 if any scene failed")
      ->expected(1, -1);
  cmd->add_option("--heat", args->heat, "also write the silhouette heat map (yellow: within the limit, red: beyond)");
  cmd->add_option("--images", args->images,
                  "also write tessref.png, reference.png, difference.png (x8) and heat.png into this folder");
  cmd->add_option("--max-distance", args->limits.max_distance,
                  "largest Hausdorff distance and position difference, as a share of the bounding-box diagonal")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--max-normal", args->limits.max_normal,
                  "largest normal difference at the same patch and gl_TessCoord, relative to the longer normal "
                  "(mesh scenes; 2 is a flipped normal)")
      ->check(CLI::Range(0.0, 2.0))
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
