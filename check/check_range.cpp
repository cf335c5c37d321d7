#include "check/check_range.h"

#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "common/error.h"
#include "check/check.h"
#include "stages/tess_stage.h"

namespace tessref {
namespace {

int vec_size(const std::string& type) {
  if (type == "float") return 1;
  return type[3] - '0';  // vec2 .. vec4
}

const char* kComponents = "xyzw";

[[noreturn]] void fail(const std::string& spec, const std::string& rule) {
  throw InputError("--check-range '" + spec + "': " + rule);
}

// A bound: a whole number in C's strtod syntax ("1e6", "-inf"), not NaN.
float bound(const std::string& spec, const std::string& text, const char* which) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double d = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size())
    fail(spec, std::string(which) + " bound '" + text + "' is not a number (expected NAME=LO,HI)");
  if (std::isnan(d)) fail(spec, std::string(which) + " bound is NaN: a range needs two ordered numbers");
  return float(d);
}

std::string known_names(const std::vector<CheckOutput>& outputs) {
  std::string s = "gl_Position";
  for (const CheckOutput& o : outputs) s += ", " + o.name;
  return s + " (each with .x/.y/.z/.w or inside length(...)), levels, gl_TessLevelOuter[0..3], "
             "gl_TessLevelInner[0..1]";
}

}  // namespace

std::vector<CheckOutput> evaluation_output_names(const CheckSource& tes) {
  // The built-in programs pack the normal right after the position (stages/tess_stage.h).
  if (tes.file.empty()) return {{"v_world_position", 4 + kVaryingPosition, 3}, {"v_world_normal", 4 + kVaryingNormal, 3}};
  std::vector<CheckOutput> out;
  static const std::regex decl(
      R"(layout\s*\(\s*location\s*=\s*(\d+)\s*\)\s*out\s+(float|vec2|vec3|vec4)\s+(\w+)\s*;)");
  for (std::sregex_iterator it(tes.text.begin(), tes.text.end(), decl), end; it != end; ++it) {
    const int location = std::atoi((*it)[1].str().c_str());
    if (location < 0 || location > 7) continue;
    out.push_back({(*it)[3].str(), 4 + 4 * location, vec_size((*it)[2].str())});
  }
  return out;
}

CheckRange parse_check_range(const std::string& spec, const std::vector<CheckOutput>& outputs) {
  const std::size_t eq = spec.rfind('=');
  if (eq == std::string::npos || eq == 0) fail(spec, "expected NAME=LO,HI");
  std::string name = spec.substr(0, eq);
  const std::string bounds = spec.substr(eq + 1);
  const std::size_t comma = bounds.find(',');
  if (comma == std::string::npos) fail(spec, "expected two bounds LO,HI after '='");
  CheckRange r;
  r.spec = spec;
  r.lo = bound(spec, bounds.substr(0, comma), "lower");
  r.hi = bound(spec, bounds.substr(comma + 1), "upper");
  if (r.lo > r.hi) fail(spec, "the lower bound is above the upper one (LO <= HI)");

  // Levels.
  if (name == "levels") {
    r.level = true;
    r.index = {0, 1, 2, 4};
    r.names = {"gl_TessLevelOuter[0]", "gl_TessLevelOuter[1]", "gl_TessLevelOuter[2]", "gl_TessLevelInner[0]"};
    return r;
  }
  static const std::regex level(R"(gl_TessLevel(Outer|Inner)\[(\d)\])");
  if (std::smatch m; std::regex_match(name, m, level)) {
    const bool outer = m[1] == "Outer";
    const int i = m[2].str()[0] - '0';
    if (i > (outer ? 3 : 1)) fail(spec, "gl_TessLevel" + m[1].str() + " has " + (outer ? "4" : "2") + " elements");
    r.level = true;
    r.index = {outer ? i : 4 + i};
    r.names = {name};
    return r;
  }

  // Evaluation shader outputs: NAME, NAME.c or length(NAME).
  std::string base = name;
  static const std::regex length(R"(length\((\w+)\))");
  if (std::smatch m; std::regex_match(name, m, length)) {
    r.length = true;
    base = m[1].str();
  }
  int component = -1;
  if (const std::size_t dot = base.find('.'); !r.length && dot != std::string::npos) {
    const std::string c = base.substr(dot + 1);
    if (c.size() != 1 || std::string(kComponents).find(c[0]) == std::string::npos)
      fail(spec, "'." + c + "': a component is one of .x .y .z .w");
    component = int(std::string(kComponents).find(c[0]));
    base = base.substr(0, dot);
  }
  CheckOutput found{"", -1, 0};
  if (base == "gl_Position") found = {"gl_Position", 0, 4};
  for (const CheckOutput& o : outputs)
    if (o.name == base) found = o;
  if (found.first < 0) fail(spec, "unknown name '" + base + "'; this scene has " + known_names(outputs));
  if (component >= found.components)
    fail(spec, "'" + base + "' has " + std::to_string(found.components) + " component(s)");
  for (int c = 0; c < found.components; ++c) {
    if (component >= 0 && c != component) continue;
    r.index.push_back(found.first + c);
    r.names.push_back(found.components == 1 ? base : base + "." + kComponents[c]);
  }
  if (r.length) r.names = {name};
  return r;
}

}  // namespace tessref
