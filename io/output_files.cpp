#include "io/output_files.h"

#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <system_error>

#include "common/error.h"

namespace tessref {
namespace {

namespace fs = std::filesystem;

fs::path folder_of(const fs::path& target) {
  const fs::path parent = target.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

// What decides "the same file": the absolute, lexically normal path with its folder resolved
// (links in the folder followed; the file itself need not exist yet).
fs::path identity_of(const fs::path& target) {
  std::error_code ec;
  fs::path folder = fs::weakly_canonical(fs::absolute(folder_of(target), ec), ec);
  if (ec) folder = fs::absolute(folder_of(target)).lexically_normal();
  return folder / target.filename();
}

// Temporaries not yet committed, removed at exit too: some image writers (libjpeg's, inside
// OpenImageIO) end the process with exit() on a write error, past every destructor.
std::mutex pending_mutex;
struct Pending {
  std::string temp, target;
};
std::vector<Pending>& pending() {
  static std::vector<Pending> files;
  return files;
}
// Normal exits find the list empty (OutputFiles removed or committed its files); a library that
// called exit() mid-write leaves entries: remove them and exit with the bad-output status, 2.
void remove_pending() {
  std::lock_guard lock(pending_mutex);
  if (pending().empty()) return;
  for (const Pending& f : pending()) {
    std::remove(f.temp.c_str());
    std::fprintf(stderr,
                 "tessref: error: %s: the image library failed writing it (disk full or file size "
                 "limit?); nothing was written\n",
                 f.target.c_str());
  }
  pending().clear();
  std::fflush(stderr);
  _exit(2);
}
// The same list for SIGINT and SIGTERM, in a form a signal handler may read: fixed buffers, set
// before the slot count is published.
constexpr int kSignalSlots = 16;
char signal_paths[kSignalSlots][4096];
volatile std::sig_atomic_t signal_count = 0;

extern "C" void remove_on_signal(int sig) {
  for (int i = 0; i < signal_count; ++i)
    if (signal_paths[i][0]) unlink(signal_paths[i]);
  static const char msg[] = "\ntessref: interrupted; unfinished output files removed\n";
  [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, msg, sizeof msg - 1);
  _exit(128 + sig);
}

void track_for_signals(const fs::path& temp) {
  static const bool installed = [] {
    std::signal(SIGINT, remove_on_signal);
    std::signal(SIGTERM, remove_on_signal);
    return true;
  }();
  (void)installed;
  const std::string s = temp.string();
  if (signal_count >= kSignalSlots || s.size() >= sizeof signal_paths[0]) return;
  std::memcpy(signal_paths[signal_count], s.c_str(), s.size() + 1);
  signal_count = signal_count + 1;
}

void untrack_for_signals(const fs::path& temp) {
  const std::string s = temp.string();
  for (int i = 0; i < signal_count; ++i)
    if (s == signal_paths[i]) signal_paths[i][0] = '\0';
}

void track(const fs::path& temp, const fs::path& target) {
  track_for_signals(temp);
  // pending() first: objects built before atexit() is called are destroyed after the handler ran.
  static const bool registered = (pending(), std::atexit(remove_pending), true);
  (void)registered;
  std::lock_guard lock(pending_mutex);
  pending().push_back(Pending{temp.string(), target.string()});
}
void untrack(const fs::path& temp) {
  untrack_for_signals(temp);
  std::lock_guard lock(pending_mutex);
  auto& p = pending();
  for (auto it = p.begin(); it != p.end(); ++it)
    if (it->temp == temp.string()) {
      p.erase(it);
      return;
    }
}

// Temporaries of `target` (".STEM.tessref-PID-N.EXT" in its folder) whose process is gone: a run
// killed with SIGKILL (or a machine that went down) had no chance to remove them. Those of live
// processes are left alone: another run may be writing the same file right now.
void remove_stale_temporaries(const fs::path& folder, const fs::path& target, const fs::path& extension) {
  const std::string prefix = "." + target.stem().string() + ".tessref-";
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + extension.string().size() || name.compare(0, prefix.size(), prefix) != 0 ||
        it->path().extension() != extension)
      continue;
    // PID-N between the prefix and the extension, digits only.
    const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - extension.string().size());
    const std::size_t dash = middle.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == middle.size() ||
        middle.find_first_not_of("0123456789-") != std::string::npos || middle.find('-', dash + 1) != std::string::npos)
      continue;
    const long pid = std::strtol(middle.substr(0, dash).c_str(), nullptr, 10);
    if (pid <= 0 || pid == long(getpid())) continue;
    if (::kill(pid_t(pid), 0) == 0 || errno == EPERM) continue;  // still running (maybe another user's)
    std::error_code rm;
    if (it->is_regular_file(rm)) fs::remove(it->path(), rm);
  }
}

}  // namespace

OutputFiles::~OutputFiles() {
  for (const Entry& e : entries_) {
    untrack(e.temp);
    if (committed_) continue;
    std::error_code ec;
    fs::remove(e.temp, ec);
  }
}

fs::path OutputFiles::add(const std::string& option, const fs::path& given) {
  const std::string name = given.string();
  if (given.filename().empty() || given.filename() == "." || given.filename() == "..")
    throw InputError(name + ": " + option + " needs a file name, not a folder");
  // A link is followed: the file it names is replaced (the link stays), written whole beside it.
  std::error_code link_ec;
  fs::path target = given;
  if (fs::is_symlink(fs::symlink_status(given, link_ec))) target = fs::weakly_canonical(fs::absolute(given), link_ec);
  const fs::file_status existing = fs::status(target, link_ec);
  if (fs::exists(existing) && !fs::is_regular_file(existing) && !fs::is_directory(existing))
    throw InputError(name + ": " + option + ": " + target.string() +
                     " is not a regular file (a device, pipe or socket): outputs are written whole to a "
                     "temporary file and renamed into place, which such a file cannot take");
  const fs::path folder = folder_of(target);
  std::error_code ec;
  const fs::file_status st = fs::status(folder, ec);
  if (!fs::exists(st))
    throw InputError(name + ": " + option + ": the folder " + folder.string() + " does not exist");
  if (!fs::is_directory(st))
    throw InputError(name + ": " + option + ": " + folder.string() + " is not a folder");
  if (access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(name + ": " + option + ": the folder " + folder.string() +
                     " is not writable (" + std::strerror(errno) + ")");
  if (fs::is_directory(fs::status(target, ec)))
    throw InputError(name + ": " + option + " names a folder, not a file");
  const fs::path identity = identity_of(target);
  for (const Entry& e : entries_)
    if (e.identity == identity)
      throw InputError(name + ": " + option + " and " + e.option +
                       " name the same file; one would overwrite the other");
  // Same folder as the file replaced, the extension of the name given (the image writer picks
  // the format by extension), hidden, and unique to this process.
  std::string temp_name = ".";
  temp_name += target.stem().string();
  temp_name += ".tessref-";
  temp_name += std::to_string(getpid());
  temp_name += '-';
  temp_name += std::to_string(entries_.size());
  temp_name += given.extension().string();
  const fs::path temp = folder / temp_name;
  remove_stale_temporaries(folder, target, given.extension());
  entries_.push_back(Entry{option, target, temp, identity});
  track(temp, target);
  return temp;
}

void OutputFiles::commit() {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    std::error_code ec;
    fs::rename(e.temp, e.target, ec);
    if (ec)
      throw InputError(e.target.string() + ": " + e.option + ": cannot move the finished file into place (" +
                       ec.message() + ")");
  }
  committed_ = true;
}

CreatedFolder::CreatedFolder(const std::filesystem::path& dir, const std::string& what) {
  // The outermost missing folder: the one to remove on failure.
  fs::path missing;
  for (fs::path p = fs::absolute(dir); !p.empty() && !fs::exists(p); p = p.parent_path()) {
    missing = p;
    if (p == p.parent_path()) break;
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create " + what + " (" + ec.message() + ")");
  created_ = missing;
}

CreatedFolder::~CreatedFolder() {
  if (created_.empty()) return;
  std::error_code ec;
  fs::remove_all(created_, ec);
}

void write_text_file(const std::filesystem::path& temp, const std::string& target, const std::string& text) {
  write_binary_file(temp, target, std::as_bytes(std::span(text.data(), text.size())));
}

void write_binary_file(const std::filesystem::path& temp, const std::string& target, std::span<const std::byte> bytes) {
  std::ofstream out(temp, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out.flush()) throw InputError(target + ": cannot write");
}

}  // namespace tessref
