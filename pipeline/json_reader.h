#pragma once
// Typed, strict access to one JSON object of a scene: every read names its key path in errors, and
// finish() rejects the keys nobody read. Errors are InputError "<source>: <key.path>: <what>".
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace tessref {

// Where values come from: the scene file (or "<default scene>") and the key paths --set replaced.
struct JsonSource {
  std::string name;
  std::vector<std::string> overridden;
  // `related`: the key paths the failed rule reads (for camera.far > camera.near, both); a --set
  // of any of them is named. Empty: just key_path.
  [[noreturn]] void fail(const std::string& key_path, const std::string& what,
                         const std::vector<std::string>& related = {}) const;
};

// Numbers for messages: integers without a fraction, others in the shortest form that reads back
// the same ("nan", "inf" spelled out); format_float echoes a float as typed (-0.1, not
// -0.10000000149011612).
std::string format_number(double v);
std::string format_float(float f);

// "a string (\"abc\")", "an array", "null", ...: for "expected X, got Y" messages.
std::string describe_json(const nlohmann::json& j);

class JsonObject {
 public:
  // Fails unless j is an object.
  JsonObject(const nlohmann::json& j, std::string path, const JsonSource& source);

  bool has(const std::string& key);  // an optional key: known, read only if present
  std::string path_of(const std::string& key) const;
  const nlohmann::json& value(const std::string& key);  // required; marks the key as read
  // `also`: sibling keys the failed rule reads besides `key` (named when --set changed them).
  [[noreturn]] void fail(const std::string& key, const std::string& what,
                         const std::vector<std::string>& also = {}) const;

  JsonObject object(const std::string& key);
  bool boolean(const std::string& key);
  std::string string(const std::string& key);
  float number(const std::string& key);  // finite
  float number_in(const std::string& key, float lo, float hi, bool lo_open, bool hi_open);
  int integer(const std::string& key, int lo, int hi);
  glm::vec3 vec3(const std::string& key);             // array of 3 finite numbers
  glm::vec3 vec3_or_scalar(const std::string& key);   // a number s means (s, s, s)
  glm::vec4 rgba(const std::string& key);             // 3 numbers (alpha 1) or 4
  // Tessellation levels: numbers, or "nan", "inf", "-inf" as strings (JSON has no such literals).
  std::vector<float> levels(const std::string& key, std::size_t min_count, std::size_t max_count);

  // Fails on the first key no accessor read, naming the keys that exist here.
  void finish() const;

 private:
  const nlohmann::json& j_;
  std::string path_;
  const JsonSource& source_;
  std::vector<std::string> known_;  // keys asked for, in the order asked
  void mark(const std::string& key);
};

}  // namespace tessref
