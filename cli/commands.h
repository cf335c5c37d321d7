#pragma once
// Subcommand registration. Each add_*_command registers its options and a callback that runs
// the command; callbacks throw InputError for bad input and set the exit code for other failures.
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace tessref::cli {

void add_render_command(CLI::App& app);  // cli/render_command.cpp
void add_tpg_command(CLI::App& app);     // cli/tpg_command.cpp
void add_shader_test_command(CLI::App& app);  // cli/shader_test_command.cpp
void add_scene_command(CLI::App& app);   // cli/scene_command.cpp
void add_diff_command(CLI::App& app);    // cli/diff_command.cpp
void add_verify_command(CLI::App& app);  // cli/verify_command.cpp
void add_compare_tessellators_command(CLI::App& app);  // cli/compare_tessellators_command.cpp
void add_inspect_command(CLI::App& app);  // cli/inspect_command.cpp
void add_stats_command(CLI::App& app);    // cli/stats_command.cpp
void add_import_command(CLI::App& app);   // cli/import_command.cpp
// The command line is stored in the capture's manifest.
void add_capture_command(CLI::App& app, int argc, char** argv);  // cli/capture_command.cpp

// Every scene key with what it allows and its default, one per line (render --help, scene --keys).
std::string scene_keys_text();

// Checks that an option's value is an integer before a range check runs (CLI11's Range would call
// a word "not in range"): "expected an integer, got 'abc'".
inline const CLI::Validator kInteger(
    [](std::string& s) -> std::string {
      std::size_t used = 0;
      try {
        (void)std::stoll(s, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      return used != 0 && used == s.size() ? std::string() : "expected an integer, got '" + s + "'";
    },
    "INTEGER");

// The scene a command reads: the positional SCENE (none: the built-in default scene) and the
// repeatable --set KEY=VALUE overrides.
inline void add_scene_options(CLI::App* cmd, std::string& scene, std::vector<std::string>& sets) {
  cmd->add_option("scene", scene, "scene file (see README.md); without one, the built-in default scene");
  cmd->add_option("--set", sets, "override a scene value, KEY=VALUE (e.g. camera.eye=2,5,-10); repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

// Exit status set by a command callback (0 unless it failed without throwing).
int exit_code();
void set_exit_code(int code);

}  // namespace tessref::cli
