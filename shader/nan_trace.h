#pragma once
// NaN provenance for `tessref render --check`: the first instruction of one invocation whose
// result held a NaN or an infinity while its operands held none. The executor looks for a trace
// request once per run (a thread-local pointer), so a draw without --check pays nothing per
// instruction; the checker re-runs only the offending invocation, alone in lane 0, with one set.
#include <cstdint>
#include <string>

namespace tessref::shader {

struct NanTrace {
  int lane = 0;            // the invocation traced
  bool found = false;      // an instruction made a non-finite value from finite operands
  bool fallback = false;   // none did; the first non-finite result at all (operands non-finite)
  int line = 0;            // its source line (OpLine; 0: unknown)
  std::uint16_t spv = 0;   // its SPIR-V opcode
  std::uint32_t ext = 0;   // OpExtInst: the GLSL.std.450 instruction number
  float value = 0.0f;      // the first non-finite component of its result

  // "OpExtInst Normalize" or "OpFDiv".
  std::string instruction() const;
};

// While alive, executor runs on this thread record into `trace` (the first hit only).
class NanTraceScope {
 public:
  explicit NanTraceScope(NanTrace& trace);
  ~NanTraceScope();
  NanTraceScope(const NanTraceScope&) = delete;
  NanTraceScope& operator=(const NanTraceScope&) = delete;

 private:
  NanTrace* previous_;
};

// The trace request of this thread, or null (what Invocations::run reads once).
NanTrace* current_nan_trace();

}  // namespace tessref::shader
