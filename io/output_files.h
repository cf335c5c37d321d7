#pragma once
// The files one command writes, written all or none. Each output goes to a temporary file in its
// target's folder (so the final rename is atomic and a failed or interrupted run leaves no
// half-written file under the target's name); only when every output has been written and checked
// are they renamed into place. Paths are checked before any work starts.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "common/error.h"

namespace tessref {

class OutputFiles {
 public:
  OutputFiles() = default;
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();  // removes the temporaries of a set that was not committed

  // Registers an output; `option` names it in messages ("-o", "--depth"). A symbolic link is
  // followed (the file it names is replaced, the link stays). InputError when the folder does not
  // exist, is not a folder or is not writable, when the file is a device, pipe or socket (such as
  // a link to /dev/full), or when an earlier output names the same file. Returns the temporary
  // path to write to (the file's folder, the given name's extension).
  std::filesystem::path add(const std::string& option, const std::filesystem::path& target);

  // Renames every temporary onto its target, in the order added. InputError if one fails (the
  // ones not yet renamed are removed).
  void commit();

 private:
  struct Entry {
    std::string option;
    std::filesystem::path target, temp, identity;
  };
  std::vector<Entry> entries_;
  bool committed_ = false;
};

// Runs a write to `temp` (a path OutputFiles::add returned) and names `target` instead of the
// temporary in any InputError it throws: users know the file they asked for, not its hidden twin.
template <class Write>
void write_as(const std::filesystem::path& temp, const std::filesystem::path& target, Write&& write) {
  try {
    write();
  } catch (const InputError& e) {
    std::string message = e.what();
    const std::string from = temp.string(), to = target.string();
    for (std::size_t at; (at = message.find(from)) != std::string::npos;) message.replace(at, from.size(), to);
    throw InputError(message);
  }
}

// A folder a command creates for its outputs (capture --out, verify --html): removed again, with
// whatever is in it, unless keep() is called, so that a failed run leaves no empty folder behind.
// A folder that already existed is left alone.
class CreatedFolder {
 public:
  // Creates `dir` and its missing parents; InputError naming `what` when it cannot.
  CreatedFolder(const std::filesystem::path& dir, const std::string& what);
  CreatedFolder(const CreatedFolder&) = delete;
  CreatedFolder& operator=(const CreatedFolder&) = delete;
  ~CreatedFolder();
  void keep() { created_.clear(); }

 private:
  std::filesystem::path created_;  // the outermost folder this created; empty: none
};

// Writes `text` into `temp` (a path OutputFiles::add returned). InputError naming `target` when
// the write fails (a full disk).
void write_text_file(const std::filesystem::path& temp, const std::string& target, const std::string& text);
// The same for raw bytes.
void write_binary_file(const std::filesystem::path& temp, const std::string& target, std::span<const std::byte> bytes);

}  // namespace tessref
