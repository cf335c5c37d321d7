#include "cli/scene_name.h"

namespace tessref::cli {

std::string scene_label(const std::string& source, const std::vector<std::string>& sets) {
  std::string keys;
  for (const std::string& set : sets) keys += (keys.empty() ? "" : ", ") + set.substr(0, set.find('='));
  return keys.empty() ? source : source + " with --set " + keys;
}

std::string shell_word(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                        "0123456789_./=,:+-@%") == std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string scene_arguments(const std::string& scene_file, const std::vector<std::string>& sets) {
  std::string args = scene_file.empty() ? "" : shell_word(scene_file) + " ";
  for (const std::string& set : sets) args += "--set " + shell_word(set) + " ";
  return args;
}

}  // namespace tessref::cli
