#include "cli/verify_campaign.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>

#include "cli/verify_html.h"
#include "common/error.h"
#include "io/output_files.h"
#include "scene/json_input.h"

namespace tessref::cli {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

void write_text(OutputFiles& outputs, const std::string& option, const fs::path& target, const std::string& text) {
  write_text_file(outputs.add(option, target), target.string(), text);
}

// One scene's report and images, written together or not at all.
void write_scene_outputs(const fs::path& reports, const std::string& stem, const VerifyResult& r) {
  const fs::path images = reports / stem;
  std::error_code ec;
  fs::create_directories(images, ec);
  if (ec) throw InputError(images.string() + ": cannot create the folder: " + ec.message());
  OutputFiles outputs;
  write_text(outputs, "--out", reports / (stem + ".json"), r.report.dump(2) + "\n");
  const Rgb8Image* pictures[4] = {&r.tessref, &r.reference, &r.difference, &r.heat};
  for (int k = 0; k < 4; ++k) write_rgb8_image(*pictures[k], outputs.add("--out", images / kVerifyImageFiles[k]));
  outputs.commit();
}

struct LoadedReport {
  std::string stem;
  fs::path file;
  json report;
};

// Why a report is not one verify wrote, or "".
std::string malformed(const json& j) {
  if (!j.is_object()) return "not a JSON object";
  if (!j.contains("scene") || !j["scene"].is_string()) return "no \"scene\" string";
  if (!j.contains("pass") || !j["pass"].is_boolean()) return "no \"pass\" true/false";
  if (!j.contains("severity") || !j["severity"].is_number()) return "no \"severity\" number";
  if (!j.contains("failures") || !j["failures"].is_array()) return "no \"failures\" list";
  return "";
}

std::vector<LoadedReport> read_reports(const std::vector<fs::path>& folders) {
  std::map<std::string, LoadedReport> by_stem;  // sorted by name, whatever the folders' order
  for (const fs::path& folder : folders) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) throw InputError(folder.string() + ": --merge needs a reports folder (verify --out)");
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      if (it->path().extension() != ".json" || !it->is_regular_file()) continue;
      LoadedReport r{it->path().stem().string(), it->path(), {}};
      try {
        r.report = read_json_file(r.file, "verify report");
      } catch (const InputError& e) {
        throw InputError(r.file.string() + ": not a verify report: the JSON does not parse (" + e.what() + ")");
      }
      if (const std::string why = malformed(r.report); !why.empty())
        throw InputError(r.file.string() + ": not a verify report: " + why);
      if (auto seen = by_stem.find(r.stem); seen != by_stem.end())
        throw InputError("scene '" + r.stem + "' is reported twice: " + seen->second.file.string() + " and " +
                         r.file.string() + " (merge each campaign's shards once)");
      by_stem.emplace(r.stem, std::move(r));
    }
    if (ec) throw InputError(folder.string() + ": cannot list the reports folder: " + ec.message());
  }
  if (by_stem.empty()) throw InputError("--merge: no <scene>.json report in the folders given");
  std::vector<LoadedReport> out;
  for (auto& [stem, r] : by_stem) out.push_back(std::move(r));
  return out;
}

json merged(const std::vector<LoadedReport>& reports) {
  json scenes = json::array();
  int failed = 0;
  double worst = -1.0;
  std::string worst_scene;
  for (const LoadedReport& r : reports) {
    scenes.push_back({{"name", r.stem}, {"report", r.report}});
    failed += !r.report["pass"].get<bool>();
    const double s = r.report["severity"].get<double>();
    if (s > worst) worst = s, worst_scene = r.stem;  // ties: the first by name
  }
  const int count = int(reports.size());
  return {{"summary",
           {{"scenes", count}, {"passed", count - failed}, {"failed", failed}, {"pass", failed == 0},
            {"worst_severity", worst}, {"worst_scene", worst_scene}}},
          {"scenes", scenes}};
}

}  // namespace

int run_verify_campaign(const VerifyCampaign& c, const Parallel& parallel) {
  const std::vector<CampaignScene> scenes = campaign_scenes(c.scenes, c.shard);
  // Every capture first: a campaign should not stop an hour in for a missing folder.
  for (const CampaignScene& s : scenes) {
    std::error_code ec;
    if (!fs::is_directory(c.captures / s.stem, ec))
      throw InputError("scene '" + s.stem + "' (" + s.path.string() + ") has no capture: " +
                       (c.captures / s.stem).string() + " is not a folder (tessref capture " + c.scenes.string() +
                       " --out " + c.captures.string() + ")");
  }
  std::error_code ec;
  fs::create_directories(c.reports, ec);
  if (ec) throw InputError(c.reports.string() + ": cannot create the --out folder: " + ec.message());
  std::fprintf(stderr, "tessref verify: shard %d/%d: %zu scene(s) of %s\n", c.shard.index, c.shard.count, scenes.size(),
               c.scenes.string().c_str());
  int failed = 0;
  std::vector<SiteScene> site;
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const CampaignScene& s = scenes[k];
    const auto start = std::chrono::steady_clock::now();
    VerifyResult r;
    try {
      r = verify_scene(s.path.string(), c.sets, (c.captures / s.stem).string(), c.limits, parallel);
    } catch (const InputError& e) {
      throw InputError("scene '" + s.stem + "': " + e.what());
    }
    write_scene_outputs(c.reports, s.stem, r);
    failed += !r.pass();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "tessref verify: [%zu/%zu] %s: %s (severity %.3g, %.1f s)\n", k + 1, scenes.size(),
                 s.stem.c_str(), r.pass() ? "PASS" : "FAIL", r.report.value("severity", 0.0), seconds);
    for (const auto& f : r.report["failures"]) std::fprintf(stderr, "  FAIL: %s\n", f.get<std::string>().c_str());
    if (!c.html.empty()) site.push_back({s.stem, r.report, c.reports / s.stem});
  }
  if (!c.html.empty()) write_verify_site(c.html, site);
  std::fprintf(stderr, "tessref verify: shard %d/%d: %zu passed, %d failed\n", c.shard.index, c.shard.count,
               scenes.size() - std::size_t(failed), failed);
  return failed;
}

json merge_verify_reports(const std::vector<fs::path>& folders) { return merged(read_reports(folders)); }

int run_verify_merge(const std::vector<fs::path>& folders, const fs::path& json_out, const fs::path& html) {
  const std::vector<LoadedReport> reports = read_reports(folders);
  const json m = merged(reports);
  if (!json_out.empty()) {
    OutputFiles outputs;
    write_text(outputs, "--json", json_out, m.dump(2) + "\n");
    outputs.commit();
  }
  if (!html.empty()) {
    std::vector<SiteScene> site;
    for (const LoadedReport& r : reports) site.push_back({r.stem, r.report, r.file.parent_path() / r.stem});
    write_verify_site(html, site);
  }
  const json& s = m["summary"];
  std::printf("tessref verify --merge: %d scenes, %d passed, %d failed; worst severity %.3g (%s)\n",
              s["scenes"].get<int>(), s["passed"].get<int>(), s["failed"].get<int>(),
              s["worst_severity"].get<double>(), s["worst_scene"].get<std::string>().c_str());
  return s["failed"].get<int>();
}

}  // namespace tessref::cli
