#pragma once
// tessref inspect --trace: the source-level trace of the invocations one inspect query touches
// (shader/source_trace.h). Each is the scene's GLSL program run again on the executor for that
// invocation alone (a TCS: its patch, tracing one lane), on this thread, with the inputs the draw
// gave it; the built-in C++ programs are traced through their GLSL twins.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "shader/glsl_compile.h"
#include "shader/source_trace.h"

namespace tessref {

// The stages a trace may cover.
enum TraceStages : unsigned {
  kTraceVertex = 1u, kTraceControl = 2u, kTraceEvaluation = 4u, kTraceFragment = 8u,
  kTraceAll = 15u,
};
// "vertex,control" -> bits; InputError naming --trace-stages for an unknown word.
unsigned parse_trace_stages(const std::string& list);

struct InspectTrace {
  shader::Stage stage = shader::Stage::Vertex;
  std::string invocation;  // "corner 0 = mesh vertex 8", "invocation 2", "gl_TessCoord (...)"
  std::string file;        // the source's file name, as the scene names it
  int first_line = 1;      // the file line of the text's first line
  std::vector<std::string> text;  // the source, line by line
  shader::SourceTrace trace;
  // The source line of an executed line ("" when out of the text).
  const std::string& source_line(int line) const;
};

// Runs `run` (one batch of the stage's program on this thread) while tracing lane `lane`: the
// traced invocation, described by `invocation`, with `source` as its text.
InspectTrace run_traced(const shader::ShaderSource& source, std::string invocation, int lane,
                        const std::function<void()>& run);

// The text trace: a heading per invocation, then `  LINE: source  -> values` per executed line.
std::string format_traces(const std::vector<InspectTrace>& traces);

}  // namespace tessref
