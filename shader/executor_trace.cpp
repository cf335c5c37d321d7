// The traced form of Runner::run_block for `render --check` (shader/nan_trace.h): the same
// instructions, each followed by a look at one lane's result. Only the checker's re-run of a
// single offending invocation comes here.
#include <cmath>
#include <cstring>

#include "shader/executor_runner.h"

namespace tessref::shader {
namespace {

// Moves and copies pass a NaN on; they never make one.
bool produces(XOp op) {
  switch (op) {
    case XOp::Nop: case XOp::Copy: case XOp::Undef: case XOp::Composite: case XOp::ExtractDyn:
    case XOp::InsertDyn: case XOp::Load: case XOp::Store: case XOp::AccessChain:
    case XOp::CopyMemory: case XOp::Select: case XOp::Kill:
      return false;
    default:
      return true;
  }
}

// The first non-finite float of the value at `row` for `lane`; false if every one is finite
// (or the row starts no value the decoder described).
bool non_finite(const DecodedProgram& p, const std::uint32_t* arena, std::uint32_t row, int lane,
                float& value) {
  if (row == kNone || row >= p.value_words.size()) return false;
  for (std::uint32_t w = 0; w < p.value_words[row]; ++w) {
    if (!p.float_rows[row + w]) continue;
    float f;
    std::memcpy(&f, arena + std::size_t(row + w) * kMaxLanes + lane, sizeof f);
    if (!std::isfinite(f)) {
      value = f;
      return true;
    }
  }
  return false;
}

}  // namespace

void Runner::traced_block(const XBlock& b) {
  if (!b.phis.empty()) run_phis(b);
  const XIns* code = p.code.data() + b.first;
  const int lane = trace->lane;
  for (std::uint32_t i = 0; i < b.count; ++i) {
    const XIns& x = code[i];
    exec(x);
    if (trace->found || !mask[lane] || !produces(x.op)) continue;
    float result = 0.0f, ignored = 0.0f;
    if (!non_finite(p, A, x.dst, lane, result)) continue;
    const bool operands_finite = !non_finite(p, A, x.a, lane, ignored) &&
                                 !non_finite(p, A, x.b, lane, ignored) &&
                                 !non_finite(p, A, x.c, lane, ignored) &&
                                 !non_finite(p, A, x.d, lane, ignored);
    if (!operands_finite && (trace->fallback)) continue;
    trace->found = operands_finite;
    trace->fallback = !operands_finite;
    trace->line = x.line;
    trace->spv = x.spv;
    trace->ext = x.op == XOp::Ext ? x.aux : 0;
    trace->value = result;
  }
}

}  // namespace tessref::shader
