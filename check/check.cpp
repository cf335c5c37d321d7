#include "check/check.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <regex>
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
  if (slot == 0) return "gl_Position";
  if (slot <= kMaxStageLocations) return "location " + std::to_string(slot - 1);
  const int d = slot - 1 - kMaxStageLocations;  // the built-in slots after the locations
  if (d >= 4) return "gl_PointSize";
  return (d < 2 ? "gl_ClipDistance[" : "gl_CullDistance[") + std::to_string(4 * (d % 2)) + ".." + std::to_string(4 * (d % 2) + 3) + "]";
}

// Line `line` of the stage's file, leading blanks dropped ("" if the text does not hold it).
std::string line_text(const CheckSource& src, int line) {
  std::istringstream in(src.text);
  std::string text;
  for (int at = src.first_line; std::getline(in, text); ++at)
    if (at == line) return text.erase(0, std::min(text.size(), text.find_first_not_of(" \t")));
  return "";
}

std::string source_line(const CheckSource& src, int line) {
  if (line <= 0) return src.file + ": (no line information)";
  return src.file + ":" + std::to_string(line) + ": " + line_text(src, line);
}

// The control shader phase that ran `line`: the barrier() calls before it in main(). GLSL allows
// barrier() only in main() and outside control flow, so the count in the text is the count run.
// -1 when the line is not in main() (a function: its phase is its caller's) or unknown.
int barrier_phase(const CheckSource& src, int line) {
  if (src.file.empty() || line <= 0) return -1;
  static const std::regex main_start(R"(\bvoid\s+main\s*\()"), barrier(R"(\bbarrier\s*\(\s*\))");
  std::istringstream in(src.text);
  std::string text;
  bool in_main = false;
  int phase = 0;
  for (int at = src.first_line; std::getline(in, text) && at < line; ++at) {
    text = text.substr(0, text.find("//"));
    if (std::regex_search(text, main_start)) in_main = true;
    if (in_main && std::regex_search(text, barrier)) ++phase;
  }
  return in_main ? phase : -1;
}

std::string out_of(const CheckRange& r) {
  return " outside [" + num(r.lo) + ", " + num(r.hi) + "] (--check-range " + r.spec + ")";
}

}  // namespace

// Watches a fragment program's colour outputs for the checker; the lowest (row, column) wins, so
// the report does not depend on which thread shaded which tile.
class WatchedFragment final : public FragmentProgram {
 public:
  WatchedFragment(const FragmentProgram& fs, Checker& checker) : fs_(fs), checker_(checker) {}
  FragmentOutput shade(const FragmentInput& in) const override { return fs_.shade(in); }
  bool may_discard() const override { return fs_.may_discard(); }
  bool reads_quads() const override { return fs_.reads_quads(); }
  void shade_batch(FragmentBatch& batch) const override {
    fs_.shade_batch(batch);
    for (int l = 0; l < batch.lanes(); ++l) {
      if (!batch.live[l]) continue;
      for (int c = 0; c < 4; ++c)
        if (!std::isfinite(batch.color[c][l]))
          checker_.record_fragment(batch, l, c, batch.color[c][l]);
    }
  }

 private:
  const FragmentProgram& fs_;
  Checker& checker_;
};

Checker::Checker(CheckContext context) : context_(std::move(context)) {}
Checker::~Checker() = default;

void Checker::vertex_output(std::size_t vertex, std::string_view name, const float* v, int n,
                            std::span<const std::uint32_t> indices, int patch_vertices,
                            const VertexTrace& trace) const {
  const int c = first_bad(v, n);
  if (c < 0) return;
  std::size_t patch = vertex / std::size_t(std::max(1, patch_vertices));
  if (!indices.empty())
    for (std::size_t i = 0; i < indices.size(); ++i)
      if (indices[i] == vertex) {
        patch = i / std::size_t(std::max(1, patch_vertices));
        break;
      }
  std::string report = "stage: vertex shader\nvertex: " + std::to_string(vertex) +
                       " (gl_VertexID; first used by patch " + std::to_string(patch) + ")\noutput: " + std::string(name) +
                       "." + component(c) + " = " + num(v[c]) + "\ninspect: tessref inspect " +
                       context_.inspect_args + "--patch " + std::to_string(patch);
  if (trace) report += provenance(context_.vertex, trace(vertex), "vertex");
  throw CheckOffence(report);
}

void Checker::control_output(std::size_t patch, const PatchOutput& out, const ControlTrace& trace) {
  const std::string head = "stage: tessellation control shader\npatch: " + std::to_string(patch) + " (gl_PrimitiveID)\n";
  const std::string inspect = "\ninspect: tessref inspect " + context_.inspect_args + "--patch " + std::to_string(patch);
  // The invocation that made the value: `first` is traced first (gl_out[i] is written by
  // invocation i), then the others; the first trace that names an instruction wins.
  auto offence = [&](int first, const std::string& output) {
    std::string invocation = first >= 0 ? "invocation: gl_InvocationID " + std::to_string(first) + "\n" : "";
    std::string source;
    if (trace) {
      shader::NanTrace best;
      int best_lane = -1;
      for (int k = 0; k < out.vertex_count; ++k) {
        const int lane = first >= 0 ? (first + k) % out.vertex_count : k;
        const shader::NanTrace t = trace(patch, lane);
        if ((t.found && !best.found) || (t.fallback && best_lane < 0)) {
          best = t;
          best_lane = lane;
        }
        if (best.found) break;
      }
      if (best_lane >= 0) {
        invocation = "invocation: gl_InvocationID " + std::to_string(best_lane);
        if (const int phase = barrier_phase(context_.control, best.line); phase >= 0)
          invocation += ", phase " + std::to_string(phase) + " (after " + std::to_string(phase) + " barrier())";
        invocation += "\n";
      }
      source = provenance(context_.control, best, "control");
    }
    throw CheckOffence(head + invocation + output + inspect + source);
  };
  for (int v = 0; v < out.vertex_count; ++v)
    for (int s = 0; s < kMaxStageAttributes; ++s) {
      const float* x = &out.vertices[v].attr[s][0];
      if (const int c = first_bad(x, 4); c >= 0)
        offence(v, "output: gl_out[" + std::to_string(v) + "] " + slot_name(s) + "." + component(c) + " = " + num(x[c]));
    }
  for (int s = 0; s < kMaxPatchAttributes; ++s)
    if (const int c = first_bad(&out.patch[s][0], 4); c >= 0)
      offence(-1, "output: patch out slot " + std::to_string(s) + "." + component(c) + " = " + num(out.patch[s][c]));
  // Level ranges (a NaN level is the warning's, below).
  for (const CheckRange& r : context_.ranges) {
    if (!r.level) continue;
    for (std::size_t i = 0; i < r.index.size(); ++i) {
      const int k = r.index[i];
      const float level = k < 4 ? out.levels.outer[k] : out.levels.inner[k - 4];
      if (!std::isnan(level) && (level < r.lo || level > r.hi))
        throw CheckOffence(head + "output: " + r.names[i] + " = " + num(level) + out_of(r) + inspect, true);
    }
  }
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
  for (std::size_t k = 0; k < records.size(); ++k, ++point) {
    if (k > 0 && records[k].patch_id != records[k - 1].patch_id) point = 0;
    const float* v = base + k * floats;
    const int bad = first_bad(v, 4 + nv);
    const CheckRange* range = nullptr;
    std::string output;
    if (bad >= 0) {
      output = bad < 4 ? std::string("gl_Position.") + component(bad)
                       : "varyings[" + std::to_string(bad - 4) + "] (location " + std::to_string((bad - 4) / 4) +
                             "." + component((bad - 4) % 4) + ")";
      output += " = " + num(v[bad]);
    } else {
      for (const CheckRange& r : context_.ranges) {
        if (r.level) continue;
        if (r.length) {
          double sum = 0.0;
          for (int i : r.index) sum += double(i < 4 + nv ? v[i] : 0.0f) * double(i < 4 + nv ? v[i] : 0.0f);
          const float len = float(std::sqrt(sum));
          if (len < r.lo || len > r.hi) output = r.names[0] + " = " + num(len);
        } else {
          for (std::size_t i = 0; i < r.index.size() && output.empty(); ++i) {
            const float x = r.index[i] < 4 + nv ? v[r.index[i]] : 0.0f;
            if (x < r.lo || x > r.hi) output = r.names[i] + " = " + num(x);
          }
        }
        if (!output.empty()) {
          range = &r;
          break;
        }
      }
      if (!range) continue;
    }
    const TessDumpRecord& r = records[k];
    const std::string coord = num(r.tess_coord.x) + "," + num(r.tess_coord.y) + "," + num(r.tess_coord.z);
    std::string report = "stage: tessellation evaluation shader\npatch: " + std::to_string(r.patch_id) +
                         " (gl_PrimitiveID)\ninvocation: domain point " + std::to_string(point) +
                         ", gl_TessCoord (" + coord + ")\noutput: " + output + (range ? out_of(*range) : "") +
                         "\ninspect: tessref inspect " + context_.inspect_args + "--patch " +
                         std::to_string(r.patch_id) + " --coord " + coord;
    if (range) throw CheckOffence(report, true);
    if (trace) report += provenance(context_.evaluation, trace(r.patch_id, r.tess_coord), "evaluation");
    throw CheckOffence(report);
  }
}

std::string Checker::provenance(const CheckSource& src, const shader::NanTrace& t, const char* stage) const {
  if (t.found || t.fallback)
    return std::string("\nfirst ") + (std::isnan(t.value) ? "NaN" : "Inf") + ": " + source_line(src, t.line) +
           "  (" + t.instruction() + (t.found ? ", operands finite)" : ", operands already non-finite)");
  if (!src.file.empty())
    return std::string("\nfirst NaN: no instruction of the ") + stage +
           " shader made it (its inputs were non-finite)";
  return "";
}

std::unique_ptr<FragmentProgram> Checker::watch(const FragmentProgram& fs) {
  fragment_shader_ = &fs;
  return std::make_unique<WatchedFragment>(fs, *this);
}

void Checker::record_fragment(const FragmentBatch& batch, int lane, int component_index, float value) {
  const int x = int(batch.frag_coord[0][lane]), y = int(batch.frag_coord[1][lane]);
  std::lock_guard lock(fragment_mutex_);
  if (fragment_bad_ && (y > fragment_y_ || (y == fragment_y_ && x >= fragment_x_))) return;
  fragment_bad_ = true;
  fragment_x_ = x;
  fragment_y_ = y;
  fragment_component_ = component_index;
  fragment_value_ = value;
  // Its quad's inputs (shading leaves them as they were), to shade it again traced.
  const int first = lane & ~3;
  Quad& q = fragment_quad_;
  q.lane = lane - first;
  q.num_varyings = batch.num_varyings;
  for (int l = 0; l < 4; ++l) {
    for (int c = 0; c < 4; ++c) q.frag_coord[c][l] = batch.frag_coord[c][first + l];
    for (int k = 0; k < batch.num_varyings; ++k) q.varyings[k][l] = batch.varyings[k][first + l];
    q.front_facing[l] = batch.front_facing[first + l];
  }
}

void Checker::after_raster() {
  if (!fragment_bad_) return;
  // X from the left, Y from the top row: the pixel as image files and `inspect --pixel` count it.
  const int top_y = context_.image_height > 0 ? context_.image_height - 1 - fragment_y_ : fragment_y_;
  std::string report = "stage: fragment shader\npixel: " + std::to_string(fragment_x_) + "," + std::to_string(top_y) +
                       " (X from the left, Y down from the top row; gl_FragCoord.xy (" + std::to_string(fragment_x_) +
                       ".5, " + std::to_string(fragment_y_) + ".5); of the batch's bad fragments, the lowest gl_FragCoord row, then column)\n"
                       "output: color." + component(fragment_component_) + " = " + num(fragment_value_) +
                       "\ninspect: tessref inspect " + context_.inspect_args + "--pixel " +
                       std::to_string(fragment_x_) + "," + std::to_string(top_y);
  if (fragment_shader_) {
    // The quad alone (derivatives difference its lanes), the bad fragment's lane traced.
    auto batch = std::make_unique<FragmentBatch>();
    const Quad& q = fragment_quad_;
    batch->quads = 1;
    batch->num_varyings = q.num_varyings;
    for (int l = 0; l < 4; ++l) {
      for (int c = 0; c < 4; ++c) batch->frag_coord[c][l] = q.frag_coord[c][l];
      for (int k = 0; k < q.num_varyings; ++k) batch->varyings[k][l] = q.varyings[k][l];
      batch->front_facing[l] = q.front_facing[l];
      batch->live[l] = 1;
    }
    shader::NanTrace trace;
    trace.lane = q.lane;
    {
      shader::NanTraceScope scope(trace);
      fragment_shader_->shade_batch(*batch);
    }
    report += provenance(context_.fragment, trace, "fragment");
  }
  throw CheckOffence(report);
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

shader::NanTrace trace_control(const TessDrawInput& input, const TessControlProgram& tcs,
                               std::size_t patch, int invocation) {
  // gl_in[] as the draw gathers it; outputs an invocation does not write read as zero.
  Patch in;
  in.vertex_count = input.patch_vertices;
  in.primitive_id = int(patch);
  const std::size_t base = patch * std::size_t(input.patch_vertices);
  for (int k = 0; k < input.patch_vertices; ++k) {
    const std::size_t v = input.indices.empty() ? base + std::size_t(k) : std::size_t(input.indices[base + std::size_t(k)]);
    if (v >= input.vertices.size()) return {};
    in.vertices[std::size_t(k)] = input.vertices[v];
  }
  PatchOutput out;
  out.vertex_count = tcs.output_vertices();
  const Patch* ins[1] = {&in};
  PatchOutput* outs[1] = {&out};
  shader::NanTrace trace;
  trace.lane = invocation;
  {
    shader::NanTraceScope scope(trace);
    tcs.run_patches(ins, outs, 1);
  }
  return trace;
}

shader::NanTrace trace_vertex(const DrawProgram& program,
                              const std::vector<VertexAttribute>& attributes,
                              std::size_t vertex, int instance) {
  StageVertex out;
  const Parallel serial(1);
  shader::NanTrace trace;  // lane 0: the vertex runs alone
  {
    shader::NanTraceScope scope(trace);
    program.run_vertices(attributes, vertex, 1, instance, &out, serial);
  }
  return trace;
}

}  // namespace tessref
