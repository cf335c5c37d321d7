#include "pipeline/check.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace tessref {
namespace {

// 9 significant digits: each float read back gives the bits the pipeline computed.
std::string num(float f) {
  if (std::isnan(f)) return "nan";  // printf's "-nan" says nothing useful
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", double(f));
  return buf;
}

int first_bad(const float* v, int n) {
  for (int c = 0; c < n; ++c)
    if (!std::isfinite(v[c])) return c;
  return -1;
}

const char* component(int c) { return c == 0 ? "x" : c == 1 ? "y" : c == 2 ? "z" : "w"; }

std::string slot_name(int slot) {
  return slot == 0 ? "gl_Position" : "location " + std::to_string(slot - 1);
}

}  // namespace

// Watches a fragment program's colour outputs for the checker; the lowest (row, column) wins, so
// the report does not depend on which thread shaded which tile.
class WatchedFragment final : public FragmentProgram {
 public:
  WatchedFragment(const FragmentProgram& fs, Checker& checker) : fs_(fs), checker_(checker) {}
  FragmentOutput shade(const FragmentInput& in) const override { return fs_.shade(in); }
  bool may_discard() const override { return fs_.may_discard(); }
  void shade_batch(FragmentBatch& batch) const override {
    fs_.shade_batch(batch);
    for (int l = 0; l < batch.lanes(); ++l) {
      if (!batch.live[l]) continue;
      for (int c = 0; c < 4; ++c)
        if (!std::isfinite(batch.color[c][l]))
          checker_.record_fragment(int(batch.frag_coord[0][l]), int(batch.frag_coord[1][l]), c,
                                   batch.color[c][l]);
    }
  }

 private:
  const FragmentProgram& fs_;
  Checker& checker_;
};

Checker::Checker(CheckContext context) : context_(std::move(context)) {
  std::istringstream in(context_.tes_text);
  for (std::string line; std::getline(in, line);) source_lines_.push_back(line);
}
Checker::~Checker() = default;

void Checker::vertex_output(std::size_t vertex, const std::string& name, const float* v, int n,
                            std::span<const std::uint32_t> indices, int patch_vertices) const {
  const int c = first_bad(v, n);
  if (c < 0) return;
  std::size_t patch = vertex / std::size_t(std::max(1, patch_vertices));
  if (!indices.empty())
    for (std::size_t i = 0; i < indices.size(); ++i)
      if (indices[i] == vertex) {
        patch = i / std::size_t(std::max(1, patch_vertices));
        break;
      }
  throw CheckOffence("stage: vertex shader\nvertex: " + std::to_string(vertex) +
                     " (first used by patch " + std::to_string(patch) + ")\noutput: " + name + "." +
                     component(c) + " = " + num(v[c]) + "\ninspect: tessref inspect " +
                     context_.inspect_args + "--patch " + std::to_string(patch));
}

void Checker::control_output(std::size_t patch, const PatchOutput& out) {
  for (int v = 0; v < out.vertex_count; ++v)
    for (int s = 0; s < kMaxStageAttributes; ++s) {
      const float* x = &out.vertices[v].attr[s][0];
      if (const int c = first_bad(x, 4); c >= 0)
        throw CheckOffence("stage: tessellation control shader\npatch: " + std::to_string(patch) +
                           " (gl_PrimitiveID)\ninvocation: gl_InvocationID " + std::to_string(v) +
                           "\noutput: gl_out[" + std::to_string(v) + "] " + slot_name(s) + "." +
                           component(c) + " = " + num(x[c]) + "\ninspect: tessref inspect " +
                           context_.inspect_args + "--patch " + std::to_string(patch));
    }
  for (int s = 0; s < kMaxPatchAttributes; ++s)
    if (const int c = first_bad(&out.patch[s][0], 4); c >= 0)
      throw CheckOffence("stage: tessellation control shader\npatch: " + std::to_string(patch) +
                         " (gl_PrimitiveID)\noutput: patch out slot " + std::to_string(s) + "." +
                         component(c) + " = " + num(out.patch[s][c]) + "\ninspect: tessref inspect " +
                         context_.inspect_args + "--patch " + std::to_string(patch));
  // A NaN level discards the patch (GL 4.6 section 11.2.2): legal, so only worth a warning.
  std::string level;
  for (int i = 0; i < 4 && level.empty(); ++i)
    if (std::isnan(out.levels.outer[i])) level = "gl_TessLevelOuter[" + std::to_string(i) + "]";
  for (int i = 0; i < 2 && level.empty(); ++i)
    if (std::isnan(out.levels.inner[i])) level = "gl_TessLevelInner[" + std::to_string(i) + "]";
  if (level.empty()) return;
  if (nan_level_patches_++ == 0)
    first_nan_level_ = "patch " + std::to_string(patch) + " " + level;
}

void Checker::evaluation_outputs(const std::vector<TessDumpRecord>& records,
                                 const TriangleBatch& batch, const TesTrace& trace) const {
  const int nv = batch.num_varyings;
  const std::size_t floats = 16 * std::size_t(batch.records());
  const float* base = reinterpret_cast<const float*>(batch.vertices.data());
  std::size_t point = 0;  // the vertex's index among its patch's domain points
  for (std::size_t k = 0; k < records.size(); ++k) {
    if (k > 0 && records[k].patch_id != records[k - 1].patch_id) point = 0;
    const float* v = base + k * floats;
    int bad = first_bad(v, 4 + nv);
    if (bad < 0) {
      ++point;
      continue;
    }
    const TessDumpRecord& r = records[k];
    const std::string name = bad < 4 ? std::string("gl_Position.") + component(bad)
                                     : "varyings[" + std::to_string(bad - 4) + "] (location " +
                                           std::to_string((bad - 4) / 4) + "." + component((bad - 4) % 4) + ")";
    const std::string coord = num(r.tess_coord.x) + "," + num(r.tess_coord.y) + "," + num(r.tess_coord.z);
    std::string report = "stage: tessellation evaluation shader\npatch: " + std::to_string(r.patch_id) +
                         " (gl_PrimitiveID)\ninvocation: domain point " + std::to_string(point) +
                         ", gl_TessCoord (" + coord + ")\noutput: " + name + " = " + num(v[bad]) +
                         "\ninspect: tessref inspect " + context_.inspect_args + "--patch " +
                         std::to_string(r.patch_id) + " --coord " + coord;
    if (trace) {
      const shader::NanTrace t = trace(r.patch_id, r.tess_coord);
      if (t.found || t.fallback)
        report += std::string("\nfirst ") + (std::isnan(t.value) ? "NaN" : "Inf") + ": " +
                  source_line(t.line) + "  (" + t.instruction() +
                  (t.found ? ", operands finite)" : ", operands already non-finite)");
      else if (!context_.tes_file.empty())
        report += "\nfirst NaN: no instruction of the evaluation shader made it (its inputs were non-finite)";
    }
    throw CheckOffence(report);
  }
}

std::string Checker::source_line(int line) const {
  if (line <= 0) return context_.tes_file + ": (no line information)";
  std::string text;
  const int at = line - context_.tes_first_line;
  if (at >= 0 && std::size_t(at) < source_lines_.size()) {
    text = source_lines_[std::size_t(at)];
    text.erase(0, text.find_first_not_of(" \t"));
  }
  return context_.tes_file + ":" + std::to_string(line) + ": " + text;
}

std::unique_ptr<FragmentProgram> Checker::watch(const FragmentProgram& fs) {
  return std::make_unique<WatchedFragment>(fs, *this);
}

void Checker::record_fragment(int x, int y, int component_index, float value) {
  std::lock_guard lock(fragment_mutex_);
  if (fragment_bad_ && (y > fragment_y_ || (y == fragment_y_ && x >= fragment_x_))) return;
  fragment_bad_ = true;
  fragment_x_ = x;
  fragment_y_ = y;
  fragment_component_ = component_index;
  fragment_value_ = value;
}

void Checker::after_raster() {
  if (!fragment_bad_) return;
  throw CheckOffence("stage: fragment shader\npixel: " + std::to_string(fragment_x_) + "," +
                     std::to_string(fragment_y_) + " (gl_FragCoord, the lowest row and column of the batch)\n"
                     "output: color." + component(fragment_component_) + " = " + num(fragment_value_));
}

std::vector<std::string> Checker::warnings() const {
  if (nan_level_patches_ == 0) return {};
  return {"--check: " + std::to_string(nan_level_patches_) +
          " patch(es) have a NaN tessellation level and were discarded (legal GL), the first " +
          first_nan_level_};
}

shader::NanTrace trace_evaluation(const TessDrawInput& input, const TessControlProgram& tcs,
                                  const TessEvalProgram& tes, const TessOptions& options,
                                  std::uint32_t patch, const glm::vec3& coord) {
  PatchOutput control;
  TessOptions again = options;
  again.dump = nullptr;
  again.lines = again.points = nullptr;
  again.control_check = [&](std::size_t, const PatchOutput& out) { control = out; };
  TriangleBatch batch;
  const Parallel serial(1);
  tessellate(input, patch, patch + 1, tcs, tes, again, serial, batch);
  shader::NanTrace trace;  // lane 0: evaluate() runs the point alone
  {
    shader::NanTraceScope scope(trace);
    tes.evaluate(coord, control, int(patch));
  }
  return trace;
}

}  // namespace tessref
