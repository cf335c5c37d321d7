#include "render/storage_files.h"

#include <algorithm>
#include <cctype>

namespace tessref {

std::string memory_file_name(const std::string& prefix, std::string name) {
  std::replace_if(name.begin(), name.end(), [](char c) {
    return !std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.';
  }, '_');
  return prefix + '.' + name + ".bin";
}

std::vector<std::pair<std::size_t, std::string>> storage_buffer_files(const Scene& scene, const std::string& prefix) {
  std::vector<bool> bound(scene.buffers.size(), false);
  for (const DrawSetting& d : scene.draws)
    for (const UniformBufferSetting& u : d.storage_buffers) bound.at(u.buffer) = true;
  std::vector<std::pair<std::size_t, std::string>> files;
  for (std::size_t b = 0; b < scene.buffers.size(); ++b)
    if (bound[b]) files.emplace_back(b, memory_file_name(prefix, scene.buffers[b].name));
  return files;
}

}  // namespace tessref
