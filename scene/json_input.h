#pragma once
// JSON that a user hands tessref (scene files, --set values, tags files, capture manifests, verify
// reports), parsed with the limits that keep a hostile file from crashing it, and with every error
// placed at a line and column.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace tessref {

// Arrays and objects nested deeper than this are refused while parsing, before the deep value
// exists: nlohmann::json parses iteratively but copies values recursively, so a file of 150,000
// nested arrays (300 KB) parses and then overflows the stack when the scene is merged. No tessref
// file needs more than a handful of levels.
inline constexpr int kMaxJsonNesting = 256;

// Parses `text`, read from `name`. `callback` sees every parse event as nlohmann's parser callback
// does (the scene loader uses it to find duplicate keys). Throws InputError
// "NAME: line L, column C: ..." for a syntax error, a number beyond double's range (1e999) and
// nesting deeper than kMaxJsonNesting.
nlohmann::json parse_json_input(const std::string& text, const std::string& name,
                                const nlohmann::json::parser_callback_t& callback = nullptr,
                                bool ignore_comments = false);

// As parse_json_input, but text that is not JSON (or holds a number beyond double's range) gives a
// discarded value, for --set values that may be plain strings or number lists; nesting deeper than
// kMaxJsonNesting still throws.
nlohmann::json parse_json_or_discard(const std::string& text, const std::string& name);

// The largest JSON file tessref reads: scenes hold settings and file names, not data, so this is
// far above any real one, and it bounds what a wrong path (a log, a disk image) costs.
inline constexpr std::uintmax_t kMaxJsonFileBytes = std::uintmax_t(64) << 20;

// The text of `file`, whose role `what` ("scene file") names in errors. InputError
// "FILE: no such scene file", "FILE: is a directory, ...", "FILE: is not a regular file ..." (a
// device such as /dev/zero, a pipe, a socket), "FILE: ... larger than 64 MiB ..." and
// "FILE: cannot read ...".
std::string read_json_text(const std::filesystem::path& file, const std::string& what);

// read_json_text, then parse_json_input.
nlohmann::json read_json_file(const std::filesystem::path& file, const std::string& what);

// "line L, column C" (both from 1) of byte `offset` in `text`.
std::string text_position(const std::string& text, std::size_t offset);

}  // namespace tessref
