#pragma once
// Helpers for running small GLSL programs on the SPIR-V executor directly (no stages/): compile
// one stage with compile_program, read it with read_module, and get and set a variable's value
// per lane by name, in flattened words (spirv_module.h: a double as two words, low first),
// whatever the executor's arena layout.
#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shader/executor.h"
#include "shader/glsl_compile.h"
#include "shader/spirv_module.h"

namespace tessref::shader::test {

inline std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }
inline std::uint64_t bits(double d) { return std::bit_cast<std::uint64_t>(d); }
inline float as_float(std::uint32_t w) { return std::bit_cast<float>(w); }
inline double as_double(std::uint32_t lo, std::uint32_t hi) {
  return std::bit_cast<double>(std::uint64_t(lo) | (std::uint64_t(hi) << 32));
}

// The words of a single stage's module (a vertex or fragment shader on its own).
inline std::vector<std::uint32_t> compile_stage(Stage stage, const std::string& glsl,
                                                const std::string& file = "k.glsl") {
  const CompiledProgram p = compile_program({{stage, file, 1, glsl}});
  for (const CompiledStage& s : p.stages)
    if (s.stage == stage) return s.spirv;
  throw std::runtime_error("compile_stage: no stage in the result");
}

// One stage on the executor, with its own Invocations.
class Kernel {
 public:
  explicit Kernel(const std::string& glsl, ExecLimits limits = {}, Stage stage = Stage::Vertex)
      : exe_(read_module(compile_stage(stage, glsl)), limits), inv_(exe_) {}

  const Executable& exe() const { return exe_; }
  Invocations& inv() { return inv_; }
  const Module& module() const { return exe_.module(); }

  bool has(const std::string& name) const { return find(name) != nullptr; }
  const Variable& variable(const std::string& name) const {
    const Variable* v = find(name);
    if (!v) throw std::runtime_error("no module-level variable named '" + name + "'");
    return *v;
  }
  const VariableSlot& slot(const std::string& name) const {
    const VariableSlot* s = exe_.slot(variable(name).id);
    if (!s) throw std::runtime_error("no slot for '" + name + "'");
    return *s;
  }
  const std::vector<FlatComponent>& flat(const std::string& name) const {
    return module().type(variable(name).type).flat;
  }
  // Flattened words of a variable's value (every component; a double as two words).
  std::uint32_t words(const std::string& name) const { return module().type(variable(name).type).words; }

  void begin(int lanes) { inv_.begin(lanes); }
  void run() { inv_.run(); }

  // Flattened word `word` of `name` in `lane` (per-lane variables) or of the batch (shared).
  std::uint32_t get(const std::string& name, int lane, std::uint32_t word = 0) {
    const VariableSlot& s = slot(name);
    if (!s.per_lane) return inv_.shared(s)[word];
    const auto [comp_word, high] = locate(name, word);
    if (comp_word == kNoDouble) return inv_.row(s, word)[lane];
    // A double's two rows hold kMaxLanes doubles: lane l's words are 2l and 2l + 1.
    return inv_.row(s, comp_word)[2 * lane + high];
  }
  void set(const std::string& name, int lane, std::uint32_t word, std::uint32_t value) {
    const VariableSlot& s = slot(name);
    if (!s.per_lane) {
      inv_.shared(s)[word] = value;
      return;
    }
    const auto [comp_word, high] = locate(name, word);
    if (comp_word == kNoDouble) inv_.row(s, word)[lane] = value;
    else inv_.row(s, comp_word)[2 * lane + high] = value;
  }
  // Every flattened word of `name` in `lane`.
  std::vector<std::uint32_t> value(const std::string& name, int lane) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t w = 0; w < words(name); ++w) out.push_back(get(name, lane, w));
    return out;
  }

  float f32(const std::string& name, int lane, std::uint32_t word = 0) { return as_float(get(name, lane, word)); }
  std::int32_t i32(const std::string& name, int lane, std::uint32_t word = 0) {
    return std::int32_t(get(name, lane, word));
  }
  std::uint32_t u32(const std::string& name, int lane, std::uint32_t word = 0) { return get(name, lane, word); }
  // The double whose low word is flattened word `word`.
  double f64(const std::string& name, int lane, std::uint32_t word = 0) {
    return as_double(get(name, lane, word), get(name, lane, word + 1));
  }
  void set_f32(const std::string& name, int lane, std::uint32_t word, float v) { set(name, lane, word, bits(v)); }
  void set_i32(const std::string& name, int lane, std::uint32_t word, std::int32_t v) {
    set(name, lane, word, std::uint32_t(v));
  }
  void set_f64(const std::string& name, int lane, std::uint32_t word, double v) {
    const std::uint64_t b = bits(v);
    set(name, lane, word, std::uint32_t(b));
    set(name, lane, word + 1, std::uint32_t(b >> 32));
  }

  // Runs `count` invocations in batches of `batch` lanes: set(k, lane, i) writes the inputs of
  // invocation i into `lane`; the result is every flattened word of `outputs`, per invocation.
  std::vector<std::vector<std::uint32_t>> run_batches(
      int count, int batch, const std::function<void(Kernel&, int lane, int index)>& set_inputs,
      const std::vector<std::string>& outputs) {
    std::vector<std::vector<std::uint32_t>> results(static_cast<std::size_t>(count));
    for (int first = 0; first < count; first += batch) {
      const int n = std::min(batch, count - first);
      begin(n);
      for (int l = 0; l < n; ++l) set_inputs(*this, l, first + l);
      run();
      for (int l = 0; l < n; ++l)
        for (const std::string& o : outputs) {
          const std::vector<std::uint32_t> v = value(o, l);
          results[std::size_t(first + l)].insert(results[std::size_t(first + l)].end(), v.begin(), v.end());
        }
    }
    return results;
  }

 private:
  static constexpr std::uint32_t kNoDouble = 0xffffffffu;
  const Variable* find(const std::string& name) const {
    for (const Variable& v : module().variables)
      if (v.name == name) return &v;
    return nullptr;
  }
  // For flattened word `word`: (first word of the double holding it, 0 or 1 for low or high) or
  // (kNoDouble, 0) when it is a 32-bit scalar.
  std::pair<std::uint32_t, std::uint32_t> locate(const std::string& name, std::uint32_t word) const {
    for (const FlatComponent& c : flat(name)) {
      if (c.scalar == Scalar::F64 && (word == c.word || word == c.word + 1)) return {c.word, word - c.word};
      if (c.word == word) return {kNoDouble, 0};
    }
    throw std::runtime_error("word " + std::to_string(word) + " is past '" + name + "'");
  }

  Executable exe_;
  Invocations inv_;
};

}  // namespace tessref::shader::test
