#include "inspect/inspect_trace.h"

#include <sstream>

#include "common/error.h"

namespace tessref {

unsigned parse_trace_stages(const std::string& list) {
  unsigned bits = 0;
  std::istringstream in(list);
  for (std::string word; std::getline(in, word, ',');) {
    if (word == "all") bits |= kTraceAll;
    else if (word == "vertex") bits |= kTraceVertex;
    else if (word == "control") bits |= kTraceControl;
    else if (word == "evaluation") bits |= kTraceEvaluation;
    else if (word == "fragment") bits |= kTraceFragment;
    else
      throw InputError("--trace-stages: unknown stage \"" + word +
                       "\" (give a comma-separated list of vertex, control, evaluation, fragment, all)");
  }
  if (!bits) throw InputError("--trace-stages: no stage given");
  return bits;
}

const std::string& InspectTrace::source_line(int line) const {
  static const std::string none;
  const int at = line - first_line;
  return at >= 0 && std::size_t(at) < text.size() ? text[std::size_t(at)] : none;
}

InspectTrace run_traced(const shader::ShaderSource& source, std::string invocation, int lane,
                        const std::function<void()>& run) {
  InspectTrace t;
  t.stage = source.stage;
  t.invocation = std::move(invocation);
  t.file = source.file;
  t.first_line = source.first_line;
  std::istringstream in(source.text);
  for (std::string line; std::getline(in, line);) t.text.push_back(line);
  t.trace.lane = lane;
  shader::SourceTraceScope scope(t.trace);
  run();
  return t;
}

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::string format_traces(const std::vector<InspectTrace>& traces) {
  std::string out;
  for (const InspectTrace& t : traces) {
    out += "  " + std::string(shader::stage_name(t.stage)) + " " + t.file + ", " + t.invocation + ": " +
           std::to_string(t.trace.lines.size()) + " line executions" +
           (t.trace.dropped ? " (then " + std::to_string(t.trace.dropped) + " more not kept)" : "") + "\n";
    std::size_t width = 0;
    for (const shader::TraceLine& l : t.trace.lines) width = std::max(width, trimmed(t.source_line(l.line)).size());
    width = std::min<std::size_t>(width, 72);
    for (const shader::TraceLine& l : t.trace.lines) {
      std::string text = trimmed(t.source_line(l.line));
      std::string values;
      for (const shader::TraceStore& s : l.stores) values += (values.empty() ? "" : "; ") + s.target + " = " + s.value.text();
      if (l.stores.empty()) {
        // Where the paths of a ?:, && or || or an if meet: the values its variables take there.
        for (const shader::TraceValue& j : l.joins) values += (values.empty() ? "joined: " : "; ") + j.text();
        if (l.joins.empty() && l.has_result) values = l.result.text();
      }
      if (l.barrier) values += values.empty() ? "(barrier: the next phase starts)" : "  (barrier)";
      std::string row = "    " + std::to_string(l.line) + ": " + text;
      if (!values.empty()) {
        if (text.size() < width) row.append(width - text.size(), ' ');
        row += "  -> " + values;
      }
      out += row + "\n";
    }
  }
  return out;
}

}  // namespace tessref
