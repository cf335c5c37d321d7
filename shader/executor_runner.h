#pragma once
// The executor's run state and kernel helpers (internal): shared by executor.cpp (control flow,
// memory, arithmetic) and executor_ext.cpp (GLSL.std.450).
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "shader/executor_program.h"
#include "shader/nan_trace.h"
#include "shader/source_trace.h"

namespace tessref::shader {

inline constexpr int L = kMaxLanes;

// float -> int as x86's cvttss2si: NaN and out-of-range give INT_MIN (documented in executor.h).
template <class F>
std::int32_t to_int(F x) {
  if (!(x > F(-2147483649.0) && x < F(2147483648.0))) return std::numeric_limits<std::int32_t>::min();
  return std::int32_t(x);
}
template <class F>
std::uint32_t to_uint(F x) {
  if (!(x > F(-1.0))) return 0u;
  if (!(x < F(4294967296.0))) return 0xffffffffu;
  return std::uint32_t(x);
}

// An atomic operation's new value of a word (XOp::Atomic*); comparator: atomicCompSwap's.
inline std::uint32_t atomic_value(XOp op, std::uint32_t before, std::uint32_t operand, std::uint32_t comparator) {
  switch (op) {
    case XOp::AtomicInc: return before + 1;
    case XOp::AtomicDec: return before - 1;
    case XOp::AtomicAdd: return before + operand;
    case XOp::AtomicSub: return before - operand;
    case XOp::AtomicStore: case XOp::AtomicExchange: return operand;
    case XOp::AtomicSMin: return std::int32_t(operand) < std::int32_t(before) ? operand : before;
    case XOp::AtomicUMin: return operand < before ? operand : before;
    case XOp::AtomicSMax: return std::int32_t(operand) > std::int32_t(before) ? operand : before;
    case XOp::AtomicUMax: return operand > before ? operand : before;
    case XOp::AtomicAnd: return before & operand;
    case XOp::AtomicOr: return before | operand;
    case XOp::AtomicXor: return before ^ operand;
    case XOp::AtomicCompareExchange: return before == comparator ? operand : before;
    default: return before;  // AtomicLoad
  }
}

struct Runner {
  Invocations& inv;
  const DecodedProgram& p;
  std::uint32_t* A;  // arena
  int n;             // lanes
  std::uint8_t mask[L];
  bool full = false;
  std::uint32_t pc[L];
  std::uint32_t prev[L];
  std::uint64_t steps[L];
  std::uint32_t uniform_prev = kNone;  // the block every active lane came from; kNone: see prev[]
  std::pair<int, int> group_runs[L];  // [first, end) lanes of each group, in order
  int num_group_runs = 0;
  NanTrace* trace = nullptr;  // --check's re-run of one invocation (nan_trace.h); null normally
  SourceTrace* source = nullptr;  // inspect --trace (source_trace.h); null normally
  bool source_new_line = false;   // the next line recorded starts a new execution
  std::uint32_t source_block = 0;             // the block running
  std::vector<std::uint32_t> source_blocks;   // the blocks the current line execution ran

  // A shared variable's words (lane's group block for a per-group one), or a storage block's
  // memory where one is bound.
  std::uint32_t* common(std::uint32_t slot, int lane = 0) {
    const VariableSlot& v = p.slots[slot];
    if (v.storage && inv.storage_[slot]) return inv.storage_[slot];
    return inv.shared_.data() + (v.per_group ? inv.group_base_[lane] : 0u) + v.base;
  }

  template <class T>
  T* row(std::uint32_t r, std::uint32_t comp = 0) {
    return reinterpret_cast<T*>(A + std::size_t(r + comp * sizeof(T) / 4) * L);
  }

  // Writes f(l) into dst for the active lanes; inactive lanes keep their values (a value defined in
  // a loop stays valid for lanes that left the loop).
  template <class T, class F>
  void put(T* __restrict dst, F f) {
    // The count in a local: a store through dst may alias this->n (an int), which would keep
    // the loop from being vectorized.
    const int count = n;
    if (full) {
      for (int l = 0; l < count; ++l) dst[l] = f(l);
    } else {
      const std::uint8_t* m = mask;
      for (int l = 0; l < count; ++l)
        if (m[l]) dst[l] = f(l);
    }
  }

  // value into dst[lo, hi) for the active lanes.
  void put_range(std::uint32_t* __restrict dst, int lo, int hi, std::uint32_t value) {
    const std::uint8_t* m = mask;
    if (full) {
      for (int l = lo; l < hi; ++l) dst[l] = value;
    } else {
      for (int l = lo; l < hi; ++l)
        if (m[l]) dst[l] = value;
    }
  }

  // Per-component kernels over `comps` components.
  template <class T, class U, class F>
  void map1(const XIns& x, F f) {
    for (std::uint32_t c = 0; c < x.n; ++c) {
      const T* a = row<T>(x.a, c);
      put(row<U>(x.dst, c), [&](int l) { return f(a[l]); });
    }
  }
  template <class T, class U, class F>
  void map2(const XIns& x, F f, bool b_scalar = false) {
    for (std::uint32_t c = 0; c < x.n; ++c) {
      const T* a = row<T>(x.a, c);
      const T* b = row<T>(x.b, b_scalar ? 0 : c);
      put(row<U>(x.dst, c), [&](int l) { return f(a[l], b[l]); });
    }
  }
  template <class T, class U, class F>
  void map3(const XIns& x, F f) {
    for (std::uint32_t c = 0; c < x.n; ++c) {
      const T* a = row<T>(x.a, c);
      const T* b = row<T>(x.b, c);
      const T* d = row<T>(x.c, c);
      put(row<U>(x.dst, c), [&](int l) { return f(a[l], b[l], d[l]); });
    }
  }

  // The operand's scalar decides which instantiation runs.
  template <class F>
  void arith(const XIns& x, F f) {
    switch (x.s) {
      case Scalar::F32: f(float{}); break;
      case Scalar::F64: f(double{}); break;
      case Scalar::I32: f(std::int32_t{}); break;
      default: f(std::uint32_t{}); break;
    }
  }

  // Rows [0, words) of src into dst for the active lanes. A double's two rows hold its lanes
  // interleaved (lane l at words 2l, 2l + 1), so where one starts (`doubles`, relative word
  // offsets; null: none) whole doubles move.
  void copy_rows(std::uint32_t* dst, const std::uint32_t* src, std::uint32_t words,
                 const std::vector<std::uint32_t>* doubles) {
    std::size_t k = 0;
    for (std::uint32_t w = 0; w < words;) {
      if (doubles && k < doubles->size() && (*doubles)[k] == w) {
        const double* s = reinterpret_cast<const double*>(src + std::size_t(w) * L);
        put(reinterpret_cast<double*>(dst + std::size_t(w) * L), [&](int l) { return s[l]; });
        ++k;
        w += 2;
        continue;
      }
      const std::uint32_t* s = src + std::size_t(w) * L;
      put(dst + std::size_t(w) * L, [&](int l) { return s[l]; });
      ++w;
    }
  }
  const std::vector<std::uint32_t>* doubles_of(std::uint32_t index) const {
    return index == kNone ? nullptr : &p.doubles[index];
  }
  void words_copy(std::uint32_t dst, std::uint32_t src, std::uint32_t words, std::uint32_t doubles) {
    copy_rows(A + std::size_t(dst) * L, A + std::size_t(src) * L, words, doubles_of(doubles));
  }

  void exec(const XIns& x);
  void run_block(const XBlock& b);
  void traced_block(const XBlock& b);  // run_block, watching the traced lane's results
  void nan_check(const XIns& x);
  void source_record(const XIns& x);
  void source_record_joins(const XBlock& b);
  TraceLine* source_line(int line);
  void run_phis(const XBlock& b);
  void load(const XIns& x);
  std::uint32_t uniform_offset(const std::uint32_t* off) const;
  std::uint32_t uniform_in(const std::uint32_t* row, int lo, int hi) const;
  void store(const XIns& x);
  void access_chain(const XIns& x);
  void ext(const XIns& x);
  void compare(const XIns& x);
  void matrix(const XIns& x);
  void texture(const XIns& x);
  void image(const XIns& x);  // storage images: executor_image.cpp
  void atomic(const XIns& x);
  void derivative(const XIns& x);
  [[noreturn]] void fail(const std::string& what, int lane, int line) { throw ShaderRuntimeError(what, lane, line); }
};


}  // namespace tessref::shader
