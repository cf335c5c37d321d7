// tessref: the command-line front end. Each subcommand lives in its own file.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/error.h"

int main(int argc, char** argv) {
  CLI::App app{"tessref: a CPU reference of the OpenGL 4.x tessellation pipeline"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tessref ") + TESSREF_VERSION);
  tessref::cli::add_render_command(app);
  tessref::cli::add_tpg_command(app);
  tessref::cli::add_shader_test_command(app);
  tessref::cli::add_scene_command(app);
  tessref::cli::add_diff_command(app);
  tessref::cli::add_capture_command(app, argc, argv);
  tessref::cli::add_verify_command(app);
  tessref::cli::add_compare_tessellators_command(app);
  tessref::cli::add_inspect_command(app);
  tessref::cli::add_stats_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const tessref::InputError& e) {
    std::fprintf(stderr, "tessref: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessref: internal error: %s\n", e.what());
    return 3;
  }
  return tessref::cli::exit_code();
}
