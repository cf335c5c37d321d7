#pragma once
// Checked mode, `tessref render --check` (issue 10): every stage's outputs are tested for NaN and
// infinity, and the first offence (lowest patch, then lowest point: the same on any thread count)
// stops the draw with a CheckOffence naming the stage, the invocation, the value and the
// `tessref inspect` command that shows it. For GLSL on the executor, the offending invocation is
// run again alone with a NaN trace (shader/nan_trace.h) to name the source line that made it.
// A NaN tessellation level is legal GL (the patch is discarded): it is a warning, not an offence.
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster/rasterizer.h"
#include "shader/nan_trace.h"
#include "stages/tess_stage.h"

namespace tessref {

// The first offence: the report, ready to print (several lines).
class CheckOffence : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the checker knows of the scene for its messages.
struct CheckContext {
  std::string inspect_args;  // SCENE and --set options, as `tessref inspect` takes them
  std::string tes_file;      // the GLSL evaluation shader's file ("" for the built-in programs)
  std::string tes_text;
  int tes_first_line = 1;
};

class Checker {
 public:
  explicit Checker(CheckContext context);
  ~Checker();

  // Vertex shader: `n` floats of output `name` of mesh vertex `vertex`. The patch named is the
  // first that uses the vertex (indices, patch_vertices as the draw's).
  void vertex_output(std::size_t vertex, const std::string& name, const float* v, int n,
                     std::span<const std::uint32_t> indices, int patch_vertices) const;
  // Control shader: gl_out[], patch outputs; NaN levels become a warning.
  void control_output(std::size_t patch, const PatchOutput& out);
  // Evaluation shader: one chunk's vertices (vertex k of batch is records[k]). trace(patch, coord)
  // re-runs the invocation with a NaN trace.
  using TesTrace = std::function<shader::NanTrace(std::uint32_t patch, const glm::vec3& coord)>;
  void evaluation_outputs(const std::vector<TessDumpRecord>& records, const TriangleBatch& batch,
                          const TesTrace& trace) const;
  // Fragment shader: wraps `fs` to watch its colour outputs; after_raster() throws the offence of
  // the batch just drawn (the lowest pixel row, then column).
  std::unique_ptr<FragmentProgram> watch(const FragmentProgram& fs);
  void after_raster();

  // Warning lines (NaN levels), for after the draw.
  std::vector<std::string> warnings() const;

 private:
  friend class WatchedFragment;
  void record_fragment(int x, int y, int component, float value);
  std::string source_line(int line) const;
  CheckContext context_;
  std::vector<std::string> source_lines_;
  std::size_t nan_level_patches_ = 0;
  std::string first_nan_level_;
  std::mutex fragment_mutex_;
  bool fragment_bad_ = false;
  int fragment_x_ = 0, fragment_y_ = 0, fragment_component_ = 0;
  float fragment_value_ = 0.0f;
};

// Runs patch `patch` of the draw again (its control shader on one thread), then its evaluation
// shader alone at `coord` with a NaN trace. The built-in C++ programs leave the trace empty.
shader::NanTrace trace_evaluation(const TessDrawInput& input, const TessControlProgram& tcs,
                                  const TessEvalProgram& tes, const TessOptions& options,
                                  std::uint32_t patch, const glm::vec3& coord);

}  // namespace tessref
