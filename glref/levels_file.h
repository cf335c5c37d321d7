#pragma once
// Level-set files for sweeps: one patch per line, "outer0 outer1 outer2 outer3 inner0 inner1",
// tokens separated by spaces or tabs; nan, inf, -inf allowed. Blank lines and lines starting with
// '#' are skipped.
#include <istream>
#include <string>
#include <vector>

#include "stages/tpg.h"

namespace tessref::glref {

// Throws tessref::InputError naming `source` and the line for a malformed line.
std::vector<TessLevels> read_levels(std::istream& in, const std::string& source);
std::vector<TessLevels> read_levels_file(const std::string& path);  // "-" reads stdin

// One float token: decimal or hex floats, nan, inf, -inf (case-insensitive). False if malformed.
bool parse_level(const std::string& token, float& out);

}  // namespace tessref::glref
