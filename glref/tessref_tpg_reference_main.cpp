// tessref-tpg-reference: captures the primitive generator of the GL driver at hand over the
// standard sweep (stages/tpg_sweep.h), writes a compact dataset, and reports how the driver
// compares with tessref's generator (identical streams, largest coordinate difference).
//
// Dataset (DIR): manifest.txt; per layout NAME.hashes (one 64-bit stream hash per level set of the
// full sweep, in order) and NAME.full (complete streams of a short sweep, one line per patch:
// "index count hex...").
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <CLI/CLI.hpp>

#include "common/error.h"
#include "glref/gl_context.h"
#include "glref/tess_capture.h"
#include "glref/tpg_output.h"
#include "stages/tpg.h"
#include "stages/tpg_stream.h"
#include "stages/tpg_sweep.h"

namespace fs = std::filesystem;
using namespace tessref;

namespace {

struct Comparison {
  std::size_t identical = 0, count_differs = 0;
  double max_abs_diff = 0.0;  // over streams of equal length
};

Comparison compare(const TessLayout& layout, const std::vector<TessLevels>& levels,
                   const std::vector<std::vector<glm::vec3>>& captured) {
  Comparison c;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const auto ours = emitted_stream(generate_tessellation(layout, levels[i]));
    if (ours.size() != captured[i].size()) {
      ++c.count_differs;
      continue;
    }
    bool same = true;
    for (std::size_t v = 0; v < ours.size(); ++v)
      for (int k = 0; k < 3; ++k) {
        const double d = std::fabs(double(ours[v][k]) - double(captured[i][v][k]));
        same &= ours[v][k] == captured[i][v][k];
        c.max_abs_diff = std::max(c.max_abs_diff, d);
      }
    c.identical += same;
  }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Capture a GL driver's tessellation primitive generator over tessref's standard "
               "sweep, write a dataset and compare it with tessref"};
  std::string out_dir, platform = "auto";
  std::size_t sets = 2000, full = 6;
  app.add_option("--out", out_dir, "dataset folder to write (omit to only compare)");
  app.add_option("--sets", sets, "level sets per layout in the hashed sweep")->capture_default_str();
  app.add_option("--full", full, "level sets per layout stored in full")->capture_default_str();
  app.add_option("--platform", platform, "EGL platform: auto | surfaceless | device")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    glref::GlContextOptions options;
    if (!glref::parse(platform, options.platform))
      throw InputError("--platform: '" + platform + "' is not auto, surfaceless or device");
    glref::GlContext context(options);
    glref::TessCapture capture(context);
    std::printf("driver: %s | %s | EGL %s (%s)\n", context.renderer().c_str(),
                context.version().c_str(), context.egl_vendor().c_str(),
                glref::to_string(context.platform()));
    if (!out_dir.empty()) {
      fs::create_directories(out_dir);
      std::ofstream manifest(fs::path(out_dir) / "manifest.txt");
      manifest << "renderer: " << context.renderer() << "\nversion: " << context.version()
               << "\negl_vendor: " << context.egl_vendor() << "\nsets: " << sets
               << "\nfull: " << full
               << "\nseeds: hashes 1000 + layout index (SweepRange::Full), "
                  "full 5000 + layout index (SweepRange::Small)\n";
    }
    std::size_t total = 0, total_identical = 0;
    double worst = 0.0;
    const std::vector<TessLayout> layouts = sweep_layouts();
    for (std::size_t li = 0; li < layouts.size(); ++li) {
      const TessLayout& layout = layouts[li];
      const std::string name = sweep_name(layout);
      const auto levels = sweep_levels(1000 + li, sets, SweepRange::Full);
      const auto captured = capture.capture(layout, levels);
      const Comparison c = compare(layout, levels, captured);
      total += levels.size();
      total_identical += c.identical;
      worst = std::max(worst, c.max_abs_diff);
      std::printf("%-40s %zu / %zu identical, %zu differ in count, max |diff| %.3g\n",
                  name.c_str(), c.identical, levels.size(), c.count_differs, c.max_abs_diff);
      if (out_dir.empty()) continue;
      std::ofstream hashes(fs::path(out_dir) / (name + ".hashes"));
      for (const auto& stream : captured) {
        char line[24];
        std::snprintf(line, sizeof line, "%016" PRIx64 "\n", stream_hash(stream));
        hashes << line;
      }
      const auto small = sweep_levels(5000 + li, full, SweepRange::Small);
      const auto small_captured = capture.capture(layout, small);
      std::ofstream full_file(fs::path(out_dir) / (name + ".full"));
      for (std::size_t i = 0; i < small.size(); ++i)
        full_file << glref::format_sweep_line(layout.domain, i, small_captured[i]);
    }
    std::printf("total: %zu / %zu level sets identical (%.2f%%), max |diff| %.3g\n",
                total_identical, total, 100.0 * double(total_identical) / double(total), worst);
    return total_identical == total ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessref-tpg-reference: %s\n", e.what());
    return 2;
  }
}
