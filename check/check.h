#pragma once
// Checked mode, `tessref render --check` (issue 10): every stage's outputs are tested for NaN and
// infinity, and the first offence (lowest patch, then lowest point: the same on any thread count)
// stops the draw with a CheckOffence naming the stage, the invocation, the value and the
// `tessref inspect` command that shows it. For GLSL on the executor, the offending invocation is
// run again alone with a NaN trace (shader/nan_trace.h) to name the source line that made it.
// A NaN tessellation level is legal GL (the patch is discarded): it is a warning, not an offence.
// `--check-range NAME=LO,HI` adds range tests on named outputs (check_range.h's naming scheme).
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "check/check_range.h"
#include "raster/rasterizer.h"
#include "shader/nan_trace.h"
#include "stages/draw_program.h"
#include "stages/tess_stage.h"

namespace tessref {

// The first offence: the report, ready to print (several lines).
class CheckOffence : public std::runtime_error {
 public:
  explicit CheckOffence(const std::string& report, bool out_of_range = false)
      : std::runtime_error(report), out_of_range_(out_of_range) {}
  // A --check-range offence (else a NaN or an infinity).
  bool out_of_range() const { return out_of_range_; }

 private:
  bool out_of_range_;
};

// One stage's GLSL, for naming source lines ("" file: a built-in C++ program, no lines).
struct CheckSource {
  std::string file;
  std::string text;
  int first_line = 1;  // the line of `file` where `text` starts
};

// What the checker knows of the scene for its messages.
struct CheckContext {
  std::string inspect_args;  // SCENE and --set options, as `tessref inspect` takes them
  CheckSource vertex, control, evaluation, fragment;
  int image_height = 0;              // gl_FragCoord rows -> inspect --pixel's rows from the top
  std::vector<CheckRange> ranges;    // --check-range, resolved (check_range.h)
};

class Checker {
 public:
  explicit Checker(CheckContext context);
  ~Checker();

  // Re-runs of one invocation with a NaN trace (the draw's programs; empty: no source line).
  using VertexTrace = std::function<shader::NanTrace(std::size_t vertex)>;
  using ControlTrace = std::function<shader::NanTrace(std::size_t patch, int invocation)>;
  using TesTrace = std::function<shader::NanTrace(std::uint32_t patch, const glm::vec3& coord)>;

  // Vertex shader: `n` floats of output `name` of mesh vertex `vertex`. The patch named is the
  // first that uses the vertex (indices, patch_vertices as the draw's).
  void vertex_output(std::size_t vertex, std::string_view name, const float* v, int n,
                     std::span<const std::uint32_t> indices, int patch_vertices,
                     const VertexTrace& trace = {}) const;
  // Control shader: gl_out[], patch outputs, the level ranges; NaN levels become a warning.
  void control_output(std::size_t patch, const PatchOutput& out, const ControlTrace& trace = {});
  // Evaluation shader: one chunk's vertices (vertex k of batch is records[k]). trace(patch, coord)
  // re-runs the invocation with a NaN trace.
  void evaluation_outputs(const std::vector<TessDumpRecord>& records, const TriangleBatch& batch,
                          const TesTrace& trace) const;
  // Fragment shader: wraps `fs` to watch its colour outputs; after_raster() throws the offence of
  // the batch just drawn (the lowest pixel row, then column), re-running its quad traced.
  std::unique_ptr<FragmentProgram> watch(const FragmentProgram& fs);
  void after_raster();

  // Warning lines (NaN levels), for after the draw.
  std::vector<std::string> warnings() const;

 private:
  friend class WatchedFragment;
  // The inputs of the quad holding a bad fragment, to shade it again traced.
  struct Quad {
    int lane = 0;  // the bad fragment's lane in the quad
    int num_varyings = 0;
    float frag_coord[4][4];
    float varyings[kMaxVaryings][4];
    std::uint8_t front_facing[4];
  };
  void record_fragment(const FragmentBatch& batch, int lane, int component, float value);
  // "first NaN: FILE:LINE: text  (instruction, operands finite)", or "" without a trace.
  std::string provenance(const CheckSource& src, const shader::NanTrace& t, const char* stage) const;
  CheckContext context_;
  std::size_t nan_level_patches_ = 0;
  std::string first_nan_level_;
  const FragmentProgram* fragment_shader_ = nullptr;  // the unwatched one, for the traced re-run
  std::mutex fragment_mutex_;
  bool fragment_bad_ = false;
  int fragment_x_ = 0, fragment_y_ = 0, fragment_component_ = 0;
  float fragment_value_ = 0.0f;
  Quad fragment_quad_{};
};

// Runs patch `patch` of the draw again (its control shader on one thread), then its evaluation
// shader alone at `coord` with a NaN trace. The built-in C++ programs leave the trace empty.
shader::NanTrace trace_evaluation(const TessDrawInput& input, const TessControlProgram& tcs,
                                  const TessEvalProgram& tes, const TessOptions& options,
                                  std::uint32_t patch, const glm::vec3& coord);
// Runs the control shader of patch `patch` alone (all its invocations, as the draw does: they
// share gl_out[] across barrier()), tracing invocation `invocation`.
shader::NanTrace trace_control(const TessDrawInput& input, const TessControlProgram& tcs,
                               std::size_t patch, int invocation);
// Runs the vertex shader for vertex `vertex` (gl_VertexID) of instance `instance` alone, traced.
shader::NanTrace trace_vertex(const DrawProgram& program,
                              const std::vector<VertexAttribute>& attributes,
                              std::size_t vertex, int instance);

}  // namespace tessref
