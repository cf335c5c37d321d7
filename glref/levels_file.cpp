#include "glref/levels_file.h"

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/error.h"

namespace tessref::glref {

bool parse_level(const std::string& token, float& out) {
  if (token.empty()) return false;
  errno = 0;
  char* end = nullptr;
  const float v = std::strtof(token.c_str(), &end);
  // ERANGE only flags overflow to inf or underflow: both are legitimate level values here.
  if (end != token.c_str() + token.size()) return false;
  out = v;
  return true;
}

std::vector<TessLevels> read_levels(std::istream& in, const std::string& source) {
  std::vector<TessLevels> out;
  std::string line;
  for (std::size_t line_no = 1; std::getline(in, line); ++line_no) {
    std::istringstream ss(line);
    std::vector<std::string> tokens;
    for (std::string t; ss >> t;) tokens.push_back(t);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    const std::string where = source + ":" + std::to_string(line_no);
    if (tokens.size() != 6)
      throw InputError(where + ": expected 6 levels (outer0 outer1 outer2 outer3 inner0 inner1), got " +
                       std::to_string(tokens.size()));
    TessLevels l;
    float* dst[6] = {&l.outer[0], &l.outer[1], &l.outer[2], &l.outer[3], &l.inner[0], &l.inner[1]};
    for (int i = 0; i < 6; ++i)
      if (!parse_level(tokens[i], *dst[i])) throw InputError(where + ": not a number: '" + tokens[i] + "'");
    out.push_back(l);
  }
  if (in.bad()) throw InputError(source + ": read error");
  return out;
}

std::vector<TessLevels> read_levels_file(const std::string& path) {
  if (path == "-") return read_levels(std::cin, "<stdin>");
  std::ifstream in(path);
  if (!in) throw InputError("cannot open levels file " + path);
  return read_levels(in, path);
}

}  // namespace tessref::glref
