// `tessref import CAPTURE --out DIR [--event N]`: an application's frame capture as a scene of
// draws (docs/replay.md). The importers are Python scripts installed with tessref (replay/): the
// apitrace one reads `apitrace pickle`'s stream, the RenderDoc one its python module, which Debian
// builds for /usr/bin/python3 only. This command finds the scripts and runs them; their exit
// status (2: the capture cannot be imported, nothing written) is the command's.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/shard.h"
#include "common/error.h"

namespace tessref::cli {
namespace {

struct ImportArgs {
  std::string capture, out, shard;
  long long event = -1;
  double timeout = 600;
  bool quiet = false;
};

bool is_file(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_regular_file(p, ec);
}

// TESSREF_REPLAY_DIR, else beside the installed binary (share/tessref/replay), else the
// source tree this binary was built from.
std::filesystem::path find_importer() {
  const char* script = "tessref_import.py";
  if (const char* env = std::getenv("TESSREF_REPLAY_DIR"); env && *env) {
    const std::filesystem::path p = std::filesystem::path(env) / script;
    if (!is_file(p)) throw InputError(std::string("TESSREF_REPLAY_DIR is ") + env + ", which holds no " + script);
    return p;
  }
  std::vector<std::filesystem::path> tried;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) tried.push_back((exe.parent_path() / TESSREF_REPLAY_EXE_RELATIVE / script).lexically_normal());
  tried.push_back(std::filesystem::path(TESSREF_REPLAY_SOURCE_DIR) / script);
  for (const auto& p : tried)
    if (is_file(p)) return p;
  std::string list;
  for (const auto& p : tried) list += (list.empty() ? "" : ", ") + p.string();
  throw InputError("cannot find the capture importer (tried " + list + "); set TESSREF_REPLAY_DIR to its folder");
}

// The importer's hidden staging folders beside DIR (.DIR.partial-*), left when it was killed.
void remove_staging(const std::string& out) {
  const std::filesystem::path dir = std::filesystem::absolute(out);
  const std::string prefix = "." + dir.filename().string() + ".partial-";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir.parent_path(), ec))
    if (entry.path().filename().string().rfind(prefix, 0) == 0) std::filesystem::remove_all(entry.path(), ec);
}

// One run of the importer: its exit status, or -signal when a signal ended it (its staging
// folder removed).
int run_importer(const ImportArgs& a) {
  // Debian's python3: the RenderDoc module is built for it alone.
  const std::string python = is_file("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string script = find_importer().string();
  std::vector<std::string> argv = {python, script, a.capture, "--out", a.out};
  if (a.event >= 0) argv.insert(argv.end(), {"--event", std::to_string(a.event)});
  if (a.quiet) argv.push_back("--quiet");
  std::vector<char*> c_argv;
  for (std::string& s : argv) c_argv.push_back(s.data());
  c_argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw InputError(std::string("tessref import: cannot start python3: ") + std::strerror(errno));
  if (pid == 0) {
    setpgid(0, 0);  // its own group: --timeout stops it with apitrace and eglretrace under it
    execvp(c_argv[0], c_argv.data());
    std::fprintf(stderr, "tessref import: error: cannot run %s: %s (install Debian's python3)\n", c_argv[0],
                 std::strerror(errno));
    _exit(2);
  }
  setpgid(pid, pid);
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  bool stopped = false;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) throw InputError(std::string("tessref import: waitpid: ") + std::strerror(errno));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!stopped && seconds > a.timeout) {
      // A damaged capture can make RenderDoc's replay (or a retrace) run a draw of billions of
      // vertices. SIGTERM lets the importer remove what it wrote; SIGKILL follows if it is stuck
      // in native code, and the staging folder is removed here.
      kill(-pid, SIGTERM);
      for (int i = 0; i < 30 && waitpid(pid, &status, WNOHANG) == 0; ++i) usleep(100000);
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      remove_staging(a.out);
      std::fprintf(stderr,
                   "tessref import: error: %s: reading it took more than %g s (--timeout), so it was stopped; a damaged "
                   "capture can hold a draw the replay cannot finish; nothing was written\n",
                   a.capture.c_str(), a.timeout);
      return 2;
    }
    usleep(20000);
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  remove_staging(a.out);
  return -WTERMSIG(status);
}

int run_import(const ImportArgs& a) {
  // RenderDoc's module reads an .rdc in the importer's process, and a damaged capture can crash
  // it there (seen: SIGSEGV on a few changed bytes). It also crashed, rarely, on sound captures
  // that import every other time, so a crash is tried once more before it is reported.
  int status = run_importer(a);
  if (status < 0) status = run_importer(a);
  if (status >= 0) return status;
  std::fprintf(stderr,
               "tessref import: error: %s: the importer died of signal %d (%s) while reading it; RenderDoc's reader "
               "crashes so on a damaged capture (it crashed twice); nothing was written\n",
               a.capture.c_str(), -status, strsignal(-status));
  return 2;
}

// A folder of captures: each *.trace and *.rdc (name-sorted, those of the shard) into OUT/<stem>/.
int run_import_folder(const ImportArgs& a) {
  if (a.event >= 0) throw InputError("--event names a draw of one capture, not of a folder of captures");
  const Shard shard = a.shard.empty() ? Shard{} : parse_shard(a.shard);
  std::vector<std::filesystem::path> captures;
  for (const auto& entry : std::filesystem::directory_iterator(a.capture)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".trace" || ext == ".rdc")) captures.push_back(entry.path());
  }
  std::sort(captures.begin(), captures.end());
  if (captures.empty()) throw InputError(a.capture + ": no .trace or .rdc captures in the folder");
  std::filesystem::create_directories(a.out);
  int imported = 0, taken = 0;
  std::vector<std::string> stems;
  for (std::size_t i = 0; i < captures.size(); ++i) {
    const std::string stem = captures[i].stem().string();
    if (std::find(stems.begin(), stems.end(), stem) != stems.end())
      throw InputError(a.capture + ": two captures are named " + stem + " (.trace and .rdc): their folders would meet");
    stems.push_back(stem);
    if (!shard.holds(i)) continue;
    ++taken;
    ImportArgs one = a;
    one.capture = captures[i].string();
    one.out = (std::filesystem::path(a.out) / stem).string();
    one.quiet = true;
    if (run_import(one) == 0)
      ++imported;
    else
      std::fprintf(stderr, "tessref import: %s not imported (the reason is above)\n", one.capture.c_str());
  }
  std::printf("tessref import: %d of %d captures imported into %s (shard %d/%d of %zu captures)\n", imported, taken,
              a.out.c_str(), shard.index, shard.count, captures.size());
  return imported == taken ? 0 : 2;
}

}  // namespace

void add_import_command(CLI::App& app) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "import",
      "Turn a frame capture (an apitrace .trace or a RenderDoc .rdc) into a scene of draws: DIR/scene.json with its buffers, shaders "
      "and textures, DIR/gpu.png (the driver's image after the draw) and DIR/report.txt (what could not be "
      "carried). Exit 2, leaving no DIR, for a capture that cannot be imported (docs/replay.md)");
  cmd->add_option("capture", args->capture, "the capture file, or a folder of them (each into OUT/<stem>/)")->required();
  cmd->add_option("--out", args->out, "the folder to create (it must not exist, or be empty)")->required();
  cmd->add_option("--event", args->event,
                  "the draw: an apitrace call number or a RenderDoc event id (default: the last GL_PATCHES draw of "
                  "the capture's last frame)")
      ->check(kInteger)
      ->check(CLI::Range(0LL, (1LL << 53)));
  cmd->add_flag("--quiet", args->quiet, "no progress line");
  cmd->add_option("--timeout", args->timeout,
                  "seconds after which reading a capture is stopped (exit 2, nothing written): a damaged capture can "
                  "hold a draw its replay never finishes")
      ->check(CLI::Range(1.0, 1e7))
      ->capture_default_str();
  cmd->add_option("--shard", args->shard,
                  "with a folder of captures: shard I/N of its name-sorted .trace and .rdc files (or auto, as verify's)");
  cmd->callback([args] {
    std::error_code ec;
    if (std::filesystem::is_directory(args->capture, ec)) return set_exit_code(run_import_folder(*args));
    if (!args->shard.empty()) throw InputError("--shard takes a folder of captures");
    set_exit_code(run_import(*args));
  });
}

}  // namespace tessref::cli
