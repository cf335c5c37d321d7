#pragma once
// tessref's SPIR-V executor: runs up to kMaxLanes invocations of one entry point together, one
// decoded instruction at a time over structure-of-arrays registers, so an instruction's dispatch
// is paid once per batch. Divergent control flow keeps a block index per lane; the lanes waiting
// at the lowest-numbered block run it together (structured SPIR-V lists a construct's blocks
// before its merge block, so lanes meet again at merges and loops exit together). Every lane's
// results are those of running it alone: lanes never see each other except through shared memory
// (a TCS's outputs), written in lock step, which is barrier()'s meaning.
//
// Memory: each variable lives either per lane (Function, Private, and the stage's per-invocation
// inputs and outputs) or shared by the batch (uniforms; a TCS's gl_in[], gl_out[] and patch
// variables; a TES's inputs). A value of N flattened words (spirv_module.h) occupies N rows of
// kMaxLanes words in the per-lane arena: word w of lane l at row w, column l (a double occupies two
// rows as kMaxLanes contiguous doubles). Shared variables are plain flattened words.
//
// Out-of-range array indices are clamped into the array (GL robust access: "a value from within
// the buffer"), integer division by zero gives 0, and float-to-integer conversion of NaN or of a
// value out of range gives INT_MIN (as x86 does; unsigned: 0 below the range and for NaN,
// 0xffffffff above it): never undefined behaviour (docs/executor.md).
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shader/spirv_module.h"
#include "texture/texture.h"

namespace tessref::shader {

inline constexpr int kMaxLanes = 256;

// A runaway or failed invocation: what() names the cause; the stage adapters add the stage, patch
// and invocation.
class ShaderRuntimeError : public std::runtime_error {
 public:
  ShaderRuntimeError(const std::string& what, int lane, int line)
      : std::runtime_error(what), lane(lane), line(line) {}
  int lane;  // the lane (invocation within the batch) that failed
  int line;  // source line, 0 when unknown
};

struct ExecLimits {
  // Instructions one invocation may execute before it is stopped as a runaway (infinite loop).
  std::uint64_t max_instructions = 50'000'000;
  // Invocations the stage programs run per batch, 1..kMaxLanes (a fragment shader's batches are
  // whole 2x2 quads, so at least 4; a TCS runs a patch's invocations together). Results never
  // depend on it: it exists to show that, and to measure what batching gains.
  int batch_lanes = kMaxLanes;
  // Private memory of one invocation, in bytes: its registers, constants and per-invocation
  // variables (locals, globals, its own inputs and outputs). Each thread keeps kMaxLanes
  // invocations' worth (256 MiB at this default, whatever batch_lanes is), so this bounds what
  // local arrays cost: `float a[10000000]` would take 10 GB. A program above it is refused when it
  // is built, naming its largest per-invocation variable (docs/executor.md, "Limits").
  std::uint64_t max_private_bytes = std::uint64_t(1) << 20;
};

// Where a variable lives (see above). Shared variables are either common to the batch (uniforms)
// or per group: a TCS batch can hold several patches, each a group of lanes with its own copy of
// the patch's inputs and outputs.
struct VariableSlot {
  std::uint32_t id = 0;
  std::uint32_t base = 0;   // per lane: first row in the arena; shared: first word (per group:
                            // within the group's block)
  std::uint32_t words = 0;  // flattened size
  bool per_lane = true;
  bool per_group = false;
  // A shader storage block: read and written in the memory Invocations::bind_storage gives it,
  // which every batch, thread and stage of a draw shares (its words here are only a fallback).
  bool storage = false;
};

struct DecodedProgram;  // executor.cpp

class Executable;

// Per-thread state of one Executable: the arena, shared memory and lane bookkeeping. Reused batch
// after batch; not thread-safe.
class Invocations {
 public:
  explicit Invocations(const Executable& exe);
  ~Invocations();
  Invocations(const Invocations&) = delete;
  Invocations& operator=(const Invocations&) = delete;

  // Starts a batch of `lanes` invocations in `groups` groups (all lanes in group 0 until
  // set_group): per-lane Function/Private variables are reset to their initializers (or zero) and
  // outputs to zero; shared memory keeps what was written into it.
  void begin(int lanes, int groups = 1);
  void set_group(int lane, int group);
  int lanes() const { return lanes_; }

  // Per-lane rows and shared words of a variable (by slot, see Executable::slot).
  std::uint32_t* row(const VariableSlot& v, std::uint32_t word) {
    return arena_.data() + std::size_t(v.base + word) * kMaxLanes;
  }
  // A shared variable's words (of group 0, or of `group`).
  std::uint32_t* shared(const VariableSlot& v, int group = 0) {
    return shared_.data() + (v.per_group ? group_word(group) : 0) + v.base;
  }
  std::uint32_t* shared_words() { return shared_.data(); }  // the common words
  // Zeroes the common words and the first `groups` groups' blocks.
  void zero_shared(int groups = 1);

  // The texture a sampler whose value is `binding` (its texture unit) reads; null: none, which
  // reads as an incomplete texture.
  void bind_texture(std::uint32_t binding, const texture::Texture* t);
  // The words a shader storage block variable reads and writes (flattened, as a shared variable's):
  // memory outside the batch, kept by the caller for the whole draw; null: its own shared words.
  void bind_storage(std::uint32_t variable_id, std::uint32_t* words);
  // The texture an image uniform whose value is `unit` reads and writes (glBindImageTexture of its
  // level 0; its format is the one the image declares); null: none, whose loads read 0 and whose
  // stores are dropped. Writes go to the texture's stored bytes and the texels the sampler reads.
  void bind_image(std::uint32_t unit, texture::Texture* t);
  // Lanes that run as helper invocations (a fragment quad's lanes that cover no sample): their
  // stores to storage blocks and their atomics have no effect (GL 4.6 15.2.5). Reset by begin().
  void set_helpers(const std::uint8_t* helper);

  // glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS): cube maps are filtered across their faces' edges.
  void set_cube_map_seamless(bool on) { seamless_cube_ = on; }
  // Which lanes a GL driver would sample together (llvmpipe: a vector of two fragment quads),
  // one key per lane, for the current batch; lanes with equal keys must be adjacent. Without a
  // call after begin(), each fragment quad (other stages: each lane) is its own vector.
  void set_sampling_vectors(const std::uint32_t* keys);

  // A geometry shader's EmitVertex / EndPrimitive (EmitStreamVertex, EndStreamPrimitive): called
  // for each lane that runs one, with its stream, while the lane's outputs hold what it wrote
  // (row() reads them). Without a handler the calls do nothing.
  void on_emit(std::function<void(int lane, int stream, bool end)> handler) { emit_ = std::move(handler); }

  // Runs main() for lanes 0 .. lanes() - 1. Throws ShaderRuntimeError.
  void run();
  // After run(): lanes that executed OpKill (discard).
  const std::uint8_t* discarded() const { return killed_.data(); }
  // After run(): per-lane atomic counter values are in shared memory like any variable.

 private:
  friend struct Runner;
  const Executable& exe_;
  std::vector<std::uint32_t> arena_;   // registers and per-lane variables
  std::vector<std::uint32_t> shared_;  // shared variables: the common words, then one block per group
  std::uint32_t group_word(int group) const;
  std::uint32_t group_base_[kMaxLanes] = {};  // each lane's group block (first word in shared_)
  int groups_ = 1;
  std::vector<std::uint8_t> killed_;
  std::function<void(int, int, bool)> emit_;
  std::vector<std::uint32_t> staging_;  // phi values between reading and writing
  std::vector<std::uint32_t> phi_doubles_;  // scratch for Runner::run_phis
  std::vector<const texture::Texture*> textures_;
  std::vector<std::uint32_t*> storage_;  // by slot index: bind_storage's memory, null if none
  std::vector<texture::Texture*> images_;  // by image unit
  std::uint8_t helper_[kMaxLanes] = {};
  bool has_helpers_ = false;
  bool seamless_cube_ = false;
  std::uint32_t sampling_vector_[kMaxLanes] = {};
  bool has_sampling_vectors_ = false;
  int lanes_ = 0;
};

// The internal format of a storage image's layout qualifier (a spv::ImageFormat), or nullopt for
// one tessref's textures do not have (rgb10_a2).
std::optional<texture::TexelFormat> image_texel_format(std::uint32_t spv_format);

// A decoded, immutable program: one per shader stage, shared by all threads.
class Executable {
 public:
  // `shared_io`: whether the stage's Input/Output variables are shared by the batch (a TCS's and
  // a TES's patch data) rather than per lane; the per-invocation built-ins (gl_InvocationID,
  // gl_TessCoord) stay per lane either way. Throws SpirvError for unsupported instructions and
  // for private memory above limits.max_private_bytes.
  Executable(Module module, ExecLimits limits = {});
  ~Executable();

  const Module& module() const { return module_; }
  // The slot of a module-level variable; nullptr if there is none with that id.
  const VariableSlot* slot(std::uint32_t variable_id) const;
  const ExecLimits& limits() const { return limits_; }
  // Whether the entry point can discard (OpKill, OpTerminateInvocation, OpDemoteToHelperInvocation).
  bool may_discard() const;
  // Whether the entry point takes a derivative (dFdx, dFdy, fwidth: other lanes of its quad).
  bool reads_quads() const;
  // Whether the entry point writes memory other invocations see: a store or atomic into a shader
  // storage block, or an atomic counter operation. Such a program's invocations must run in one
  // fixed order (docs/executor.md, "Side effects").
  bool writes_memory() const;
  // Whether the entry point filters textures (OpImageSample*): only then do the lanes a driver
  // samples together matter (Invocations::set_sampling_vectors).
  bool samples_textures() const;
  // This thread's Invocations of this executable, made on first use and kept for the thread's
  // life (stage programs are shared by the worker threads; each thread runs its own batches).
  Invocations& local() const;

 private:
  friend class Invocations;
  friend struct Runner;
  Module module_;
  ExecLimits limits_;
  std::unique_ptr<DecodedProgram> program_;
  std::uint64_t serial_;  // tells this executable's thread-local state from an earlier one's
  // Expires with the executable, so that threads can drop their state of executables now gone.
  std::shared_ptr<const bool> alive_ = std::make_shared<const bool>(true);
};

}  // namespace tessref::shader
