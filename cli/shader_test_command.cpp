// `tessref shader-test FILE...`: piglit's .shader_test files on the CPU pipeline, one verdict line
// per file and a closing "N passed, M failed, K skipped" line; exit 1 when any failed, 2 when a
// file is missing (before any runs).
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "common/error.h"
#include "piglit/shader_test_runner.h"

namespace tessref::cli {
namespace {

struct ShaderTestArgs {
  std::vector<std::string> files;
  int threads = 0;
  std::uint64_t max_instructions = shader::ExecLimits{}.max_instructions;
  int batch_lanes = shader::ExecLimits{}.batch_lanes;
};

// A file that is not there is bad input (exit 2), not a failed test: every file is checked before
// any runs, so a typo in the list does not hide among the verdicts. A file that is there but does
// not parse still fails, as piglit fails it.
void check_files_exist(const std::vector<std::string>& files) {
  for (const std::string& path : files) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) throw InputError(path + ": no such .shader_test file");
    if (!std::filesystem::is_regular_file(status)) throw InputError(path + ": not a regular file, not a .shader_test file");
  }
}

void run(const ShaderTestArgs& a) {
  check_files_exist(a.files);
  const Parallel parallel(a.threads);
  ShaderTestOptions options;
  options.limits.max_instructions = a.max_instructions;
  options.limits.batch_lanes = a.batch_lanes;
  int passed = 0, failed = 0, skipped = 0;
  for (const std::string& path : a.files) {
    ShaderTestResult r;
    try {
      r = run_shader_test(load_shader_test(path), parallel, options);
    } catch (const InputError& e) {
      r = {Verdict::Fail, e.what()};
    }
    (r.verdict == Verdict::Pass ? passed : r.verdict == Verdict::Fail ? failed : skipped)++;
    std::string line = std::string(to_string(r.verdict)) + ": " + path;
    if (!r.reason.empty()) line += ": " + r.reason;
    // Multi-line reasons (compiler output) stay on one verdict line per file.
    for (char& ch : line)
      if (ch == '\n') ch = ' ';
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }
  std::printf("%d passed, %d failed, %d skipped\n", passed, failed, skipped);
  if (failed > 0) set_exit_code(1);
}

}  // namespace

void add_shader_test_command(CLI::App& app) {
  auto args = std::make_shared<ShaderTestArgs>();
  CLI::App* cmd = app.add_subcommand(
      "shader-test", "Run piglit .shader_test files on the CPU pipeline (the files' own GLSL on tessref's executor)");
  cmd->add_option("files", args->files, "piglit .shader_test files")->required();
  cmd->add_option("--threads", args->threads, "worker threads (0: all hardware threads)")->check(kInteger)->check(CLI::Range(0, 1024));
  cmd->add_option("--max-shader-instructions", args->max_instructions,
                  "instructions one shader invocation may run before it is stopped as a runaway")
      ->check(kInteger)
      ->check(CLI::Range(std::uint64_t(1), std::uint64_t(1) << 50));
  cmd->add_option("--batch-lanes", args->batch_lanes,
                  "shader invocations per executor batch (results do not depend on it)")
      ->check(kInteger)
      ->check(CLI::Range(1, shader::kMaxLanes));
  cmd->callback([args] { run(*args); });
}

}  // namespace tessref::cli
