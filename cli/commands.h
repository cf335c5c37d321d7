#pragma once
// Subcommand registration. Each add_*_command registers its options and a callback that runs
// the command; callbacks throw InputError for bad input and set the exit code for other failures.
#include <CLI/CLI.hpp>

namespace tessref::cli {

void add_render_command(CLI::App& app);  // cli/render_command.cpp
void add_tpg_command(CLI::App& app);     // cli/tpg_command.cpp
void add_shader_test_command(CLI::App& app);  // cli/shader_test_command.cpp

// Exit status set by a command callback (0 unless it failed without throwing).
int exit_code();
void set_exit_code(int code);

}  // namespace tessref::cli
