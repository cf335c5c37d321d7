#include "render/buffer_load.h"

#include <cstring>
#include <fstream>
#include <iterator>

#include "common/error.h"

namespace tessref {

const BufferSetting& find_buffer(const Scene& scene, const std::string& name, const std::string& key) {
  std::string names;
  for (const BufferSetting& b : scene.buffers) {
    if (b.name == name) return b;
    names += (names.empty() ? "" : ", ") + b.name;
  }
  throw InputError(key + ": no buffer named \"" + name + "\" (buffers: " + (names.empty() ? "none" : names) + ")");
}

draw::Buffer load_buffer(const std::string& source, const BufferSetting& b) {
  draw::Buffer buffer{b.name, b.data};
  if (b.file.empty()) return buffer;
  std::ifstream in(b.file, std::ios::binary);
  if (!in) throw InputError(source + ": buffers." + b.name + ".file: cannot read '" + b.file.string() + "'");
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(source + ": buffers." + b.name + ".file: error reading '" + b.file.string() + "'");
  buffer.bytes.resize(bytes.size());
  std::memcpy(buffer.bytes.data(), bytes.data(), bytes.size());
  return buffer;
}

std::vector<draw::Buffer> load_buffers(const Scene& scene) {
  std::vector<draw::Buffer> out;
  for (const BufferSetting& b : scene.buffers) out.push_back(load_buffer(scene.source, b));
  return out;
}

}  // namespace tessref
