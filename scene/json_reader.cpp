#include "scene/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "common/error.h"

namespace tessref {
namespace {

using nlohmann::json;

bool starts_with_path(const std::string& path, const std::string& prefix) {
  return path.size() > prefix.size() && path.compare(0, prefix.size(), prefix) == 0 &&
         path[prefix.size()] == '.';
}

// The one message for a finite JSON number that a float cannot hold.
std::string overflow_message(double d) {
  return format_number(d) + " overflows single precision (the largest float is 3.4028235e38)";
}

}  // namespace

std::string format_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  std::string s = json(v).dump();  // shortest round-trip form
  if (const std::size_t e = s.find("e+"); e != std::string::npos) s.erase(e + 1, 1);  // 1e38
  return s;
}

// A value read as a float, echoed as written (-0.1, not -0.10000000149011612): the shortest
// double that rounds to the same float, which is what the user typed when it came from JSON.
std::string format_float(float f) {
  for (int digits = 1; digits <= 9; ++digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*g", digits, static_cast<double>(f));
    if (std::strtof(buf, nullptr) == f) return format_number(std::strtod(buf, nullptr));
  }
  return format_number(f);
}

void JsonSource::fail(const std::string& key_path, const std::string& what,
                      const std::vector<std::string>& related) const {
  std::string where = name + ": ";
  if (!key_path.empty()) where += key_path + ": ";
  std::string from;
  for (const std::string& k : overridden)
    for (const std::string& path : related.empty() ? std::vector<std::string>{key_path} : related)
      if (path == k || starts_with_path(path, k) || starts_with_path(k, path))
        if (from.find(k) == std::string::npos) from += (from.empty() ? "" : ", ") + ("--set " + k);
  throw InputError(where + what + (from.empty() ? "" : " (from " + from + ")"));
}

std::string describe_json(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return std::string("a boolean (") + (j.get<bool>() ? "true" : "false") + ")";
    case json::value_t::string: {
      std::string s = j.get<std::string>();
      if (s.size() > 40) s = s.substr(0, 37) + "...";
      return "a string (\"" + s + "\")";
    }
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number (" + format_number(j.get<double>()) + ")";
    case json::value_t::array: return "an array of " + std::to_string(j.size());
    case json::value_t::object: return "an object";
    default: return "an unsupported value";
  }
}

JsonObject::JsonObject(const json& j, std::string path, const JsonSource& source)
    : j_(j), path_(std::move(path)), source_(source) {
  if (!j_.is_object()) source_.fail(path_, "expected an object, got " + describe_json(j_));
}

void JsonObject::mark(const std::string& key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.push_back(key);
}

SchemaKey* JsonObject::schema_entry(const std::string& key) {
  if (!source_.schema) return nullptr;
  // lights.0.position -> lights[].position: one entry for every element.
  std::string path;
  std::size_t start = 0;
  for (const std::string full = path_of(key); start <= full.size();) {
    std::size_t end = std::min(full.find('.', start), full.size());
    const std::string segment = full.substr(start, end - start);
    const bool index = !segment.empty() && segment.find_first_not_of("0123456789") == std::string::npos;
    path += index ? "[]" : (path.empty() ? "" : ".") + segment;
    start = end + 1;
  }
  for (SchemaKey& k : *source_.schema)
    if (k.path == path) return &k;
  source_.schema->push_back({path, "", false});
  return &source_.schema->back();
}

void JsonObject::describe(const std::string& key, const std::string& allowed) {
  if (SchemaKey* k = schema_entry(key)) k->allowed = allowed;
}

bool JsonObject::has(const std::string& key) {
  mark(key);
  if (SchemaKey* k = schema_entry(key)) k->optional = true;
  return j_.contains(key);
}

std::string JsonObject::path_of(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void JsonObject::fail(const std::string& key, const std::string& what,
                      const std::vector<std::string>& also) const {
  std::vector<std::string> related;
  if (!also.empty()) {
    related.push_back(path_of(key));
    for (const std::string& k : also) related.push_back(path_of(k));
  }
  source_.fail(path_of(key), what, related);
}

const json& JsonObject::value(const std::string& key) {
  auto it = j_.find(key);
  mark(key);
  if (it == j_.end()) fail(key, "missing");
  return *it;
}

JsonObject JsonObject::object(const std::string& key) {
  return JsonObject(value(key), path_of(key), source_);
}

bool JsonObject::boolean(const std::string& key) {
  describe(key, "true or false");
  const json& v = value(key);
  if (!v.is_boolean()) fail(key, "expected true or false, got " + describe_json(v));
  return v.get<bool>();
}

std::string JsonObject::string(const std::string& key) {
  describe(key, "a string");
  const json& v = value(key);
  if (!v.is_string()) fail(key, "expected a string, got " + describe_json(v));
  return v.get<std::string>();
}

float JsonObject::number(const std::string& key) {
  describe(key, "a number");
  const json& v = value(key);
  if (!v.is_number()) fail(key, "expected a number, got " + describe_json(v));
  double d = v.get<double>();
  if (!std::isfinite(d)) fail(key, "expected a finite number, got " + format_number(d));
  if (std::abs(d) > std::numeric_limits<float>::max()) fail(key, overflow_message(d));
  return static_cast<float>(d);
}

float JsonObject::number_in(const std::string& key, float lo, float hi, bool lo_open,
                            bool hi_open) {
  float f = number(key);
  const std::string range = std::string(lo_open ? "(" : "[") + format_float(lo) + ", " +
                            (std::isinf(hi) ? std::string("inf") : format_float(hi)) + (hi_open ? ")" : "]");
  describe(key, "a number in " + range);
  if (!((lo_open ? f > lo : f >= lo) && (hi_open ? f < hi : f <= hi)))
    fail(key, "expected a number in " + range + ", got " + format_float(f));
  return f;
}

int JsonObject::integer(const std::string& key, int lo, int hi) {
  describe(key, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  const json& v = value(key);
  double d = v.is_number() ? v.get<double>() : 0.0;
  if (!v.is_number() || !std::isfinite(d) || d != std::floor(d) || d < lo || d > hi)
    fail(key, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                  "], got " + describe_json(v));
  return static_cast<int>(d);
}

std::int64_t JsonObject::integer64(const std::string& key, std::int64_t lo, std::int64_t hi) {
  describe(key, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  const json& v = value(key);
  const double d = v.is_number() ? v.get<double>() : 0.0;
  if (!v.is_number() || !std::isfinite(d) || d != std::floor(d) || d < double(lo) || d > double(hi))
    fail(key, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                  describe_json(v));
  return static_cast<std::int64_t>(d);
}

namespace {
// Reads an array of n finite numbers (n in [min_n, max_n]) into out.
template <typename Fail>
void finite_numbers(const json& v, std::size_t min_n, std::size_t max_n, float* out, Fail&& fail) {
  std::string expected = "expected an array of " + std::to_string(min_n) +
                         (max_n > min_n ? " or " + std::to_string(max_n) : std::string()) +
                         " numbers";
  if (!v.is_array() || v.size() < min_n || v.size() > max_n)
    fail(expected + ", got " + describe_json(v));
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_number())
      fail(expected + ", got " + describe_json(v[i]) + " at index " + std::to_string(i));
    double d = v[i].get<double>();
    if (!std::isfinite(d))
      fail("expected finite numbers, got " + format_number(d) + " at index " + std::to_string(i));
    if (std::abs(d) > std::numeric_limits<float>::max())
      fail(overflow_message(d) + " at index " + std::to_string(i));
    out[i] = static_cast<float>(d);
  }
}
}  // namespace

glm::vec3 JsonObject::vec3(const std::string& key) {
  describe(key, "[x, y, z]");
  glm::vec3 r;
  finite_numbers(value(key), 3, 3, &r.x, [&](const std::string& w) { fail(key, w); });
  return r;
}

glm::vec3 JsonObject::vec3_or_scalar(const std::string& key) {
  const glm::vec3 v = value(key).is_number() ? glm::vec3(number(key)) : vec3(key);
  describe(key, "a number or [x, y, z]");
  return v;
}

glm::vec4 JsonObject::rgba(const std::string& key) {
  describe(key, "[r, g, b] or [r, g, b, a]");
  glm::vec4 r(0.0f, 0.0f, 0.0f, 1.0f);
  finite_numbers(value(key), 3, 4, &r.x, [&](const std::string& w) { fail(key, w); });
  return r;
}

std::vector<float> JsonObject::levels(const std::string& key, std::size_t min_count,
                                      std::size_t max_count) {
  describe(key, "a level or an array of " + std::to_string(min_count) + " to " + std::to_string(max_count) +
                    " levels (numbers, or \"nan\", \"inf\", \"-inf\")");
  const json& v = value(key);
  auto one = [&](const json& e, const std::string& where) -> float {
    if (e.is_number()) return static_cast<float>(e.get<double>());
    if (e.is_string()) {
      const std::string s = e.get<std::string>();
      if (s == "nan") return std::numeric_limits<float>::quiet_NaN();
      if (s == "inf") return std::numeric_limits<float>::infinity();
      if (s == "-inf") return -std::numeric_limits<float>::infinity();
    }
    fail(key, "expected a tessellation level (a number, \"nan\", \"inf\" or \"-inf\"), got " +
                  describe_json(e) + where);
  };
  if (!v.is_array()) return std::vector<float>(max_count, one(v, ""));
  if (v.size() < min_count || v.size() > max_count)
    fail(key, "expected a level or an array of " + std::to_string(min_count) + " to " +
                  std::to_string(max_count) + " levels, got " + describe_json(v));
  std::vector<float> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out.push_back(one(v[i], " at index " + std::to_string(i)));
  return out;
}

void JsonObject::finish() const {
  for (auto it = j_.begin(); it != j_.end(); ++it) {
    if (std::find(known_.begin(), known_.end(), it.key()) != known_.end()) continue;
    std::string known;
    for (const std::string& k : known_) known += (known.empty() ? "" : ", ") + k;
    fail(it.key(), "unknown key" + (known.empty() ? std::string() : " (expected one of: " + known + ")"));
  }
}

}  // namespace tessref
