// tessref: the command-line front end. Each subcommand lives in its own file.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <new>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/error.h"
#include "common/malloc_tuning.h"
#include "common/memory_budget.h"

int main(int argc, char** argv) {
  // Every command draws (render --repeat and verify redraw frames; capture runs llvmpipe too).
  tessref::keep_draw_buffers_off_mmap();
  CLI::App app{"tessref: a CPU reference of the OpenGL 4.x tessellation pipeline"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tessref ") + TESSREF_VERSION);
  // Options of tessref itself (--max-memory) may come after the command's name too; subcommands
  // take this setting when they are made, so it comes first.
  app.fallthrough();
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
  tessref::cli::add_import_command(app);

  // The memory budget holds for every command; it is set once the command line is read, before
  // the command runs. Below 256 MiB the libraries tessref loads (OpenImageIO's codecs alone map
  // about 100 MiB) cannot run; some of them (x265, through HEIF) hang when a thread's stack
  // cannot be mapped, so such a budget is refused.
  const std::uint64_t machine = tessref::machine_memory_bytes();
  std::uint64_t budget = tessref::default_memory_budget();
  app.add_option("--max-memory", budget,
                 "The most memory this run may use (e.g. 2G, 512M; 0: no bound); past it, the "
                 "command stops with an error. Default: 3/4 of this machine's memory (" +
                     tessref::format_bytes(machine) + " here)")
      ->envname("TESSREF_MAX_MEMORY")
      ->transform(CLI::AsSizeValue(false))
      ->check([](const std::string& value) -> std::string {
        const std::uint64_t bytes = std::stoull(value);
        if (bytes != 0 && bytes < tessref::kMinMemoryBudget)
          return "a budget under " + tessref::format_bytes(tessref::kMinMemoryBudget) +
                 " cannot load tessref's libraries; give at least that, or 0 for no bound";
        return {};
      })
      ->option_text("SIZE");
  app.parse_complete_callback([&] {
    if (!tessref::set_memory_budget(budget) && budget != 0 && app.count("--max-memory"))
      std::fprintf(stderr, "tessref: warning: --max-memory is not enforced in this build "
                           "(AddressSanitizer maps its own memory)\n");
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const tessref::InputError& e) {
    std::fprintf(stderr, "tessref: error: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    // Too large a scene, image or shader for the budget (or the machine): the input's size, not a
    // bug, so exit 2 as for other bad input.
    const std::uint64_t set = tessref::memory_budget();
    if (set)
      std::fprintf(stderr, "tessref: error: out of memory: this run needed more than its memory budget "
                   "of %s (--max-memory SIZE or TESSREF_MAX_MEMORY; the default is 3/4 of this "
                   "machine's %s)\n", tessref::format_bytes(set).c_str(), tessref::format_bytes(machine).c_str());
    else
      std::fprintf(stderr, "tessref: error: out of memory: this run needed more memory than the machine "
                   "could give\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessref: internal error: %s\n", e.what());
    return 3;
  }
  return tessref::cli::exit_code();
}
