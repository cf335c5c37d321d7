#include "scene/json_input.h"

#include <algorithm>
#include <fstream>
#include <utility>

#include "common/error.h"

namespace tessref {
namespace {

using nlohmann::json;

// Thrown out of the parser by NestingLimit; the position is found afterwards (nested_too_deep_at),
// as the parser callback is not told where it is.
struct TooDeep {};

// The parser callback that stops the parse at the first array or object that would sit deeper
// than kMaxJsonNesting, then hands every event to the caller's callback, if any.
class NestingLimit {
 public:
  explicit NestingLimit(json::parser_callback_t inner) : inner_(std::move(inner)) {}
  bool operator()(int depth, json::parse_event_t event, json& parsed) const {
    const bool opens = event == json::parse_event_t::object_start || event == json::parse_event_t::array_start;
    // `depth` counts the arrays and objects around the one that opens.
    if (opens && depth >= kMaxJsonNesting) throw TooDeep{};
    return !inner_ || inner_(depth, event, parsed);
  }

 private:
  json::parser_callback_t inner_;
};

// Calls visit(i) for each byte i of `text` outside strings (and outside comments where the parser
// skips them), in order, until visit returns true; returns that i, or npos. Only for placing an
// error the parser has already met, so the text is well-formed up to there.
template <class Visit>
std::size_t find_outside_strings(const std::string& text, bool comments, Visit visit) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
      continue;
    }
    if (comments && c == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*')) {
      const bool to_line_end = text[i + 1] == '/';
      const std::size_t end = text.find(to_line_end ? "\n" : "*/", i + 2);
      if (end == std::string::npos) return std::string::npos;
      i = to_line_end ? end : end + 1;
      continue;
    }
    if (visit(i)) return i;
  }
  return std::string::npos;
}

// The '[' or '{' that opens level kMaxJsonNesting + 1.
std::size_t nested_too_deep_at(const std::string& text, bool comments) {
  int depth = 0;
  return find_outside_strings(text, comments, [&](std::size_t i) {
    if (text[i] == '[' || text[i] == '{') return ++depth > kMaxJsonNesting;
    if (text[i] == ']' || text[i] == '}') --depth;
    return false;
  });
}

bool in_number(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// Where the number `literal` first appears as a whole token: the parser stops at the first number
// it cannot hold, and an earlier copy of the same text would have stopped it there.
std::size_t number_at(const std::string& text, const std::string& literal, bool comments) {
  if (literal.empty()) return std::string::npos;
  return find_outside_strings(text, comments, [&](std::size_t i) {
    const std::size_t end = i + literal.size();
    return text.compare(i, literal.size(), literal) == 0 && (i == 0 || !in_number(text[i - 1])) &&
           (end >= text.size() || !in_number(text[end]));
  });
}

// "[json.exception.parse_error.101] parse error at line 2, column 3: syntax error ..." ->
// "syntax error ...": the location is given separately.
std::string json_reason(const std::string& what) {
  std::size_t pos = what.find("]");
  std::string s = pos == std::string::npos ? what : what.substr(pos + 2);
  std::size_t colon = s.find(": ");
  if (s.rfind("parse error", 0) == 0 && colon != std::string::npos) s = s.substr(colon + 2);
  return s;
}

// "NAME: line L, column C: " or, where the place is unknown, "NAME: ".
std::string located(const std::string& text, const std::string& name, std::size_t offset) {
  return name + ": " + (offset == std::string::npos ? "" : text_position(text, offset) + ": ");
}

[[noreturn]] void throw_too_deep(const std::string& text, const std::string& name, bool comments) {
  throw InputError(located(text, name, nested_too_deep_at(text, comments)) +
                   "arrays and objects nested deeper than " + std::to_string(kMaxJsonNesting) +
                   " levels (tessref's limit for JSON input)");
}

// "number overflow parsing '1e999'" -> 1e999.
std::string overflowing_literal(const std::string& reason) {
  const std::size_t open = reason.find('\''), close = reason.rfind('\'');
  return open == std::string::npos || close <= open ? std::string() : reason.substr(open + 1, close - open - 1);
}

}  // namespace

std::string text_position(const std::string& text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') line++, column = 1;
    else column++;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

json parse_json_input(const std::string& text, const std::string& name, const json::parser_callback_t& callback,
                      bool ignore_comments) {
  try {
    return json::parse(text, NestingLimit(callback), /*allow_exceptions=*/true, ignore_comments);
  } catch (const TooDeep&) {
    throw_too_deep(text, name, ignore_comments);
  } catch (const json::parse_error& e) {
    // e.byte is 1-based, the byte after the last one read.
    const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    throw InputError(located(text, name, end) + "JSON syntax error: " + json_reason(e.what()));
  } catch (const json::out_of_range& e) {
    // 406: a number beyond double's range. nlohmann does not say where; the literal does.
    const std::string reason = json_reason(e.what());
    throw InputError(located(text, name, number_at(text, overflowing_literal(reason), ignore_comments)) +
                     "invalid JSON: " + reason);
  } catch (const json::exception& e) {
    throw InputError(name + ": invalid JSON: " + json_reason(e.what()));
  }
}

json parse_json_or_discard(const std::string& text, const std::string& name) {
  try {
    return json::parse(text, NestingLimit(nullptr), /*allow_exceptions=*/false);
  } catch (const TooDeep&) {
    throw_too_deep(text, name, false);
  }
}

std::string read_json_text(const std::filesystem::path& file, const std::string& what) {
  const std::string name = file.string();
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) throw InputError(name + ": no such " + what);
  if (std::filesystem::is_directory(status)) throw InputError(name + ": is a directory, not a " + what);
  // A device (/dev/zero), pipe or socket may never end, and opening a pipe waits for a writer.
  if (!std::filesystem::is_regular_file(status))
    throw InputError(name + ": is not a regular file (a device, pipe or socket), not a " + what);
  std::ifstream in(file, std::ios::binary);
  if (!in.is_open()) throw InputError(name + ": cannot open the " + what);
  // Read in blocks up to one byte past the limit: a file's size can change after it is asked, and
  // some regular files (/proc) report none. (Not one buffer of the limit's size: zeroing it cost
  // more than the rest of a small render.)
  std::string text;
  char block[1 << 16];
  while (text.size() <= kMaxJsonFileBytes) {
    const std::size_t want = std::min(sizeof block, std::size_t(kMaxJsonFileBytes) + 1 - text.size());
    in.read(block, std::streamsize(want));
    if (in.bad()) throw InputError(name + ": cannot read the " + what);
    text.append(block, std::size_t(in.gcount()));
    if (!in) break;  // end of file
  }
  if (text.size() > kMaxJsonFileBytes)
    throw InputError(name + ": the " + what + " is larger than " + std::to_string(kMaxJsonFileBytes >> 20) +
                     " MiB (tessref's limit for JSON input)");
  return text;
}

json read_json_file(const std::filesystem::path& file, const std::string& what) {
  return parse_json_input(read_json_text(file, what), file.string());
}

}  // namespace tessref
