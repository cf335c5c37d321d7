#pragma once
// Helpers shared by the pipeline tests.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mesh/camera.h"
#include "mesh/mesh_source.h"
#include "scene/scene_loader.h"

namespace tessref::test {

// A fresh folder under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("tessref_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::filesystem::path p = path_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

 private:
  std::filesystem::path path_;
};

// The tessref binary of this build, and one run of it: exit status and stdout + stderr.
inline const std::string kBinary = std::string(TESSREF_BINARY_DIR) + "/cli/tessref";

struct CliRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Any shell command: exit status and stdout + stderr.
inline CliRun run_command(const std::string& command) {
  CliRun r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

inline CliRun run_cli(const std::string& args) { return run_command(kBinary + " " + args); }

// Whether this machine lets an unprivileged process mount a file system in a user namespace (the
// small or full file systems below need it).
inline bool can_mount_small_file_systems() { return std::system("unshare -rm true >/dev/null 2>&1") == 0; }

// Runs the shell command `script` with a fresh tmpfs of `size` (as mount's size=, e.g. "2m") on
// `mnt`, in a user and mount namespace, so that nothing outside sees it: exit status and output.
// The tmpfs disappears with the namespace; print what the test needs from it inside `script`.
inline CliRun run_on_small_file_system(const std::filesystem::path& mnt, const std::string& size,
                                       const std::string& script) {
  const std::string whole = "mount -t tmpfs -o size=" + size + " tmpfs '" + mnt.string() + "' && " + script;
  std::string quoted;  // for sh -c '...'
  for (char c : whole) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return run_command("unshare -rm sh -c '" + quoted + "'");
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The default scene with --set overrides, its mesh built and its camera fitted, as render and
// inspect prepare them.
struct LoadedScene {
  Scene scene;
  Mesh mesh;
};
inline LoadedScene load_default_scene(const std::vector<std::string>& sets) {
  LoadedScene l{load_scene("", sets), {}};
  std::vector<std::string> warnings;
  l.mesh = build_mesh(l.scene.mesh, warnings);
  l.scene.camera = fitted_camera(l.scene, l.mesh);
  return l;
}

}  // namespace tessref::test
