#pragma once
// Runs piglit's .shader_test files (parsed by shader_test_file.h) on tessref's CPU pipeline with
// the file's own GLSL on the executor: `tessref shader-test`.
#include <string>

#include "common/parallel.h"
#include "piglit/shader_test_file.h"
#include "shader/executor.h"

namespace tessref {

enum class Verdict { Pass, Fail, Skip };

struct ShaderTestResult {
  Verdict verdict = Verdict::Pass;
  std::string reason;  // Fail: "LINE: what failed"; Skip: the requirement tessref does not meet
};

struct ShaderTestOptions {
  shader::ExecLimits limits;
};

// Runs one parsed file. Never throws for anything the file does: compile, link and run-time
// errors are failures with their messages, unmet requirements are skips.
ShaderTestResult run_shader_test(const ShaderTestFile& file, const Parallel& parallel,
                                 const ShaderTestOptions& options = {});

const char* to_string(Verdict v);

}  // namespace tessref
