#pragma once
// Text formats of captured TPG streams, shared by `tessref-glref tpg` / `tpg-sweep` and tests.
// They match `tessref tpg`: one emitted vertex per line, u v w for triangles, u v otherwise.
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "stages/tpg.h"

namespace tessref::glref {

enum class CoordFormat { Text, Hex };
bool parse(const std::string& s, CoordFormat& out);  // "text" | "hex"

// Components printed per vertex: 3 for triangles, 2 for quads and isolines.
int printed_components(TessDomain domain);

// One line per vertex: "%.9g %.9g[ %.9g]" or the IEEE-754 bits as 8 lowercase hex digits each.
std::string format_stream(TessDomain domain, const std::vector<glm::vec3>& coords, CoordFormat format);

// A dataset line: "<patch index> <vertex count>" then every printed component in hex, all
// separated by single spaces, ending in a newline.
std::string format_sweep_line(TessDomain domain, std::size_t patch, const std::vector<glm::vec3>& coords);
void append_sweep_line(std::string& out, TessDomain domain, std::size_t patch, const std::vector<glm::vec3>& coords);

// The float's bits as 8 lowercase hex digits.
void append_hex(std::string& out, float v);

}  // namespace tessref::glref
