#pragma once
// The source-level trace of one invocation (`tessref inspect --trace`, issue 10): every source
// line it executed, in order (a loop's lines once per iteration), with the values the line
// produced for that invocation: what it stored into a named variable (`b210 = (...)`) and the last
// value it computed. As with NaN provenance (nan_trace.h), the executor looks for a request once
// per batch through a thread-local pointer, so a draw that traces nothing pays nothing per
// instruction; a trace re-runs one invocation, or its patch, on the calling thread.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "shader/spirv_module.h"

namespace tessref::shader {

// A value of the traced invocation: its components' scalars and bits (a double: both words in
// `bits`, low first).
struct TraceValue {
  std::vector<Scalar> scalars;
  std::vector<std::uint64_t> bits;
  std::string text() const;  // "(0.331, 0.104, 0.702)", "12", "true"; floats as %.9g
  std::string component_text(std::size_t i) const;  // "0.331", "12", "7u", "true"
};

// A store into memory the shader can name: "b210", "gl_out[1].gl_Position", "v.x".
struct TraceStore {
  std::string target;
  TraceValue value;
};

// One execution of one source line.
struct TraceLine {
  int line = 0;              // the file's line (OpLine)
  bool barrier = false;      // the line holds barrier(): the TCS's next phase starts after it
  std::vector<TraceStore> stores;
  bool has_result = false;   // the line computed a value (beyond loads and stores)
  TraceValue result;         // the last one
  // Where the paths of a `c ? a : b`, `a || b` or an if on this line meet: the values its
  // variables take there (OpPhi; a local kept as an SSA value has no store to show).
  std::vector<TraceValue> joins;
};

struct SourceTrace {
  int lane = 0;                      // the invocation traced, as a lane of its batch
  std::size_t max_lines = 100'000;   // executions kept; the rest is counted in `dropped`
  std::vector<TraceLine> lines;
  std::size_t dropped = 0;
};

// While alive, executor runs on this thread record `trace->lane` into `trace`.
class SourceTraceScope {
 public:
  explicit SourceTraceScope(SourceTrace& trace);
  ~SourceTraceScope();
  SourceTraceScope(const SourceTraceScope&) = delete;
  SourceTraceScope& operator=(const SourceTraceScope&) = delete;

 private:
  SourceTrace* previous_;
};

SourceTrace* current_source_trace();

// The access path of `words` words at word `offset` of a value of type `type`: "[1].gl_Position",
// ".x", "" for the whole value (member names from OpMemberName, else "member K").
std::string access_path(const Module& m, std::uint32_t type, std::uint32_t offset, std::uint32_t words);

}  // namespace tessref::shader
