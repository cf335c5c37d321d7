#include "stages/tpg_stream.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <ostream>

namespace tessref {

std::vector<glm::vec3> emitted_stream(const TessDomainPoints& points) {
  std::vector<glm::vec3> stream;
  stream.reserve(points.indices.size());
  for (std::uint32_t i : points.indices) stream.push_back(points.coords[i]);
  return stream;
}

void write_stream(std::ostream& os, TessDomain domain, const std::vector<glm::vec3>& stream,
                  StreamFormat format) {
  const int components = domain == TessDomain::Triangles ? 3 : 2;
  char buf[24];
  for (const glm::vec3& c : stream) {
    for (int k = 0; k < components; ++k) {
      if (format == StreamFormat::Hex)
        std::snprintf(buf, sizeof buf, "%08x", std::bit_cast<std::uint32_t>(c[k]));
      else
        std::snprintf(buf, sizeof buf, "%.9g", double(c[k]));
      if (k) os << ' ';
      os << buf;
    }
    os << '\n';
  }
}

}  // namespace tessref
