#pragma once
// render --dump-tess's text dump read back, and inspect's JSON points held against it bit for bit.
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_util.h"

namespace tessref::test {

// One line of the text dump, with its gl_TessCoord words kept as printed (they read back exactly).
struct DumpLine {
  std::string u, v, w;
  float f[9];  // u v w px py pz nx ny nz
};

// The text dump of a render (sets: the scene and options after "render"), grouped by patch id.
inline std::map<int, std::vector<DumpLine>> render_dump(const TempDir& dir, const std::string& sets) {
  const auto dump = dir.path() / "dump.txt";
  const CliRun r = run_cli("render -o " + (dir.path() / "x.png").string() + " --dump-tess " + dump.string() + sets);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::map<int, std::vector<DumpLine>> out;
  std::istringstream in(test::read_file(dump));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    int patch = 0;
    DumpLine d;
    words >> patch >> d.u >> d.v >> d.w;
    d.f[0] = std::strtof(d.u.c_str(), nullptr);
    d.f[1] = std::strtof(d.v.c_str(), nullptr);
    d.f[2] = std::strtof(d.w.c_str(), nullptr);
    for (int i = 3; i < 9; ++i) {
      std::string word;
      words >> word;
      d.f[i] = std::strtof(word.c_str(), nullptr);
    }
    out[patch].push_back(d);
  }
  return out;
}

inline nlohmann::json inspect_json(const TempDir& dir, const std::string& args) {
  const auto file = dir.path() / "inspect.json";
  const CliRun r = run_cli("inspect " + args + " --json " + file.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return nlohmann::json::parse(test::read_file(file));
}

inline std::uint32_t bits(const nlohmann::json& number) { return std::bit_cast<std::uint32_t>(float(number.get<double>())); }

// A point of inspect's JSON against a dump line: gl_TessCoord, world position and normal, bit for bit.
inline void expect_same_bits(const nlohmann::json& point, const DumpLine& d, const std::string& where) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(bits(point["gl_TessCoord"][c]), std::bit_cast<std::uint32_t>(d.f[c])) << where << " coord " << c;
    EXPECT_EQ(bits(point["world_position"][c]), std::bit_cast<std::uint32_t>(d.f[3 + c])) << where << " position " << c;
    EXPECT_EQ(bits(point["world_normal"][c]), std::bit_cast<std::uint32_t>(d.f[6 + c])) << where << " normal " << c;
  }
}

}  // namespace tessref::test
