// Turns one scripts/bench.sh run into a Markdown table: the JSON that the benchmarks wrote
// (--benchmark_out, Google Benchmark's format) and machine_limits --json.
//
//   bench_report --limits FILE [--machine TEXT] [--date TEXT] [--notes TEXT] [-o FILE] BENCH.json...
//
// Per benchmark, the median over its repetitions of the real time per iteration and of each
// counter. Each figure is also given as a share of the machine's limits: the work model's bytes
// and flops per iteration (bench/work_model.h; counters model_bytes, model_flops) over the time,
// against the bandwidth and FMA peak for the threads that side uses. The larger share names the
// limit that binds. Writes the table to -o (if given) and stdout.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "work_model.h"

namespace {

using nlohmann::json;

struct Result {
  int repetitions = 0;
  double seconds = 0.0;  // median real time per iteration
  std::map<std::string, double> counters;  // medians
  std::string label;
  double counter(const std::string& name, double fallback = 0.0) const {
    const auto it = counters.find(name);
    return it == counters.end() ? fallback : it->second;
  }
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double unit_seconds(const std::string& unit) {
  if (unit == "ns") return 1e-9;
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  return 1.0;
}

// Keys of a benchmark entry that are not counters.
bool is_counter_key(const std::string& k, const json& v) {
  static const char* const fixed[] = {"name", "family_index", "per_family_instance_index",
                                      "run_name", "run_type", "repetitions", "repetition_index",
                                      "threads", "iterations", "real_time", "cpu_time",
                                      "time_unit", "label", "error_occurred", "error_message",
                                      "aggregate_name", "aggregate_unit"};
  for (const char* f : fixed)
    if (k == f) return false;
  return v.is_number();
}

struct Runs {
  std::map<std::string, Result> results;
  std::map<std::string, std::string> errors;
  json context;

  void read(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    // Google Benchmark writes a constant counter's coefficient of variation (0 / 0) as a bare
    // NaN, which is not JSON; such a value is no figure, so it becomes null.
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    static const std::regex not_a_number(R"(:\s*-?(NaN|nan|inf|Infinity)\b)");
    const json j = json::parse(std::regex_replace(text, not_a_number, ": null"));
    if (context.is_null() && j.contains("context")) context = j["context"];
    std::map<std::string, std::vector<const json*>> by_run;
    const json benchmarks = j.value("benchmarks", json::array());
    for (const json& b : benchmarks) {
      const std::string run = b.value("run_name", b.value("name", ""));
      if (b.value("error_occurred", false)) {
        errors[run] = b.value("error_message", "error");
        continue;
      }
      if (b.value("run_type", "iteration") != "iteration") continue;
      by_run[run].push_back(&b);
    }
    for (const auto& [run, entries] : by_run) {
      Result r;
      r.repetitions = int(entries.size());
      std::vector<double> times;
      std::map<std::string, std::vector<double>> counters;
      for (const json* e : entries) {
        times.push_back(e->value("real_time", 0.0) * unit_seconds(e->value("time_unit", "ns")));
        for (const auto& [k, v] : e->items())
          if (is_counter_key(k, v)) counters[k].push_back(v.get<double>());
        if (e->contains("label")) r.label = (*e)["label"].get<std::string>();
      }
      r.seconds = median(times);
      for (auto& [k, v] : counters) r.counters[k] = median(v);
      results[run] = r;
    }
  }
  const Result* find(const std::string& run) const {
    const auto it = results.find(run);
    return it == results.end() ? nullptr : &it->second;
  }
};

struct Limits {
  int threads = 1;
  bool disturbed = false;  // an all-thread figure was floored at the one-thread one
  std::string fma_kind;
  double copy[2]{}, write[2]{}, cache_write[2]{}, fma[2]{};
  void read(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    const json j = json::parse(in);
    threads = j.value("threads", 1);
    fma_kind = j.value("fma_kind", "");
    disturbed = j.value("all_threads_disturbed", false);
    for (int i = 0; i < 2; ++i) {
      copy[i] = j["copy_gbs"][i].get<double>();
      write[i] = j["write_gbs"][i].get<double>();
      cache_write[i] = j["cache_write_gbs"][i].get<double>();
      fma[i] = j["fma_gflops"][i].get<double>();
    }
  }
  // Bandwidth for the model's bytes: DRAM (the better of copy and write) or L2 (cache write).
  double bandwidth(bool all_threads, bool in_cache) const {
    const int i = all_threads ? 1 : 0;
    return in_cache ? cache_write[i] : std::max(copy[i], write[i]);
  }
};

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// What each figure measures and how it is read.
enum class Kind { FrameMs, Rate };

struct Row {
  std::string figure;
  std::string tessref, llvmpipe;  // run names
  Kind kind;
  std::string rate_counter;  // Kind::Rate: the counter (per second)
  double rate_scale;         // shown as rate / rate_scale
  bool tessref_all_threads, llvmpipe_all_threads;
  bool in_cache;  // bytes compared with the L2 write rate
  std::string target;  // "<= 0.33", ">= 3" or "" (the issue sets none): tessref/llvmpipe's bound
  // Kind::Rate: other runs the tessref figure is divided by, named in the figure cell
  // (label, run name): e.g. the executor's rate against the C++ programs'.
  std::vector<std::pair<std::string, std::string>> versus = {};
};

// Whether ratio q meets a target "<= X" or ">= X".
bool meets(const std::string& target, double q) {
  const double bound = std::stod(target.substr(2));
  return target[0] == '<' ? q <= bound : q >= bound;
}

struct Share {
  bool ok = false;
  double mem = 0, fma = 0;
};

// The work per second of one side: for a rate, its rate counter times the model's bytes and
// flops per item (so the share is of the figure shown); for a frame, the model's work per frame
// over the frame time. The model comes from the side's own counters, else from `model`'s.
Share share(const Row& row, const Result& side, const Result& model, bool all_threads,
            const Limits& limits) {
  Share s;
  auto get = [&](const char* name) { return side.counter(name, model.counter(name)); };
  const double bytes = get("model_bytes"), flops = get("model_flops"), items = get("model_items");
  double per_second = 0.0;  // iterations (frames) or items per second
  if (row.kind == Kind::FrameMs) per_second = side.seconds > 0 ? 1.0 / side.seconds : 0.0;
  else per_second = items > 0 ? side.counter(row.rate_counter) / items : 0.0;
  if (per_second <= 0 || (bytes <= 0 && flops <= 0)) return s;
  s.ok = true;
  s.mem = bytes * per_second / 1e9 / limits.bandwidth(all_threads, row.in_cache);
  s.fma = flops * per_second / 1e9 / limits.fma[all_threads ? 1 : 0];
  return s;
}

std::string percent(double share) {
  const double p = 100 * share;
  return fmt(p >= 10 ? "%.0f%%" : p >= 1 ? "%.1f%%" : "%.2f%%", p);
}

std::string share_cell(const Share& s, bool in_cache) {
  if (!s.ok) return "n/a";
  const std::string mem = percent(s.mem) + (in_cache ? " L2" : " mem");
  const std::string fma = percent(s.fma) + " fma";
  return s.mem >= s.fma ? "**" + mem + "**, " + fma : "**" + fma + "**, " + mem;
}

std::string thousands(double v) {
  std::string s = fmt("%.0f", v), out;
  const int n = int(s.size());
  for (int i = 0; i < n; ++i) {
    out += s[i];
    if ((n - i - 1) % 3 == 0 && i + 1 < n) out += ',';
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string limits_path, machine = "unknown", date, notes, out_path;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--limits") limits_path = value();
      else if (a == "--machine") machine = value();
      else if (a == "--date") date = value();
      else if (a == "--notes") notes = value();
      else if (a == "-o") out_path = value();
      else inputs.push_back(a);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_report: %s\n", e.what());
      return 2;
    }
  }
  Runs runs;
  Limits limits;
  try {
    for (const std::string& p : inputs) runs.read(p);
    if (!limits_path.empty()) limits.read(limits_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_report: %s\n", e.what());
    return 2;
  }
  if (date.empty() && runs.context.contains("date")) date = runs.context["date"].get<std::string>();
  const int n = limits.threads;
  const std::string all = std::to_string(n) + " threads";

  std::vector<Row> rows;
  const struct {
    const char* scene;
    const char* what;
    const char* target;
  } frames[] = {{"pn12", "default scene: torus (256 triangles), PN level 12", "<= 0.33"},
                {"ico64", "icosphere (80 triangles), PN level 64", "<= 0.33"},
                {"wuson12", "Wuson (3,732 triangles), PN level 12", "<= 0.33"},
                {"wuson64", "Wuson (3,732 triangles), PN level 64", "<= 0.33"},
                {"textured", "default scene as GLSL on the executor, textured fragment shader (scenes/textured.json)",
                 "<= 0.5"}};
  for (const auto& f : frames)
    rows.push_back({std::string("frame ms, ") + f.what, std::string("BM_TessrefFrame/") + f.scene + "/real_time",
                    std::string("BM_LlvmpipeFrame/") + f.scene + "/fair/real_time", Kind::FrameMs, "", 1,
                    true, true, false, f.target});
  for (int level : {8, 16, 64}) {
    const std::string l = std::to_string(level);
    rows.push_back({"TPG Mpoints/s, triangles fractional_odd, level " + l + " (one patch at a time)",
                    "BM_TessrefTpg/" + l + "/real_time", "BM_LlvmpipeTpg/" + l + "/real_time", Kind::Rate, "points_per_s", 1e6, false,
                    false, true, ""});
  }
  for (const auto& [level, chunk] : {std::pair{12, 256}, std::pair{64, 16}}) {
    const std::string l = std::to_string(level);
    rows.push_back({"PN Mvertices/s (TES invocations), quadratic normals, level " + l +
                        ", icosphere 320 triangles; tessref " + std::to_string(chunk) +
                        "-patch chunks, llvmpipe rasterizer discard",
                    "BM_TessrefPn/" + l + "/" + std::to_string(chunk) + "/real_time",
                    "BM_LlvmpipePnDiscard/" + l + "/real_time", Kind::Rate, "vertices_per_s", 1e6, true,
                    false, false, ">= 3"});
  }
  // The same draws with the GLSL twins on tessref's SPIR-V executor (pn_bench's BM_ExecutorPn).
  for (const auto& [level, chunk] : {std::pair{12, 256}, std::pair{64, 16}}) {
    const std::string lc = std::to_string(level) + "/" + std::to_string(chunk);
    rows.push_back({"PN Mvertices/s, level " + std::to_string(level) +
                        ", the same draw with the GLSL twins (pn_triangles.tesc/.tese) on tessref's executor, "
                        "batch 256",
                    "BM_ExecutorPn/" + lc + "/256/real_time", "BM_LlvmpipePnDiscard/" + std::to_string(level) + "/real_time",
                    Kind::Rate, "vertices_per_s", 1e6, true, false, false, ">= 1",
                    {{"C++ programs", "BM_TessrefPn/" + lc + "/real_time"},
                     {"batch 1", "BM_ExecutorPn/" + lc + "/1/real_time"}}});
  }
  rows.push_back({"raster Mtriangles/s, seeded soup of 1,000,200 clip-space triangles (0.3-6 px, 200 of "
                  "32-256 px), 1024x1024 RGBA32F + depth, constant color",
                  "BM_TessrefRaster/real_time", "BM_LlvmpipeRaster/real_time", Kind::Rate, "triangles_per_s",
                  1e6, true, true, false, ""});

  std::ostringstream md;
  md << "### scripts/bench.sh, " << date << "\n\n";
  md << "Machine: " << machine << ". " << notes << "\n\n";
  md << "| figure | tessref | llvmpipe | tessref/llvmpipe | target | tessref: share of limit | llvmpipe: share of limit |\n";
  md << "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Row& r : rows) {
    const Result* t = runs.find(r.tessref);
    const Result* l = runs.find(r.llvmpipe);
    if (!t && !l) continue;
    auto value = [&](const Result* x) -> std::string {
      if (!x) return "n/a";
      if (r.kind == Kind::FrameMs) return fmt(x->seconds * 1e3 >= 100 ? "%.0f" : "%.1f", x->seconds * 1e3);
      return fmt("%.2f", x->counter(r.rate_counter) / r.rate_scale);
    };
    std::string ratio = "n/a", met;
    if (t && l) {
      double q = 0;
      if (r.kind == Kind::FrameMs) q = t->seconds / l->seconds;
      else if (l->counter(r.rate_counter) > 0) q = t->counter(r.rate_counter) / l->counter(r.rate_counter);
      ratio = r.kind == Kind::FrameMs ? fmt("%.2f", q) : fmt("%.2fx", q);
      if (!r.target.empty()) met = meets(r.target, q) ? " (met)" : " (not met)";
    }
    std::string figure = r.figure;
    // "; vs C++ programs (53.79): 0.25x": the other run's figure and tessref's ratio to it.
    for (const auto& [label, run] : r.versus) {
      const Result* o = runs.find(run);
      const double rate = o ? o->counter(r.rate_counter) : 0.0;
      figure += "; vs " + label + " (" + (o ? fmt("%.2f", rate / r.rate_scale) : "n/a") + "): " +
                (t && rate > 0 ? fmt("%.2fx", t->counter(r.rate_counter) / rate) : "n/a");
    }
    if (t && r.kind == Kind::FrameMs && t->counter("triangles") > 0)
      figure += " (" + thousands(t->counter("triangles")) + " triangles)";
    const std::string tt = r.tessref_all_threads ? all : "1 thread";
    const std::string lt = r.llvmpipe_all_threads ? all : "1 thread";
    const Result* model = t ? t : l;
    md << "| " << figure << " | " << value(t) << " (" << tt << ") | " << value(l) << " (" << lt << ") | "
       << ratio << " | " << (r.target.empty() ? "-" : r.target) << met << " | "
       << (t ? share_cell(share(r, *t, *model, r.tessref_all_threads, limits), r.in_cache) : "n/a")
       << " | "
       << (l ? share_cell(share(r, *l, *model, r.llvmpipe_all_threads, limits), r.in_cache) : "n/a")
       << " |\n";
  }
  bool any_error = false;
  std::set<std::string> reported;
  for (const Row& r : rows) {
    std::vector<std::string> names{r.tessref, r.llvmpipe};
    for (const auto& v : r.versus) names.push_back(v.second);
    for (const std::string& run : names)
      if (runs.errors.count(run) && reported.insert(run).second) {
        if (!any_error) md << "\nFailed or skipped:\n";
        any_error = true;
        md << "- `" << run << "`: " << runs.errors.at(run) << "\n";
      }
  }

  if (!limits_path.empty()) {
    md << "\nMachine limits (`machine_limits`, best of its trials"
       << (limits.disturbed ? "; where the all-thread run came out below one thread's, other work was "
                              "sharing the cores and the one-thread figure is given"
                            : "")
       << "):\n\n";
    md << "| limit | 1 thread | " << all << " |\n| --- | --- | --- |\n";
    md << "| memory copy GB/s (memcpy, read + write, arrays >> caches) | " << fmt("%.1f", limits.copy[0])
       << " | " << fmt("%.1f", limits.copy[1]) << " |\n";
    md << "| memory write GB/s (memset) | " << fmt("%.1f", limits.write[0]) << " | "
       << fmt("%.1f", limits.write[1]) << " |\n";
    md << "| L2 write GB/s (memset of 256 KiB per thread) | " << fmt("%.1f", limits.cache_write[0]) << " | "
       << fmt("%.1f", limits.cache_write[1]) << " |\n";
    md << "| fp32 GFLOP/s (" << limits.fma_kind << ", 12 chains) | " << fmt("%.1f", limits.fma[0]) << " | "
       << fmt("%.1f", limits.fma[1]) << " |\n";
  }

  namespace w = tessref::bench::work;
  md << "\nWork model (`bench/work_model.h`): a share is (model bytes / time) / bandwidth or (model flops / "
        "time) / FMA peak, for the threads that side uses; the larger (bold) binds. \"mem\" is the better "
        "of copy and write, \"L2\" the L2 write rate. Both sides are credited the same work.\n\n";
  md << "| item | bytes | flops |\n| --- | --- | --- |\n";
  md << "| PN vertex (TES invocation, quadratic normals) | " << w::kClipVertexBytes << " (a ClipVertex) | "
     << w::kPnVertexFlops << " |\n";
  md << "| tessellated triangle | " << w::kTriangleIndexBytes << " (3 indices) | " << w::kRasterTriangleFlops
     << " to rasterize (frames) |\n";
  md << "| TPG domain point / triangle | " << w::kTpgPointBytes << " / " << w::kTriangleIndexBytes << " | "
     << w::kTpgPointFlops << " / 0 |\n";
  md << "| soup triangle (raster) | " << w::kRasterTriangleBytes << " (3 vec4) | " << w::kRasterTriangleFlops
     << " |\n";
  md << "| fragment passing the depth test | 0 (tiles stay in cache) | " << w::kFragmentFlops << " (+ "
     << w::kPhongFragmentFlops << " Phong in frames) |\n";
  md << "| pixel of the target | " << w::kPixelBytesColorDepth << " (RGBA32F + depth; frames " << w::kPixelBytesFrame
     << " with RGBA32F normals) | 0 |\n";

  const std::string text = md.str();
  std::cout << text;
  if (!out_path.empty()) {
    std::ofstream out(out_path);
    out << text;
    if (!out) {
      std::fprintf(stderr, "bench_report: cannot write %s\n", out_path.c_str());
      return 2;
    }
  }
  return 0;
}
