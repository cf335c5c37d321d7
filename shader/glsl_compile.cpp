#include "shader/glsl_compile.h"

#include <glslang/MachineIndependent/LiveTraverser.h>  // internal headers, installed by Debian:
#include <glslang/MachineIndependent/iomapper.h>       // liveness, the OpenGL IO mapper
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Include/InfoSink.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "shader/glsl_rewrite.h"

namespace tessref::shader {

const char* stage_name(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return "vertex shader";
    case Stage::TessControl: return "tessellation control shader";
    case Stage::TessEval: return "tessellation evaluation shader";
    case Stage::Geometry: return "geometry shader";
    case Stage::Fragment: return "fragment shader";
  }
  return "shader";
}

namespace {

constexpr std::array kPipeline = {Stage::Vertex, Stage::TessControl, Stage::TessEval,
                                  Stage::Geometry, Stage::Fragment};

// Like glslangValidator -G: OpenGL SPIR-V rules; debug info keeps the source text for OpSource.
constexpr EShMessages kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgDebugInfo);

EShLanguage language(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return EShLangVertex;
    case Stage::TessControl: return EShLangTessControl;
    case Stage::TessEval: return EShLangTessEvaluation;
    case Stage::Geometry: return EShLangGeometry;
    case Stage::Fragment: return EShLangFragment;
  }
  return EShLangVertex;
}

void throw_if_any(const std::vector<std::string>& errors) {
  if (errors.empty()) return;
  std::string what;
  for (const std::string& e : errors) what += (what.empty() ? "" : "\n") + e;
  throw CompileError(what);
}

// ---------------------------------------------------------------------------------------------
// glslang's info log -> "FILE:LINE: error: MESSAGE". Located messages start with a source's
// name (setStringsWithLengthsAndNames) and carry the user's line (the rewrite's #line); the
// others are placed at `file`, with the stage spelled as a GL linker would.

std::string trim(std::string s) {
  s.erase(s.find_last_not_of(" \t\r") + 1);
  s.erase(0, std::min(s.find_first_not_of(" \t"), s.size()));
  return s;
}

// A function's GLSL name from glslang's mangled one ("f(f1;" -> "f").
std::string unmangled(const std::string& mangled) { return trim(mangled.substr(0, mangled.find('('))); }

// glslang's terse messages with what they mean for a GL program. `next` is the log's next line
// (glslang lists a recursion's calls there, unprefixed).
std::string explained(std::string message, const std::string& next) {
  if (message.ends_with("Recursion detected:")) {
    const std::size_t calling = next.find(" calling ");
    message.pop_back();  // the colon
    message += calling == std::string::npos
                   ? ": a function calls itself, directly or through other functions"
                   : ": " + unmangled(next.substr(0, calling)) + "() calls " + unmangled(next.substr(calling + 9)) +
                         "(), and the calls lead back to it";
    return message + "; GLSL forbids recursion (GLSL 4.60, section 6.1.2)";
  }
  if (message.find("requires SPIR-V 1.3") != std::string::npos)
    return trim(message) + ": tessref compiles GLSL for OpenGL 4.5 (SPIR-V 1.0), which has no subgroup "
                           "operations (GL_KHR_shader_subgroup_*)";
  if (message.find("-- expected newline") != std::string::npos ||
      message.find("unexpected tokens following directive") != std::string::npos)
    return trim(message) + " (the directive has more on its line than GLSL allows: only a comment may follow it)";
  return message;
}

void add_log_errors(const char* log, const std::vector<ShaderSource>& sources,
                    const std::string& file, std::vector<std::string>& errors) {
  std::vector<std::string> all;
  {
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);) all.push_back(line);
  }
  for (std::size_t i = 0; i < all.size(); ++i) {
    const std::string& line = all[i];
    std::string message;
    for (const char* prefix : {"ERROR: ", "INTERNAL ERROR: ", "UNIMPLEMENTED: "})
      if (line.starts_with(prefix)) message = line.substr(std::string_view(prefix).size());
    if (message.empty() || message.find("compilation errors.") != std::string::npos ||
        message.find("compilation terminated") != std::string::npos)
      continue;
    message = explained(message, i + 1 < all.size() ? all[i + 1] : std::string());
    std::string located;
    for (const ShaderSource& s : sources) {
      if (!message.starts_with(s.file + ":")) continue;
      std::size_t digits = s.file.size() + 1;
      std::size_t colon = message.find(':', digits);
      if (colon == std::string::npos || colon == digits ||
          message.find_first_not_of("0123456789", digits) != colon)
        continue;
      located = message.substr(0, colon) + ": error: " + trim(message.substr(colon + 1));
    }
    if (located.empty()) {
      for (Stage s : kPipeline) {
        std::string linking = "Linking " + std::string(stage_name(s));
        linking.replace(linking.rfind(" shader"), 7, " stage: ");
        if (message.starts_with(linking))
          message = "link error: " + std::string(stage_name(s)) + ": " +
                    message.substr(linking.size());
      }
      located = file + ": error: " + trim(message);
    }
    if (std::find(errors.begin(), errors.end(), located) == errors.end()) errors.push_back(located);
  }
}

// ---------------------------------------------------------------------------------------------
// The stage interfaces, for the link check: a GL linker matches an output to the next stage's
// input by name (the block name for a block) or, where the input has a location, by location.
// glslang 12 does not report an input without an output, and names no stage in a mismatch.

bool is_builtin(const glslang::TIntermSymbol& symbol) {
  const glslang::TType& type = symbol.getType();
  if (type.isBuiltIn() || symbol.getName().compare(0, 3, "gl_") == 0) return true;
  return type.isStruct() && !type.getStruct()->empty() && (*type.getStruct())[0].type->isBuiltIn();
}

std::string interface_name(const glslang::TIntermSymbol& symbol) {
  const glslang::TType& type = symbol.getType();
  return (type.getBasicType() == glslang::EbtBlock ? type.getTypeName() : symbol.getName()).c_str();
}

struct IoVariable {
  bool input;
  bool arrayed;  // a per-vertex array (TCS in/out, TES in) whose outer size is not compared
  std::string name;
  const glslang::TType* type;
  std::optional<glslang::TSourceLoc> first_use;  // none: not statically used
  int location;   // explicit, or -1
  int component;  // layout(component), 0 without one
};

// The type a linker compares: without the per-vertex array, with `patch`.
std::string type_text(const IoVariable& v) {
  const glslang::TType& t = *v.type;
  std::string text = t.getQualifier().patch ? "patch " : "";
  const char* prefix = "";
  switch (t.getBasicType()) {
    case glslang::EbtDouble: prefix = "d"; break;
    case glslang::EbtInt: prefix = "i"; break;
    case glslang::EbtUint: prefix = "u"; break;
    case glslang::EbtBool: prefix = "b"; break;
    default: break;
  }
  if (t.getBasicType() == glslang::EbtBlock)
    text += "block " + std::string(t.getTypeName().c_str());
  else if (t.isStruct())
    text += "struct " + std::string(t.getTypeName().c_str());
  else if (t.isMatrix())
    text += std::string(prefix) + "mat" + std::to_string(t.getMatrixCols()) +
            (t.getMatrixCols() == t.getMatrixRows() ? "" : "x" + std::to_string(t.getMatrixRows()));
  else if (t.isVector())
    text += std::string(prefix) + "vec" + std::to_string(t.getVectorSize());
  else
    text += t.getBasicTypeString().c_str();
  if (const glslang::TArraySizes* sizes = t.getArraySizes())
    for (int d = v.arrayed ? 1 : 0; d < sizes->getNumDims(); ++d) {
      text += '[';
      if (sizes->getDimSize(d) > 0) text += std::to_string(sizes->getDimSize(d));
      text += ']';
    }
  return text;
}

// GLSL 4.50, 4.3.4: structures (and blocks, which a location may pair whatever their names)
// match when their members match in name, type and order; the structure's own name does not count.
bool same_shape(const glslang::TType& a, const glslang::TType& b) {
  if (!a.isStruct() || !b.isStruct()) return a == b;
  if (a.isArray() != b.isArray() || (a.isArray() && !(*a.getArraySizes() == *b.getArraySizes()))) return false;
  const glslang::TTypeList& ma = *a.getStruct();
  const glslang::TTypeList& mb = *b.getStruct();
  if (ma.size() != mb.size()) return false;
  for (std::size_t i = 0; i < ma.size(); ++i)
    if (ma[i].type->getFieldName() != mb[i].type->getFieldName() || !same_shape(*ma[i].type, *mb[i].type)) return false;
  return true;
}

bool same_type(const IoVariable& a, const IoVariable& b) {
  if (a.type->getQualifier().patch != b.type->getQualifier().patch) return false;
  auto equals_b = [&b](const glslang::TType& type) {
    return b.arrayed ? same_shape(type, glslang::TType(*b.type, 0)) : same_shape(type, *b.type);
  };
  return a.arrayed ? equals_b(glslang::TType(*a.type, 0)) : equals_b(*a.type);
}

// The symbols that the entry point's call tree references (GL's "statically used": an input
// nothing reads needs no matching output), each with its first use in the text. glslang keeps
// no line for a global's declaration, so messages point at that first use.
class LiveSymbols : public glslang::TLiveTraverser {
 public:
  explicit LiveSymbols(const glslang::TIntermediate& intermediate) : TLiveTraverser(intermediate) {
    pushFunction(intermediate.getEntryPointMangledName().c_str());
    while (!destinations.empty()) {
      TIntermNode* function = destinations.back();
      destinations.pop_back();
      function->traverse(this);
    }
  }
  void visitSymbol(glslang::TIntermSymbol* symbol) override {
    auto [it, added] = first_use.emplace(symbol->getName().c_str(), symbol->getLoc());
    if (symbol->getLoc().line < it->second.line) it->second = symbol->getLoc();
  }
  std::map<std::string, glslang::TSourceLoc> first_use;
};

// The first static use of the stage's built-in gl_PerVertex input (gl_in[]) and output blocks.
struct PerVertexUse {
  std::optional<glslang::TSourceLoc> in, out;
};

struct StageInterface {
  Stage stage;
  std::vector<IoVariable> vars;
  PerVertexUse per_vertex;
};

// The stage's user inputs and outputs and its use of the built-in blocks, from one walk of its
// linker objects.
StageInterface interface_of(Stage stage, const glslang::TIntermediate& intermediate) {
  const LiveSymbols live(intermediate);
  const EShLanguage lang = language(stage);
  StageInterface out{stage, {}, {}};
  for (TIntermNode* global : intermediate.getTreeRoot()->getAsAggregate()->getSequence()) {
    const glslang::TIntermAggregate* objects = global->getAsAggregate();
    if (!objects || objects->getOp() != glslang::EOpLinkerObjects) continue;
    for (TIntermNode* object : objects->getSequence()) {
      const glslang::TIntermSymbol* symbol = object->getAsSymbolNode();
      if (!symbol) continue;
      const glslang::TQualifier& q = symbol->getQualifier();
      if (q.storage != glslang::EvqVaryingIn && q.storage != glslang::EvqVaryingOut) continue;
      const auto use = live.first_use.find(symbol->getName().c_str());
      const std::optional<glslang::TSourceLoc> first_use =
          use == live.first_use.end() ? std::nullopt : std::optional(use->second);
      if (symbol->getType().getBasicType() == glslang::EbtBlock && symbol->getType().getTypeName() == "gl_PerVertex") {
        if (first_use) (q.storage == glslang::EvqVaryingIn ? out.per_vertex.in : out.per_vertex.out) = first_use;
        continue;
      }
      if (is_builtin(*symbol)) continue;
      out.vars.push_back(IoVariable{q.storage == glslang::EvqVaryingIn, q.isArrayedIo(lang), interface_name(*symbol),
                                    &symbol->getType(), first_use,
                                    q.hasLocation() ? static_cast<int>(q.layoutLocation) : -1,
                                    q.hasComponent() ? static_cast<int>(q.layoutComponent) : 0});
    }
  }
  return out;
}

std::string where(const glslang::TSourceLoc& loc) {
  return std::string(loc.getFilenameStr()) + ":" + std::to_string(loc.line);
}
// " (FILE:LINE)" of a variable's first use, or nothing.
std::string used_at(const IoVariable& v) {
  return v.first_use ? " (" + where(*v.first_use) + ")" : "";
}

// GL's rules between adjacent stages (OpenGL 4.5, 7.4.1; GLSL 4.50, 4.4.1): an output matches an
// input when both have the same location and component, or when neither has a location and
// their names agree; a location on one side only matches nothing (Mesa links it so: the input
// then reads undefined values). Every statically used input needs a match of the same type.
void check_links(const std::vector<StageInterface>& stages, std::vector<std::string>& errors) {
  for (std::size_t i = 1; i < stages.size(); ++i) {
    const StageInterface& producer = stages[i - 1];
    const StageInterface& consumer = stages[i];
    for (const IoVariable& in : consumer.vars) {
      if (!in.input || !in.first_use) continue;
      auto output = [&](auto matches) -> const IoVariable* {
        for (const IoVariable& out : producer.vars)
          if (!out.input && matches(out)) return &out;
        return nullptr;
      };
      const IoVariable* out =
          in.location >= 0
              ? output([&](const IoVariable& o) { return o.location == in.location && o.component == in.component; })
              : output([&](const IoVariable& o) { return o.location < 0 && o.name == in.name; });
      const std::string head = where(*in.first_use) + ": error: link error: " +
                               stage_name(consumer.stage) + " input '" + in.name + "'";
      const std::string other = std::string(stage_name(producer.stage)) + " output";
      if (!out) {
        const IoVariable* named = output([&](const IoVariable& o) { return o.name == in.name; });
        if (named && (named->location < 0) != (in.location < 0))
          errors.push_back(head + (in.location >= 0 ? " has location " + std::to_string(in.location) + " but the " + other +
                                                          used_at(*named) + " of that name has none"
                                                    : " has no location but the " + other + used_at(*named) +
                                                          " of that name has location " + std::to_string(named->location)) +
                           ": GL matches by name only when neither side has a location, so on a driver the input "
                           "would have no matching output (give both the same location, or neither)");
        else if (in.location >= 0)
          errors.push_back(head + " has location " + std::to_string(in.location) +
                           (in.component ? " component " + std::to_string(in.component) : std::string()) +
                           " but no " + other + " has that location" +
                           (in.component ? " and component" : ""));
        else
          errors.push_back(head + " has no matching output in the " + stage_name(producer.stage));
      } else if (!same_type(in, *out)) {
        errors.push_back(head + " is " + type_text(in) + " but the " + other + " '" + out->name + "'" +
                         used_at(*out) + " is " + type_text(*out));
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// SPIR-V: generated with debug info (OpLine, OpName for every variable, OpSource with the
// rewritten text), then legalized.

constexpr spv_target_env kTargetEnv = SPV_ENV_OPENGL_4_5;

std::vector<std::uint32_t> to_spirv(const glslang::TIntermediate& intermediate,
                                    const std::string& file) {
  glslang::SpvOptions options;
  options.generateDebugInfo = true;
  options.disableOptimizer = true;  // legalize() runs its own pass list
  spv::SpvBuildLogger logger;
  std::vector<unsigned int> spirv;
  glslang::GlslangToSpv(intermediate, spirv, &logger, &options);
  const std::string messages = logger.getAllMessages();
  if (messages.find("error") != std::string::npos ||
      messages.find("Missing functionality") != std::string::npos)
    throw CompileError(file + ": error: glslang cannot generate SPIR-V: " + trim(messages));
  return {spirv.begin(), spirv.end()};
}

// How many instructions of `opcode` a module holds.
std::size_t count_opcode(const std::vector<std::uint32_t>& spirv, std::uint32_t opcode) {
  std::size_t n = 0;
  for (std::size_t i = 5; i < spirv.size(); i += std::max<std::uint32_t>(spirv[i] >> 16, 1))
    n += (spirv[i] & 0xffffu) == opcode;
  return n;
}
constexpr std::uint32_t kOpFunctionCall = 57, kOpLoopMerge = 246;

// Optimizer::RegisterLegalizationPasses (SPIRV-Tools 2023.1) without the passes that may change
// a floating-point result or that only HLSL needs:
// - no SimplificationPass: its folding rules turn x + 0.0 into x (wrong for -0.0; the twins
//   write `p += vec3(0.0)` on purpose), x * 1.0 into x and (x * c1) * c2 into x * (c1 * c2);
// - no CCP: its constant folding is IEEE-exact for + - * /, but it also folds dot(x, 0-vector)
//   to 0.0 whatever x holds (NaN, inf) and sin/exp/pow... of constants with the host libm in
//   double, so a result would depend on what inlining happened to make constant;
// - no LoopUnroll: GLSL needs no unrolling to be legal, and loops stay as written;
// - no FixStorageClass, ReduceLoadSize, InterpolateFixup: DXC's cases or pure optimizations.
// What remains moves no arithmetic: it inlines, promotes memory to SSA values, removes dead
// code. OpLine survives on every instruction that survives (the tests check it). A line can lose
// all its instructions: a call (inlined, the body keeps the callee's lines), a function header,
// a store to a local that became an SSA value (`vec3 c = vec3(0.0);`). pn_triangles.tesc keeps
// 72 of its 82 lines. Instructions the passes create (OpPhi) have no line.
// In two lists, so that the loops can be counted between them (legalize). The first inlines:
void register_inlining_passes(spvtools::Optimizer& optimizer) {
  optimizer
      .RegisterPass(spvtools::CreateWrapOpKillPass())  // discard in a function: inlinable
      .RegisterPass(spvtools::CreateDeadBranchElimPass())  // unreachable blocks, for MergeReturn
      .RegisterPass(spvtools::CreateMergeReturnPass())     // one return per function, to inline
      .RegisterPass(spvtools::CreateInlineExhaustivePass())
      .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
      .RegisterPass(spvtools::CreatePrivateToLocalPass());  // globals main alone uses: locals
}

// The second promotes memory to SSA values and, with `dead_code`, removes dead code. AggressiveDCE
// also removes a loop whose results nothing uses, even one that never ends (`while (true) {}`):
// without it the executor runs such a loop into its instruction budget, as a GPU would hang.
void register_ssa_passes(spvtools::Optimizer& optimizer, bool dead_code) {
  auto dce = [&] {
    if (dead_code) optimizer.RegisterPass(spvtools::CreateAggressiveDCEPass());
  };
  optimizer.RegisterPass(spvtools::CreateLocalSingleBlockLoadStoreElimPass())
      .RegisterPass(spvtools::CreateLocalSingleStoreElimPass());
  dce();
  optimizer.RegisterPass(spvtools::CreateScalarReplacementPass(0))  // split local arrays/structs
      .RegisterPass(spvtools::CreateLocalSingleBlockLoadStoreElimPass())
      .RegisterPass(spvtools::CreateLocalSingleStoreElimPass());
  dce();
  optimizer.RegisterPass(spvtools::CreateLocalMultiStoreElimPass());  // the rest to SSA (OpPhi)
  dce();
  optimizer.RegisterPass(spvtools::CreateCopyPropagateArraysPass())
      .RegisterPass(spvtools::CreateVectorDCEPass())
      .RegisterPass(spvtools::CreateDeadInsertElimPass());
  dce();
  optimizer.RegisterPass(spvtools::CreateBlockMergePass());  // the straight-line blocks inlining left
}

// glslang keeps an OpenGL `uniform bool` as a bool in UniformConstant storage, which the SPIR-V
// spec reserves for storage that is not externally visible (Mesa's GL SPIR-V path takes it). The
// validator stops at the first such variable; so the rest is validated on a copy in which the
// uniforms that hold no opaque type are Private instead.
std::vector<std::uint32_t> with_private_uniforms(std::vector<std::uint32_t> spirv) {
  enum : std::uint32_t {
    OpTypeVector = 23, OpTypeMatrix = 24, OpTypeImage = 25, OpTypeSampler = 26,
    OpTypeSampledImage = 27, OpTypeArray = 28, OpTypeRuntimeArray = 29, OpTypeStruct = 30,
    OpTypePointer = 32, OpVariable = 59, UniformConstant = 0, Private = 6
  };
  std::set<std::uint32_t> opaque, private_pointers;
  for (std::size_t i = 5; i < spirv.size(); i += std::max<std::uint32_t>(spirv[i] >> 16, 1)) {
    const std::uint32_t op = spirv[i] & 0xffffu, count = spirv[i] >> 16;
    switch (op) {
      case OpTypeImage: case OpTypeSampler: case OpTypeSampledImage:
        opaque.insert(spirv[i + 1]);
        break;
      case OpTypeVector: case OpTypeMatrix: case OpTypeArray: case OpTypeRuntimeArray:
      case OpTypeStruct:  // element types: one word, or every member of a struct
        for (std::uint32_t k = 2; k < (op == OpTypeStruct ? count : 3); ++k)
          if (opaque.count(spirv[i + k])) opaque.insert(spirv[i + 1]);
        break;
      case OpTypePointer:
        if (spirv[i + 2] == UniformConstant && !opaque.count(spirv[i + 3])) {
          spirv[i + 2] = Private;
          private_pointers.insert(spirv[i + 1]);
        }
        break;
      case OpVariable:
        if (private_pointers.count(spirv[i + 1])) spirv[i + 3] = Private;
        break;
      default: break;
    }
  }
  return spirv;
}

// A SPIRV-Tools message consumer that appends errors to `diagnostics`.
spvtools::MessageConsumer collect_errors(std::string& diagnostics) {
  return [&diagnostics](spv_message_level_t level, const char*, const spv_position_t&,
                        const char* message) {
    if (level > SPV_MSG_ERROR) return;
    diagnostics += std::string(diagnostics.empty() ? "" : "; ") + message;
  };
}

void validate(const std::vector<std::uint32_t>& spirv, const std::string& file, const char* what) {
  std::string diagnostics;
  auto valid = [&diagnostics](const std::vector<std::uint32_t>& module) {
    spvtools::SpirvTools tools(kTargetEnv);
    diagnostics.clear();
    tools.SetMessageConsumer(collect_errors(diagnostics));
    return tools.Validate(module);
  };
  if (valid(spirv)) return;
  if (diagnostics.find("If OpTypeBool is stored in conjunction with OpVariable") !=
          std::string::npos &&
      valid(with_private_uniforms(spirv)))
    return;
  throw std::logic_error(file + ": internal error: " + what + " does not validate: " + diagnostics);
}

std::vector<std::uint32_t> legalize(const std::vector<std::uint32_t>& spirv,
                                    const std::string& file) {
  validate(spirv, file, "glslang's SPIR-V");
  std::string diagnostics;
  auto run = [&](const std::vector<std::uint32_t>& in, const auto& register_list) {
    spvtools::Optimizer optimizer(kTargetEnv);
    optimizer.SetMessageConsumer(collect_errors(diagnostics));
    register_list(optimizer);
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);  // validate() did, tolerating glslang's bool uniforms
    std::vector<std::uint32_t> out;
    if (!optimizer.Run(in.data(), in.size(), &out, options))
      throw std::logic_error(file + ": internal error: SPIR-V legalization failed: " + diagnostics);
    return out;
  };
  const std::vector<std::uint32_t> inlined = run(spirv, register_inlining_passes);
  std::vector<std::uint32_t> legal = run(inlined, [](spvtools::Optimizer& o) { register_ssa_passes(o, true); });
  // Dead-code removal dropped a loop (its results unused, or no way out of it): keep the dead
  // code, so that every loop the shader runs is run, and one that never ends meets the budget.
  if (count_opcode(legal, kOpLoopMerge) < count_opcode(inlined, kOpLoopMerge))
    legal = run(inlined, [](spvtools::Optimizer& o) { register_ssa_passes(o, false); });
  validate(legal, file, "legalized SPIR-V");
  if (count_opcode(legal, kOpFunctionCall) > 0)
    throw CompileError(file + ": error: a function could not be inlined (discard in a loop's "
                              "continue expression?)");
  return legal;
}

const char* first_file(const std::vector<ShaderSource>& sources, Stage stage) {
  for (const ShaderSource& s : sources)
    if (s.stage == stage) return s.file.c_str();
  return sources.front().file.c_str();
}

void init_glslang() {
  static const bool initialized = glslang::InitializeProcess();
  (void)initialized;
}

// A TCS of several compilation units: glslang compiles each unit alone, so a unit that indexes
// gl_out[] without the output vertex count that another unit declares fails to compile. Each such
// unit gets the declaration too (GLSL lets every unit repeat it with the same count); the line is
// added before the unit's #line, so its line numbers stay the user's.
void lend_output_vertices(const std::vector<ShaderSource>& sources, std::vector<RewrittenSource>& rewritten) {
  static const std::regex declaration(R"(layout\s*\(\s*vertices\s*=\s*(\d+)\s*\)\s*out\s*;)");
  std::string count;
  int units = 0;
  for (const ShaderSource& s : sources) {
    if (s.stage != Stage::TessControl) continue;
    ++units;
    std::smatch m;
    if (count.empty() && std::regex_search(s.text, m, declaration)) count = m[1];
  }
  if (units < 2 || count.empty()) return;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (sources[i].stage != Stage::TessControl || std::regex_search(sources[i].text, declaration)) continue;
    std::string& text = rewritten[i].text;
    const std::size_t eol = text.find('\n');  // after "#version ..."
    text.insert(eol + 1, "layout(vertices = " + count + ") out;\n");
    rewritten[i].notes.push_back(sources[i].file + ":" + std::to_string(sources[i].first_line) +
                                 ": layout(vertices = " + count +
                                 ") out; added from another unit of the tessellation control shader");
  }
}

// GLSL 4.50 section 4.4.2.1: an output patch of more than GL_MAX_PATCH_VERTICES vertices is a
// compile-time error. glslang does not check it, and the pipeline would meet it only at the draw,
// as an internal limit. Placed at the declaration's line where the text shows it.
void check_output_vertices(const ShaderSource& source, const glslang::TShader& shader,
                           std::vector<std::string>& errors) {
  const int vertices = shader.getIntermediate()->getVertices();
  if (source.stage != Stage::TessControl || vertices <= kGlMaxPatchVertices) return;
  // The declaration with this count (not a comment that mentions layout(vertices = N)).
  const std::regex declaration(R"(layout\s*\([^)]*\bvertices\s*=\s*)" + std::to_string(vertices) +
                               R"(\b[^)]*\)\s*out\s*;)");
  std::smatch m;
  int line = source.first_line;
  if (std::regex_search(source.text, m, declaration))
    line += int(std::count(source.text.begin(), source.text.begin() + m.position(0), '\n'));
  errors.push_back(source.file + ":" + std::to_string(line) + ": error: layout(vertices = " +
                   std::to_string(vertices) + ") is more than GL_MAX_PATCH_VERTICES (" +
                   std::to_string(kGlMaxPatchVertices) + "): an output patch has 1 to " +
                   std::to_string(kGlMaxPatchVertices) + " vertices");
}

// OpenGL 4.5, 7.4: "To use any built-in input or output in the gl_PerVertex ... blocks in
// separable program objects, shader code must redeclare those blocks prior to use." As Mesa
// checks it: between each stage and the next one in the program, for GLSL 1.50 and later
// (ARB_separate_shader_objects issue 28 exempts 1.40 and earlier, which have no blocks).
void check_separable_blocks(const std::vector<StageInterface>& stages, const std::vector<ShaderSource>& sources, const std::vector<RewrittenSource>& rewritten,
                            std::vector<std::string>& errors) {
  int version = 0;
  for (const RewrittenSource& r : rewritten) version = std::max(version, r.version);
  if (version < 150) return;
  auto redeclares = [&](Stage stage, bool in) {
    for (std::size_t i = 0; i < sources.size(); ++i)
      if (sources[i].stage == stage && (in ? rewritten[i].redeclares_per_vertex_in : rewritten[i].redeclares_per_vertex_out))
        return true;
    return false;
  };
  for (std::size_t i = 0; i + 1 < stages.size(); ++i)
    for (const bool in : {false, true}) {
      const std::size_t k = in ? i + 1 : i;  // the producer's outputs, then the consumer's inputs
      const std::optional<glslang::TSourceLoc>& use = in ? stages[k].per_vertex.in : stages[k].per_vertex.out;
      if (!use || redeclares(stages[k].stage, in)) continue;
      errors.push_back(where(*use) + ": error: link error: the " + stage_name(stages[k].stage) + " uses the built-in " +
                       (in ? "input" : "output") + " block gl_PerVertex without redeclaring it ('" +
                       (in ? "in" : "out") + " gl_PerVertex { ... }'), which a separable program of GLSL 1.50 or " +
                       "later must (OpenGL 4.5, 7.4)");
    }
}

}  // namespace

CompiledProgram compile_program(const std::vector<ShaderSource>& sources, Linking linking) {
  if (sources.empty()) throw CompileError("error: a program needs at least one shader");
  std::vector<std::string> errors;
  // GL 4.5 section 7.3: a (non-separable) program with tessellation or geometry shaders needs a
  // vertex shader.
  const bool has_vertex = std::any_of(sources.begin(), sources.end(), [](const ShaderSource& s) {
    return s.stage == Stage::Vertex;
  });
  for (const ShaderSource& s : sources)
    if (!has_vertex && (s.stage == Stage::TessControl || s.stage == Stage::TessEval || s.stage == Stage::Geometry)) {
      errors.push_back(s.file + ":" + std::to_string(s.first_line) + ": error: link error: a " +
                       stage_name(s.stage) + " needs a vertex shader in the program");
      break;
    }
  throw_if_any(errors);

  std::vector<RewrittenSource> rewritten;
  for (const ShaderSource& s : sources) rewritten.push_back(rewrite_glsl(s));
  lend_output_vertices(sources, rewritten);

  init_glslang();
  // The program must be destroyed before its shaders: declared after them.
  std::vector<std::unique_ptr<glslang::TShader>> shaders;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const EShLanguage lang = language(sources[i].stage);
    auto shader = std::make_unique<glslang::TShader>(lang);
    const char* text = rewritten[i].text.c_str();
    const int length = static_cast<int>(rewritten[i].text.size());
    const char* name = sources[i].file.c_str();
    shader->setStringsWithLengthsAndNames(&text, &length, &name, 1);
    shader->setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientOpenGL, 100);
    shader->setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
    shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    shader->setAutoMapLocations(true);  // default-block uniforms and in/out need locations
    shader->setAutoMapBindings(true);
    if (!shader->parse(GetDefaultResources(), 450, ECoreProfile, false, false, kMessages))
      add_log_errors(shader->getInfoLog(), sources, sources[i].file, errors);
    shaders.push_back(std::move(shader));
  }
  throw_if_any(errors);
  for (std::size_t i = 0; i < sources.size(); ++i) check_output_vertices(sources[i], *shaders[i], errors);
  throw_if_any(errors);

  // One TProgram per stage links that stage's compilation units. The stages meet in
  // check_links and in one IO mapping over all of them, not in TProgram::link: glslang 12's
  // cross-stage check refuses a TES `patch in` array (it drops the array's dimension as if it
  // were the per-vertex one), which upstream fixed only in 2025.
  std::vector<std::pair<Stage, std::unique_ptr<glslang::TProgram>>> programs;
  for (Stage stage : kPipeline) {
    auto program = std::make_unique<glslang::TProgram>();
    for (std::size_t i = 0; i < sources.size(); ++i)
      if (sources[i].stage == stage) program->addShader(shaders[i].get());
    if (program->getShaders(language(stage)).empty()) continue;
    if (!program->link(kMessages))
      add_log_errors(program->getInfoLog(), sources, first_file(sources, stage), errors);
    programs.emplace_back(stage, std::move(program));
  }
  throw_if_any(errors);
  auto intermediate = [&programs](Stage stage) -> glslang::TIntermediate& {
    for (auto& [s, program] : programs)
      if (s == stage) return *program->getIntermediate(language(stage));
    throw std::logic_error("no such stage");
  };

  std::vector<StageInterface> interfaces;
  for (auto& [stage, program] : programs)
    interfaces.push_back(interface_of(stage, intermediate(stage)));
  if (linking != Linking::SeparatePrograms) check_links(interfaces, errors);
  if (linking == Linking::SeparableProgram) check_separable_blocks(interfaces, sources, rewritten, errors);
  throw_if_any(errors);

  // TProgram::mapIO over several programs. glslang's OpenGL mapper and resolver (which
  // glslangValidator does not use: its default mapper numbers each stage on its own) give an
  // in/out without a location the location that the same name (the block name for a block) has
  // in the adjacent stage, and a uniform the same location in every stage.
  glslang::TDefaultGlslIoResolver resolver(*shaders.front()->getIntermediate());
  glslang::TGlslIoMapper mapper;
  TInfoSink sink;
  bool mapped = true;
  for (auto& [stage, program] : programs)
    mapped = mapped && mapper.addStage(language(stage), intermediate(stage), sink, &resolver);
  if (!mapped || !mapper.doMap(&resolver, sink))
    add_log_errors(sink.info.c_str(), sources, sources.front().file, errors);
  throw_if_any(errors);

  CompiledProgram compiled;
  for (const StageInterface& stage : interfaces) {
    const std::string file = first_file(sources, stage.stage);
    CompiledStage out{stage.stage, legalize(to_spirv(intermediate(stage.stage), file), file), {}};
    for (std::size_t i = 0; i < sources.size(); ++i)
      if (sources[i].stage == stage.stage)
        out.rewrites.insert(out.rewrites.end(), rewritten[i].notes.begin(),
                            rewritten[i].notes.end());
    compiled.stages.push_back(std::move(out));
  }
  return compiled;
}

}  // namespace tessref::shader
