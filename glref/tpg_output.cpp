#include "glref/tpg_output.h"

#include <cstdint>
#include <cstring>
#include <sstream>

#include "stages/tpg_stream.h"

namespace tessref::glref {

bool parse(const std::string& s, CoordFormat& out) {
  if (s == "text") return out = CoordFormat::Text, true;
  if (s == "hex") return out = CoordFormat::Hex, true;
  return false;
}

int printed_components(TessDomain domain) { return domain == TessDomain::Triangles ? 3 : 2; }

void append_hex(std::string& out, float v) {
  static const char digits[] = "0123456789abcdef";
  std::uint32_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  char buf[8];
  for (int i = 7; i >= 0; --i, bits >>= 4) buf[i] = digits[bits & 15u];
  out.append(buf, 8);
}

std::string format_stream(TessDomain domain, const std::vector<glm::vec3>& coords, CoordFormat format) {
  // The same writer as `tessref tpg`, so the two programs' outputs agree by construction.
  std::ostringstream out;
  write_stream(out, domain, coords, format == CoordFormat::Hex ? StreamFormat::Hex : StreamFormat::Text);
  return out.str();
}

void append_sweep_line(std::string& out, TessDomain domain, std::size_t patch, const std::vector<glm::vec3>& coords) {
  const int n = printed_components(domain);
  out += std::to_string(patch);
  out += ' ';
  out += std::to_string(coords.size());
  out.reserve(out.size() + coords.size() * n * 9 + 1);
  for (const glm::vec3& c : coords)
    for (int k = 0; k < n; ++k) {
      out += ' ';
      append_hex(out, c[k]);
    }
  out += '\n';
}

std::string format_sweep_line(TessDomain domain, std::size_t patch, const std::vector<glm::vec3>& coords) {
  std::string out;
  append_sweep_line(out, domain, patch, coords);
  return out;
}

}  // namespace tessref::glref
