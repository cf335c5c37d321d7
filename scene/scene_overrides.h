#pragma once
// Command-line overrides of scene values: --set camera.eye=2,5,-10, --set tessellation.inner=8,
// --set lights.0.intensity=[1,1,1], --set mesh.type=torus.
#include <string>

#include <nlohmann/json.hpp>

namespace tessref {

struct SceneOverride {
  std::string key;  // dotted path; array elements by index ("lights.0.position")
  nlohmann::json value;
};

// The value is JSON if it parses as JSON, else a comma-separated list of numbers (one number:
// a scalar; decimal only, so 0x40 is a string, while "nan", "inf" and 1e999 reach validation as
// such), else a string. JSON nested deeper than kMaxJsonNesting (json_input.h) is an InputError
// that starts with `name`.
nlohmann::json parse_override_value(const std::string& text, const std::string& name = "--set");

// Splits "key=value"; InputError for a missing '=' or an empty key segment.
SceneOverride parse_override(const std::string& text);

// Merges `over` into `base`: objects key by key, a null member removes the key (as a JSON merge
// patch does), anything else replaces what `base` has. Scene files merge over the default scene
// this way, and so does --set with an object value ({"u_old": null, "u_new": 1}).
void merge_json(nlohmann::json& base, const nlohmann::json& over);

// Merges value into root[key] (merge_json), creating missing object members (validation then reports them if they
// are unknown). An array index may be one past the end, which appends. InputError when the path
// runs through a value that is neither an object nor an array, or past an array's end.
void apply_override(nlohmann::json& root, const SceneOverride& o);

}  // namespace tessref
