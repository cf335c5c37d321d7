// The traced form of Runner::run_block (shader/nan_trace.h, shader/source_trace.h): the same
// instructions, each followed by a look at one lane's result. Only the re-run of a single
// invocation (--check's offender, inspect --trace) comes here.
#include <cmath>
#include <cstring>

#include <spirv/unified1/spirv.hpp>

#include "shader/executor_runner.h"
#include "shader/source_trace.h"

namespace tessref::shader {
namespace {

// Moves and copies pass a NaN on; they never make one.
bool produces(XOp op) {
  switch (op) {
    case XOp::Nop: case XOp::Copy: case XOp::Undef: case XOp::Composite: case XOp::ExtractDyn:
    case XOp::InsertDyn: case XOp::Load: case XOp::Store: case XOp::AccessChain:
    case XOp::CopyMemory: case XOp::Select: case XOp::Kill: case XOp::Emit:
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
    if (p.row_scalar[row + w] != Scalar::F32) continue;
    float f;
    std::memcpy(&f, arena + std::size_t(row + w) * kMaxLanes + lane, sizeof f);
    if (!std::isfinite(f)) {
      value = f;
      return true;
    }
  }
  return false;
}

// Word `word` of a value whose rows start at `row`, for `lane` (a double: its two words).
std::uint64_t lane_bits(const std::uint32_t* arena, std::uint32_t row, std::uint32_t word, Scalar s, int lane) {
  if (s == Scalar::F64) {
    std::uint64_t d;
    std::memcpy(&d, arena + std::size_t(row + word) * kMaxLanes + std::size_t(lane) * 2, sizeof d);
    return d;
  }
  return arena[std::size_t(row + word) * kMaxLanes + lane];
}

// The value of `flat` components at `row` for `lane`.
TraceValue lane_value(const std::uint32_t* arena, std::uint32_t row, const std::vector<FlatComponent>& flat, int lane) {
  TraceValue value;
  for (const FlatComponent& c : flat) {
    value.scalars.push_back(c.scalar);
    value.bits.push_back(lane_bits(arena, row, c.word, c.scalar, lane));
  }
  return value;
}

}  // namespace

void Runner::nan_check(const XIns& x) {
  const int lane = trace->lane;
  if (trace->found || !mask[lane] || !produces(x.op)) return;
  float result = 0.0f, ignored = 0.0f;
  if (!non_finite(p, A, x.dst, lane, result)) return;
  const bool operands_finite = !non_finite(p, A, x.a, lane, ignored) &&
                               !non_finite(p, A, x.b, lane, ignored) &&
                               !non_finite(p, A, x.c, lane, ignored) &&
                               !non_finite(p, A, x.d, lane, ignored);
  if (!operands_finite && trace->fallback) return;
  trace->found = operands_finite;
  trace->fallback = !operands_finite;
  trace->line = x.line;
  trace->spv = x.spv;
  trace->ext = x.op == XOp::Ext ? x.aux : 0;
  trace->value = result;
}

// The record of the traced lane's current execution of `line`, or null when none is kept. A new
// execution starts where the line changes; instructions of no line (the front end's bookkeeping)
// belong to the line before them.
TraceLine* Runner::source_line(int line) {
  SourceTrace& t = *source;
  if (line > 0 && (t.lines.empty() || t.lines.back().line != line || source_new_line)) {
    source_new_line = false;
    source_blocks.clear();
    source_blocks.push_back(source_block);
    if (t.lines.size() >= t.max_lines) {
      ++t.dropped;
      return nullptr;
    }
    t.lines.emplace_back().line = line;
  }
  if (t.lines.empty() || t.dropped) return nullptr;
  return &t.lines.back();
}

// The phis of a selection's merge block, given to the selection's line: after `mid = c ? h :
// f(h);` (whose else path ran f's lines) the line comes back with the value mid took.
void Runner::source_record_joins(const XBlock& b) {
  const int lane = source->lane;
  if (!mask[lane]) return;
  TraceLine* line = source_line(b.join_line);
  if (!line) return;
  line->joins.clear();
  for (const Phi& phi : b.phis) line->joins.push_back(lane_value(A, phi.dst, phi.flat, lane));
}

void Runner::source_record(const XIns& x) {
  const int lane = source->lane;
  if (!mask[lane]) return;
  TraceLine* current = source_line(x.line);
  if (!current) return;
  TraceLine& line = *current;
  if (x.op == XOp::Nop && x.spv == spv::OpControlBarrier) line.barrier = true;
  if (x.op == XOp::Store) {
    const Access& a = p.accesses[x.aux];
    const VariableSlot& v = p.slots[a.slot];
    const Module& m = inv.exe_.module();
    const Variable* var = m.variable(v.id);
    const std::uint32_t offset = a.offset + (a.offset_reg == kNone ? 0u : A[std::size_t(a.offset_reg) * L + lane]);
    // gl_PerVertex blocks have no instance name: their members are named alone ("gl_Position").
    const auto name = m.names.find(v.id);
    std::string path = var ? access_path(m, var->type, offset, a.words) : "";
    TraceStore store;
    if (name != m.names.end() && !name->second.empty()) store.target = name->second + path;
    else if (!path.empty() && path[0] == '.') store.target = path.substr(1);
    else return;  // a temporary the front end made (a call's argument copy): not the user's
    store.value = lane_value(A, x.a, a.flat, lane);
    line.stores.push_back(std::move(store));
    return;
  }
  if (x.op == XOp::Load || x.op == XOp::AccessChain || x.dst == kNone || x.dst >= p.value_words.size()) return;
  const std::uint32_t words = p.value_words[x.dst];
  if (words == 0) return;
  TraceValue value;
  for (std::uint32_t w = 0; w < words; ++w) {
    const Scalar s = p.row_scalar[x.dst + w];
    if (s == Scalar::None) continue;  // a double's second word
    value.scalars.push_back(s);
    value.bits.push_back(lane_bits(A, x.dst, w, s, lane));
  }
  line.has_result = true;
  line.result = std::move(value);
}

void Runner::traced_block(const XBlock& b) {
  if (!b.phis.empty()) run_phis(b);
  // A block already run during the current line's execution means a loop went round: its line
  // starts a new execution even when it is the same line (`for (...)` heads, one-line loops).
  // Other blocks within a line (`a || b`, `c ? x : y`) continue the execution.
  source_block = std::uint32_t(&b - p.blocks.data());
  if (source) {
    for (std::uint32_t seen : source_blocks)
      if (seen == source_block) source_new_line = true;
    if (!source_new_line) source_blocks.push_back(source_block);
    if (b.join_line > 0) source_record_joins(b);
  }
  const XIns* code = p.code.data() + b.first;
  for (std::uint32_t i = 0; i < b.count; ++i) {
    const XIns& x = code[i];
    exec(x);
    if (trace) nan_check(x);
    if (source) source_record(x);
  }
}

}  // namespace tessref::shader
