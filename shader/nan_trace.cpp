#include "shader/nan_trace.h"

#include <spirv/unified1/GLSL.std.450.h>
#include <spirv/unified1/spirv.hpp>

#include "shader/opcode_names.h"

namespace tessref::shader {
namespace {

thread_local NanTrace* tl_trace = nullptr;

// The GLSL.std.450 instructions that can turn finite operands into NaN or infinity.
const char* ext_name(std::uint32_t n) {
  switch (n) {
    case GLSLstd450Sqrt: return "Sqrt";
    case GLSLstd450InverseSqrt: return "InverseSqrt";
    case GLSLstd450Normalize: return "Normalize";
    case GLSLstd450Pow: return "Pow";
    case GLSLstd450Log: return "Log";
    case GLSLstd450Log2: return "Log2";
    case GLSLstd450Exp: return "Exp";
    case GLSLstd450Exp2: return "Exp2";
    case GLSLstd450Asin: return "Asin";
    case GLSLstd450Acos: return "Acos";
    case GLSLstd450Atan2: return "Atan2";
    case GLSLstd450Tan: return "Tan";
    case GLSLstd450Length: return "Length";
    case GLSLstd450Distance: return "Distance";
    case GLSLstd450Cross: return "Cross";
    case GLSLstd450Reflect: return "Reflect";
    case GLSLstd450Refract: return "Refract";
    case GLSLstd450FMix: return "FMix";
    case GLSLstd450Fma: return "Fma";
    case GLSLstd450Acosh: return "Acosh";
    case GLSLstd450Atanh: return "Atanh";
    case GLSLstd450Sinh: return "Sinh";
    case GLSLstd450Cosh: return "Cosh";
    case GLSLstd450Ldexp: return "Ldexp";
    case GLSLstd450MatrixInverse: return "MatrixInverse";
    case GLSLstd450SmoothStep: return "SmoothStep";
    default: return nullptr;
  }
}

}  // namespace

std::string NanTrace::instruction() const {
  const char* op = opcode_name(spv);
  std::string s = op ? op : "SPIR-V opcode " + std::to_string(spv);
  if (spv == spv::OpExtInst) {
    const char* e = ext_name(ext);
    s += std::string(" ") + (e ? e : "GLSL.std.450 #" + std::to_string(ext));
  }
  return s;
}

NanTraceScope::NanTraceScope(NanTrace& trace) : previous_(tl_trace) { tl_trace = &trace; }
NanTraceScope::~NanTraceScope() { tl_trace = previous_; }

NanTrace* current_nan_trace() { return tl_trace; }

}  // namespace tessref::shader
