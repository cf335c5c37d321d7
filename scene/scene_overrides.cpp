#include "scene/scene_overrides.h"

#include <charconv>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "common/error.h"
#include "scene/json_input.h"
#include "scene/json_reader.h"

namespace tessref {
namespace {

using nlohmann::json;

std::string trim(const std::string& s) {
  std::size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// A decimal number over the whole piece (no hexadecimal: 0x40 is not a number in a scene, as JSON
// has none either); false if anything is left over. Out-of-range values become +-inf or 0 as
// strtod's would, for the validation to name.
bool parse_double(const std::string& piece, double& out) {
  std::string s = trim(piece);
  if (!s.empty() && s[0] == '+') s.erase(0, 1);
  if (s.empty()) return false;
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, out, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) out = std::strtod(s.c_str(), nullptr);
  else if (ec != std::errc()) return false;
  return ptr == end;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!s.empty() && s.back() == sep) parts.push_back("");
  return parts;
}

bool is_index(const std::string& s) {
  return !s.empty() && s.size() < 9 && s.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

json parse_override_value(const std::string& text, const std::string& name) {
  json j = parse_json_or_discard(text, name);
  if (!j.is_discarded()) return j;
  std::vector<std::string> pieces = split(text, ',');
  if (pieces.empty()) return json(text);
  json numbers = json::array();
  for (const std::string& p : pieces) {
    double d;
    if (!parse_double(p, d)) return json(text);
    numbers.push_back(d);
  }
  if (numbers.size() == 1) return numbers[0];
  return numbers;
}

SceneOverride parse_override(const std::string& text) {
  std::size_t eq = text.find('=');
  if (eq == std::string::npos)
    throw InputError("--set " + text + ": expected KEY=VALUE (e.g. camera.eye=2,5,-10)");
  const std::string key = trim(text.substr(0, eq));
  SceneOverride o{key, parse_override_value(text.substr(eq + 1), "--set " + key)};
  for (const std::string& seg : split(o.key, '.'))
    if (seg.empty()) throw InputError("--set " + text + ": empty key segment in '" + o.key + "'");
  if (o.key.empty()) throw InputError("--set " + text + ": empty key");
  return o;
}

void apply_override(json& root, const SceneOverride& o) {
  json* node = &root;
  std::string path;
  for (const std::string& seg : split(o.key, '.')) {
    if (node->is_array()) {
      if (!is_index(seg))
        throw InputError("--set " + o.key + ": " + path + " is an array: expected an index, got '" + seg + "'");
      std::size_t i = std::stoul(seg);
      if (i > node->size())
        throw InputError("--set " + o.key + ": " + path + " has " + std::to_string(node->size()) +
                         " elements: index " + seg + " is past its end");
      if (i == node->size()) node->push_back(json::object());
      node = &(*node)[i];
    } else if (node->is_object() || node->is_null()) {
      node = &(*node)[seg];
    } else {
      throw InputError("--set " + o.key + ": " + path + " is " + describe_json(*node) +
                       ", not an object");
    }
    path += (path.empty() ? "" : ".") + seg;
  }
  merge_json(*node, o.value);
}

void merge_json(json& base, const json& over) {
  if (!base.is_object() || !over.is_object()) {
    base = over;
    return;
  }
  for (auto it = over.begin(); it != over.end(); ++it) {
    if (it.value().is_null()) base.erase(it.key());  // as in a JSON merge patch (RFC 7386)
    else merge_json(base[it.key()], it.value());
  }
}

}  // namespace tessref
