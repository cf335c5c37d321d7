#include "piglit/shader_test_file.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <string_view>

#include "common/error.h"

namespace tessref {
namespace {

// ---- text ----

// A line of the file, for messages.
struct Where {
  const std::string& file;
  int line;  // 1-based
};

[[noreturn]] void fail(const std::string& file, int line, const std::string& what) {
  throw InputError(file + ":" + std::to_string(line) + ": " + what);
}

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// piglit's comments run from '#' to the end of the line, in [require], [vertex data] and [test].
std::string_view strip_comment(std::string_view s) { return trim(s.substr(0, s.find('#'))); }

// Words split at white space; in [test] lines '(', ')' and ',' are words of their own, so that
// "(0.5,0.5)" and "( 0.5 , 0.5 )" read alike (piglit's sscanf patterns accept both).
std::vector<std::string> split_words(std::string_view s, bool punctuation) {
  std::vector<std::string> words;
  std::string word;
  auto flush = [&] {
    if (!word.empty()) words.push_back(word);
    word.clear();
  };
  for (char c : s) {
    if (is_space(c)) {
      flush();
    } else if (punctuation && (c == '(' || c == ')' || c == ',')) {
      flush();
      words.emplace_back(1, c);
    } else {
      word += c;
    }
  }
  flush();
  return words;
}

// ---- numbers ----
// piglit reads integers with strtol(s, 0) (0x hex, a leading 0 octal) and floats with its
// strtof_hex/strtod_hex, where "0x..." is the raw bit pattern of the float or double.

bool has_hex_prefix(std::string_view s) {
  return s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
}

// An unsigned number in the given base, the whole of s.
std::optional<std::uint64_t> to_unsigned(std::string_view s, int base) {
  std::uint64_t v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, base);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

// Hex is a 64-bit pattern (as in piglit's int64 parser); decimal and octal must fit in 63 bits.
std::optional<long long> to_integer(std::string_view s) {
  bool negative = !s.empty() && s[0] == '-';
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) s.remove_prefix(1);
  const bool hex = has_hex_prefix(s);
  std::optional<std::uint64_t> v;
  if (hex)
    v = to_unsigned(s.substr(2), 16);
  else if (s.size() > 1 && s[0] == '0')
    v = to_unsigned(s.substr(1), 8);
  else
    v = to_unsigned(s, 10);
  if (!v || (!hex && *v > static_cast<std::uint64_t>(INT64_MAX))) return std::nullopt;
  return static_cast<long long>(negative ? 0 - *v : *v);  // modular, like strtoull's result
}

template <typename Float, typename Bits>
std::optional<double> to_floating(std::string_view s) {
  if (has_hex_prefix(s)) {
    std::optional<std::uint64_t> bits = to_unsigned(s.substr(2), 16);
    if (!bits || *bits > static_cast<std::uint64_t>(static_cast<Bits>(-1))) return std::nullopt;
    return std::bit_cast<Float>(static_cast<Bits>(*bits));
  }
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const char* last = s.data() + s.size();
  Float v = 0;
  auto [end, ec] = std::from_chars(s.data(), last, v);
  if (ec == std::errc::result_out_of_range && end == last) {
    // Beyond the type's range: strtof gives inf or 0 (or a denormal), and piglit takes that
    // (its generated tes-input tests have a uniform float 3.38e+42).
    long double wide = 0;
    if (std::from_chars(s.data(), last, wide).ec == std::errc()) return static_cast<Float>(wide);
  }
  if (s.empty() || ec != std::errc() || end != last) return std::nullopt;
  return v;
}

const char* describe(DataType t) {
  switch (t) {
    case DataType::Byte: return "a byte";
    case DataType::Ubyte: return "an unsigned byte";
    case DataType::Short: return "a short";
    case DataType::Ushort: return "an unsigned short";
    case DataType::Int: return "an integer";
    case DataType::Uint: return "an unsigned integer";
    case DataType::Float: return "a float";
    case DataType::Double: return "a double";
  }
  return "";
}

// One number of type t, or nullopt. Int and Uint keep the low 32 bits, as piglit's casts do
// (0xffffffff is -1 as an Int, -1 is 4294967295 as a Uint; its generated tests even have
// 0x1fffffffe); a Uint may end in 'u' like a GLSL literal ("0u", which piglit's strtoul reads).
// The small types must fit.
std::optional<double> to_number(std::string_view s, DataType t) {
  if (t == DataType::Float) return to_floating<float, std::uint32_t>(s);
  if (t == DataType::Double) return to_floating<double, std::uint64_t>(s);
  if (t == DataType::Uint && (s.ends_with('u') || s.ends_with('U'))) s.remove_suffix(1);
  std::optional<long long> v = to_integer(s);
  if (!v) return std::nullopt;
  auto within = [&](long long lo, long long hi) { return *v >= lo && *v <= hi; };
  switch (t) {
    case DataType::Byte: return within(-128, 127) ? v : std::nullopt;
    case DataType::Ubyte: return within(0, 255) ? v : std::nullopt;
    case DataType::Short: return within(-32768, 32767) ? v : std::nullopt;
    case DataType::Ushort: return within(0, 65535) ? v : std::nullopt;
    case DataType::Int: return static_cast<std::int32_t>(static_cast<std::uint32_t>(*v));
    case DataType::Uint: return static_cast<std::uint32_t>(*v);
    default: return std::nullopt;
  }
}

DataType data_type_of(ScalarType s) {
  switch (s) {
    case ScalarType::Float: return DataType::Float;
    case ScalarType::Double: return DataType::Double;
    case ScalarType::Uint: return DataType::Uint;
    case ScalarType::Int:
    case ScalarType::Bool: return DataType::Int;
  }
  return DataType::Float;
}

// ---- types ----

// float, vec3, int, ivec2, uint, uvec4, bool, bvec3, double, dvec2, mat3, mat2x4, dmat4x3.
std::optional<GlslType> parse_glsl_type(std::string_view s) {
  struct Name {
    std::string_view scalar, vector, matrix;
    ScalarType type;
  };
  static constexpr Name names[] = {{"float", "vec", "mat", ScalarType::Float},
                                   {"double", "dvec", "dmat", ScalarType::Double},
                                   {"int", "ivec", "", ScalarType::Int},
                                   {"uint", "uvec", "", ScalarType::Uint},
                                   {"bool", "bvec", "", ScalarType::Bool}};
  auto dimension = [](char c) { return c >= '2' && c <= '4' ? c - '0' : 0; };
  for (const Name& n : names) {
    if (s == n.scalar) return GlslType{n.type, 1, 1};
    if (s.size() == n.vector.size() + 1 && s.starts_with(n.vector) && dimension(s.back()))
      return GlslType{n.type, 1, dimension(s.back())};
    if (n.matrix.empty() || !s.starts_with(n.matrix)) continue;
    std::string_view d = s.substr(n.matrix.size());
    if (d.size() == 1 && dimension(d[0])) return GlslType{n.type, dimension(d[0]), dimension(d[0])};
    if (d.size() == 3 && d[1] == 'x' && dimension(d[0]) && dimension(d[2]))
      return GlslType{n.type, dimension(d[0]), dimension(d[2])};
  }
  return std::nullopt;
}

std::optional<Comparison> parse_comparison(std::string_view s) {
  if (s == "==") return Comparison::Equal;
  if (s == "!=") return Comparison::NotEqual;
  if (s == "<") return Comparison::Less;
  if (s == "<=") return Comparison::LessEqual;
  if (s == ">") return Comparison::Greater;
  if (s == ">=") return Comparison::GreaterEqual;
  return std::nullopt;
}

// ---- [require] ----

// The words after "GL" or "GLSL": [CORE|COMPAT|ES] OP MAJOR.MINOR.
VersionRequirement parse_version(const std::vector<std::string>& w, bool glsl, const Where& at) {
  VersionRequirement v;
  std::size_t i = 1;
  static constexpr std::pair<std::string_view, Profile> profiles[] = {
      {"CORE", Profile::Core}, {"COMPAT", Profile::Compat}, {"ES", Profile::Es}};
  for (const auto& [name, profile] : profiles) {
    if (i < w.size() && w[i] == name) {
      v.profile = profile;
      ++i;
    }
  }
  std::optional<Comparison> op = i < w.size() ? parse_comparison(w[i]) : std::nullopt;
  std::string_view number = i + 1 < w.size() ? std::string_view(w[i + 1]) : "";
  std::size_t dot = number.find('.');
  std::optional<std::uint64_t> major = to_unsigned(number.substr(0, dot), 10);
  std::string_view minor_text = dot == std::string_view::npos ? "" : number.substr(dot + 1);
  std::optional<std::uint64_t> minor = to_unsigned(minor_text, 10);
  // GLSL minors have two digits (1.50), GL minors one (3.2); "GLSL >= 4.5" and "GL >= 4.00"
  // appear too.
  bool minor_ok =
      minor && (minor_text.size() == 1 || (minor_text.size() == 2 && (glsl || *minor % 10 == 0)));
  if (!op || !major || *major > 9 || !minor_ok || w.size() != i + 2)
    fail(at.file, at.line, "expected '" + w[0] + " [CORE|COMPAT|ES] >= MAJOR.MINOR'");
  v.comparison = *op;
  v.major = static_cast<int>(*major);
  v.minor = static_cast<int>(*minor);
  if (glsl && minor_text.size() == 1) v.minor *= 10;
  if (!glsl && minor_text.size() == 2) v.minor /= 10;
  return v;
}

LimitRequirement parse_limit(const std::vector<std::string>& w, std::size_t i, const Where& at) {
  std::optional<Comparison> op = i + 1 < w.size() ? parse_comparison(w[i + 1]) : std::nullopt;
  std::optional<long long> value = i + 2 < w.size() ? to_integer(w[i + 2]) : std::nullopt;
  if (!op || !value || w.size() != i + 3) fail(at.file, at.line, "expected 'GL_NAME OP VALUE'");
  return LimitRequirement{w[i], *op, *value};
}

void parse_requirement(std::string_view raw, const Where& at, Requirements& r) {
  std::string_view text = strip_comment(raw);
  if (text.empty()) return;
  std::vector<std::string> w = split_words(text, false);
  const std::string& first = w[0];
  if (first == "INT") {
    r.limits.push_back(parse_limit(w, 1, at));
  } else if (first.starts_with("GL_") && w.size() > 1) {
    r.limits.push_back(parse_limit(w, 0, at));
  } else if (first.starts_with("GL_") || first.starts_with("!GL_")) {
    if (w.size() > 1) fail(at.file, at.line, "unexpected '" + w[1] + "' after the extension");
    bool negated = first[0] == '!';
    r.extensions.push_back({first.substr(negated ? 1 : 0), negated});
  } else if (first == "GLSL" || first == "GL") {
    std::optional<VersionRequirement>& slot = first == "GL" ? r.gl : r.glsl;
    if (slot) fail(at.file, at.line, "a second " + first + " version requirement");
    slot = parse_version(w, first == "GLSL", at);
  } else if (first == "SIZE") {
    std::optional<long long> width = w.size() == 3 ? to_integer(w[1]) : std::nullopt;
    std::optional<long long> height = w.size() == 3 ? to_integer(w[2]) : std::nullopt;
    if (!width || !height || *width < 1 || *height < 1 || *width > 16384 || *height > 16384)
      fail(at.file, at.line, "expected 'SIZE WIDTH HEIGHT'");
    r.size = std::array<int, 2>{static_cast<int>(*width), static_cast<int>(*height)};
  } else {
    r.other.push_back({at.line, std::string(text)});
  }
}

// ---- [vertex data] ----

std::optional<DataType> parse_data_type(std::string_view s) {
  static constexpr std::pair<std::string_view, DataType> types[] = {
      {"byte", DataType::Byte},     {"ubyte", DataType::Ubyte},  {"short", DataType::Short},
      {"ushort", DataType::Ushort}, {"int", DataType::Int},      {"uint", DataType::Uint},
      {"float", DataType::Float},   {"double", DataType::Double}};
  for (const auto& [name, type] : types)
    if (s == name) return type;
  return std::nullopt;
}

// The GLSL kind of a column given as a count ("vertex/float/2"), as piglit's table has it.
ScalarType scalar_of(DataType t) {
  switch (t) {
    case DataType::Byte:
    case DataType::Short:
    case DataType::Int: return ScalarType::Int;
    case DataType::Ubyte:
    case DataType::Ushort:
    case DataType::Uint: return ScalarType::Uint;
    case DataType::Float: return ScalarType::Float;
    case DataType::Double: return ScalarType::Double;
  }
  return ScalarType::Float;
}

VertexColumn parse_column(const std::string& header, const Where& at) {
  auto bad = [&](const std::string& what) {
    fail(at.file, at.line, "vertex data column '" + header + "': " + what);
  };
  std::vector<std::string> parts;
  std::stringstream in(header);
  for (std::string part; std::getline(in, part, '/');) parts.push_back(part);
  if (parts.size() < 3 || parts.size() > 4 || parts[0].empty())
    bad("expected NAME/TYPE/GLSL_TYPE or NAME/TYPE/COUNT, optionally /MATRIX_COLUMN");
  VertexColumn c;
  c.name = parts[0];
  if (std::size_t open = c.name.find('['); open != std::string::npos) {
    std::optional<long long> index =
        c.name.back() == ']'
            ? to_integer(std::string_view(c.name).substr(open + 1, c.name.size() - open - 2))
            : std::nullopt;
    if (!index || *index < 0 || *index > 1024 || open == 0) bad("bad array index");
    c.array_index = static_cast<int>(*index);
    c.name.resize(open);
  }
  std::optional<DataType> type = parse_data_type(parts[1]);
  if (!type) bad("unknown data type '" + parts[1] + "'");
  c.data_type = *type;
  if (std::isdigit(static_cast<unsigned char>(parts[2][0]))) {
    std::optional<long long> count = to_integer(parts[2]);
    if (!count || *count < 1 || *count > 4) bad("the component count must be 1 to 4");
    c.glsl_type = GlslType{scalar_of(c.data_type), 1, static_cast<int>(*count)};
  } else {
    std::optional<GlslType> glsl = parse_glsl_type(parts[2]);
    if (!glsl) bad("unknown GLSL type '" + parts[2] + "'");
    c.glsl_type = *glsl;
  }
  if (parts.size() == 4) {
    std::optional<long long> column = to_integer(parts[3]);
    if (!column || *column < 0 || *column > 3) bad("the matrix column must be 0 to 3");
    c.matrix_column = static_cast<int>(*column);
  }
  return c;
}

void parse_vertex_row(const std::vector<std::string>& values, const Where& at, VertexData& d) {
  std::size_t expected = 0;
  for (const VertexColumn& c : d.columns) expected += c.glsl_type.rows;
  if (values.size() != expected)
    fail(at.file, at.line,
         "vertex data row has " + std::to_string(values.size()) + " values, the header asks for " +
             std::to_string(expected));
  std::size_t i = 0;
  for (VertexColumn& c : d.columns) {
    for (int k = 0; k < c.glsl_type.rows; ++k, ++i) {
      std::optional<double> v = to_number(values[i], c.data_type);
      if (!v)
        fail(at.file, at.line,
             "vertex data column '" + c.name + "': expected " + describe(c.data_type) + ", got '" +
                 values[i] + "'");
      c.values.push_back(*v);
    }
  }
  ++d.vertex_count;
}

// ---- [test] ----

// The words of one command, read front to back. Messages name the command by the keywords
// matched so far.
class Args {
 public:
  Args(std::vector<std::string> words, const Where& at) : words_(std::move(words)), at_(at) {}

  // Consumes the keywords if the next words are exactly these.
  bool match(std::initializer_list<std::string_view> keywords) {
    std::size_t i = pos_;
    for (std::string_view k : keywords)
      if (i >= words_.size() || words_[i++] != k) return false;
    for (std::string_view k : keywords) command_ += (command_.empty() ? "" : " ") + std::string(k);
    pos_ = i;
    return true;
  }
  bool done() const { return pos_ == words_.size(); }
  std::string_view peek() const { return done() ? std::string_view() : words_[pos_]; }

  std::string word(const char* what) {
    if (done() || is_punctuation(words_[pos_]))
      fail("expected " + std::string(what) + ", got " + next_desc());
    return words_[pos_++];
  }
  double number(DataType t) {
    std::optional<double> v = done() ? std::nullopt : to_number(words_[pos_], t);
    if (!v) fail("expected " + std::string(describe(t)) + ", got " + next_desc());
    ++pos_;
    return *v;
  }
  void numbers(std::vector<double>& out, int n, DataType t) {
    for (int i = 0; i < n; ++i) out.push_back(number(t));
  }
  // "( V , V , ... )" with n values. Like piglit's sscanf patterns, this does not insist on the
  // closing ')': piglit reads "(r, g, b, a)" where it wants three values as "(r, g, b)".
  void tuple(std::vector<double>& out, int n, DataType t) {
    punctuation("(");
    for (int i = 0; i < n; ++i) {
      if (i > 0) punctuation(",");
      out.push_back(number(t));
    }
    if (peek() == ")") ++pos_;
  }
  [[noreturn]] void fail(const std::string& what) const {
    tessref::fail(at_.file, at_.line, "'" + command_ + "': " + what);
  }

 private:
  static bool is_punctuation(std::string_view w) { return w == "(" || w == ")" || w == ","; }
  std::string next_desc() const {
    return done() ? "the end of the line" : "'" + words_[pos_] + "'";
  }
  void punctuation(std::string_view p) {
    if (peek() != p) fail("expected '" + std::string(p) + "', got " + next_desc());
    ++pos_;
  }

  std::vector<std::string> words_;
  std::size_t pos_ = 0;
  Where at_;
  std::string command_;
};

constexpr DataType F = DataType::Float;
constexpr DataType I = DataType::Int;
constexpr DataType U = DataType::Uint;

// rgb or rgba: the colour's channel count, or 0 for anything else.
int channels(Args& a) {
  if (a.match({"rgba"})) return 4;
  if (a.match({"rgb"})) return 3;
  return 0;
}

// The primitive modes piglit's decode_drawing_mode knows (GL_POINTS to GL_PATCHES).
bool is_draw_mode(std::string_view m) {
  static constexpr std::string_view modes[] = {"GL_POINTS",
                                               "GL_LINES",
                                               "GL_LINE_LOOP",
                                               "GL_LINE_STRIP",
                                               "GL_TRIANGLES",
                                               "GL_TRIANGLE_STRIP",
                                               "GL_TRIANGLE_FAN",
                                               "GL_QUADS",
                                               "GL_QUAD_STRIP",
                                               "GL_POLYGON",
                                               "GL_LINES_ADJACENCY",
                                               "GL_LINE_STRIP_ADJACENCY",
                                               "GL_TRIANGLES_ADJACENCY",
                                               "GL_TRIANGLE_STRIP_ADJACENCY",
                                               "GL_PATCHES"};
  for (std::string_view known : modes)
    if (m == known) return true;
  return false;
}

using K = CommandKind;

void parse_draw(Args& a, TestCommand& c) {
  if (a.match({"draw", "arrays"})) {
    bool instanced = a.match({"instanced"});
    c.words.push_back(a.word("a primitive mode"));
    if (!is_draw_mode(c.words[0])) a.fail("unknown primitive mode '" + c.words[0] + "'");
    a.numbers(c.numbers, 2, I);
    c.numbers.push_back(instanced ? a.number(I) : 1);
    c.kind = K::DrawArrays;
    return;
  }
  bool instanced = a.match({"draw", "instanced", "rect"});
  if (!instanced && !a.match({"draw", "rect"})) return;
  if (a.match({"tex"})) return;  // draw rect tex: texture coordinates too, not modelled
  c.ortho = a.match({"ortho"});
  c.patch = a.match({"patch"});
  double instances = instanced ? a.number(I) : 1;
  a.numbers(c.numbers, 4, F);
  c.numbers.push_back(instances);
  c.kind = K::DrawRect;
}

// The scalar GLSL type a ssbo command names (int, uint, float, double); false for others
// (int64, vectors), which leave the command Unknown.
bool ssbo_type(Args& a, TestCommand& c) {
  const std::optional<GlslType> t = parse_glsl_type(a.word("a type"));
  if (!t || t->columns != 1 || t->rows != 1 || t->scalar == ScalarType::Bool) return false;
  c.type = *t;
  return true;
}

void parse_probe(Args& a, TestCommand& c) {
  if (a.match({"probe", "ssbo"})) {
    if (!ssbo_type(a, c)) return;
    a.numbers(c.numbers, 2, U);
    std::string op = a.word("a comparison");
    std::optional<Comparison> cmp = parse_comparison(op);
    if (!cmp) a.fail("unknown comparison '" + op + "'");
    c.comparison = *cmp;
    c.numbers.push_back(a.number(data_type_of(c.type.scalar)));
    c.kind = K::ProbeSsbo;
    return;
  }
  if (a.match({"probe", "atomic", "counter"})) {
    bool buffer = a.match({"buffer"});
    a.numbers(c.numbers, buffer ? 2 : 1, U);
    std::string op = a.word("a comparison");
    std::optional<Comparison> cmp = parse_comparison(op);
    if (!cmp) a.fail("unknown comparison '" + op + "'");
    c.comparison = *cmp;
    c.numbers.push_back(a.number(U));
    c.kind = buffer ? K::ProbeAtomicCounterBuffer : K::ProbeAtomicCounter;
    return;
  }
  c.relative = a.match({"relative"});
  if (!a.match({"probe"})) return;
  bool all = !c.relative && a.match({"all"});
  bool rect = !all && a.match({"rect"});
  int n = channels(a);
  if (n == 0 || (rect && a.peek() == "int")) return;  // probe depth, probe ssbo, rect rgba int...
  if (all) {
    a.numbers(c.numbers, n, F);
    c.kind = K::ProbeAll;
    return;
  }
  if (rect)
    a.tuple(c.numbers, 4, c.relative ? F : I);
  else if (c.relative)
    a.tuple(c.numbers, 2, F);
  else
    a.numbers(c.numbers, 2, F);  // piglit reads these as floats and truncates
  if (c.relative || rect)
    a.tuple(c.numbers, n, F);
  else
    a.numbers(c.numbers, n, F);
  c.kind = rect ? K::ProbeRect : K::Probe;
}

void parse_texture(Args& a, TestCommand& c) {
  if (a.match({"texture", "checkerboard"})) {
    a.numbers(c.numbers, 2, I);
    a.tuple(c.numbers, 2, I);
    a.tuple(c.numbers, 4, F);
    a.tuple(c.numbers, 4, F);
    c.kind = K::TextureCheckerboard;
  } else if (a.match({"texture", "rgbw"})) {
    // "texture rgbw 1D 0", "... 3D", "... 2DArray": other targets, not modelled
    if (!to_integer(a.peek())) return;
    c.numbers.push_back(a.number(I));
    a.tuple(c.numbers, 2, I);
    if (!a.done()) c.words.push_back(a.word("an internal format"));
    c.kind = K::TextureRgbw;
  } else if (a.match({"texparameter"})) {
    while (!a.done()) c.words.push_back(a.word("a texture parameter"));
    if (c.words.size() < 3) a.fail("expected 'texparameter TARGET NAME VALUE'");
    c.kind = K::TexParameter;
  }
}

void parse_uniform(Args& a, TestCommand& c) {
  if (!a.match({"uniform"})) return;
  c.words.push_back(a.word("a type"));
  std::optional<GlslType> type = parse_glsl_type(c.words[0]);
  if (!type) return;  // int64_t, handle, ...
  c.type = *type;
  c.words.push_back(a.word("a uniform name"));
  a.numbers(c.numbers, type->columns * type->rows, data_type_of(type->scalar));
  c.kind = K::Uniform;
}

// Sets c.kind, c.numbers, c.words... when a's words are a command this parser models.
void parse_arguments(Args& a, TestCommand& c) {
  if (a.match({"clear", "color"})) {
    a.numbers(c.numbers, 4, F);
    c.kind = K::ClearColor;
  } else if (a.match({"clear"})) {
    if (a.done()) c.kind = K::Clear;  // "clear depth" stays Unknown
  } else if (a.match({"patch", "parameter", "vertices"})) {
    c.numbers.push_back(a.number(I));
    c.kind = K::PatchVertices;
  } else if (a.match({"patch", "parameter", "default", "level", "outer"})) {
    a.numbers(c.numbers, 4, F);
    c.kind = K::PatchDefaultOuterLevel;
  } else if (a.match({"patch", "parameter", "default", "level", "inner"})) {
    a.numbers(c.numbers, 2, F);
    c.kind = K::PatchDefaultInnerLevel;
  } else if (a.peek() == "draw") {
    parse_draw(a, c);
  } else if (a.peek() == "probe" || a.peek() == "relative") {
    parse_probe(a, c);
  } else if (a.peek() == "texture" || a.peek() == "texparameter") {
    parse_texture(a, c);
  } else if (a.peek() == "uniform") {
    parse_uniform(a, c);
  } else if (a.match({"tolerance"})) {
    while (!a.done()) c.numbers.push_back(a.number(F));
    if (c.numbers.size() != 1 && c.numbers.size() != 4) a.fail("expected 1 or 4 values");
    c.kind = K::Tolerance;
  } else if (a.match({"ssbo"})) {
    c.numbers.push_back(a.number(U));
    if (a.match({"subdata"})) {
      if (!ssbo_type(a, c)) return;
      c.numbers.push_back(a.number(U));
      while (!a.done()) c.numbers.push_back(a.number(data_type_of(c.type.scalar)));
      c.kind = K::SsboSubData;
    } else {
      c.numbers.push_back(a.number(U));
      c.kind = K::SsboSize;
    }
  } else if (a.match({"atomic", "counters"})) {
    c.numbers.push_back(a.number(U));
    c.kind = K::AtomicCounters;
  } else if (a.match({"atomic", "counter", "buffer"})) {
    a.numbers(c.numbers, 2, U);
    c.kind = K::AtomicCounterBuffer;
  } else if (a.match({"atomic", "counter"})) {
    a.numbers(c.numbers, 3, U);
    c.kind = K::AtomicCounterSet;
  } else if (a.match({"enable"})) {
    c.words.push_back(a.word("a capability"));
    c.kind = K::Enable;
  } else if (a.match({"disable"})) {
    c.words.push_back(a.word("a capability"));
    c.kind = K::Disable;
  } else if (a.match({"clip", "plane"})) {
    c.numbers.push_back(a.number(I));
    a.numbers(c.numbers, 4, DataType::Double);
    c.kind = K::ClipPlane;
  } else if (a.match({"ortho"})) {
    if (!a.done()) a.numbers(c.numbers, 4, F);
    c.kind = K::Ortho;
  } else if (a.match({"newlist"})) {
    c.words.push_back(a.word("a list mode"));
    c.kind = K::NewList;
  } else if (a.match({"endlist"})) {
    c.kind = K::EndList;
  } else if (a.match({"calllist"})) {
    c.kind = K::CallList;
  } else if (a.match({"deletelist"})) {
    c.kind = K::DeleteList;
  } else if (a.match({"link", "error"})) {
    c.kind = K::LinkError;
  } else if (a.match({"link", "success"})) {
    c.kind = K::LinkSuccess;
  }
}

TestCommand parse_command(std::string_view text, const Where& at) {
  TestCommand c;
  c.line = at.line;
  c.text = text;
  Args a(split_words(text, true), at);
  parse_arguments(a, c);
  // Words after a command's arguments are ignored, as piglit does ("probe all rgb 1 0 0 0").
  if (c.kind != K::Unknown) return c;
  // Unknown carries the text only: a partly read line leaves nothing behind.
  TestCommand unknown;
  unknown.line = at.line;
  unknown.text = text;
  return unknown;
}

// ---- sections ----

enum class SectionKind { Require, Shader, VertexData, Test, Other };

struct SectionInfo {
  SectionKind kind;
  ShaderStage stage = ShaderStage::Vertex;
  ShaderLanguage language = ShaderLanguage::Glsl;
};

// piglit's section headers (process_test_script in shader_runner.c).
std::optional<SectionInfo> section_info(std::string_view header) {
  using S = ShaderStage;
  using L = ShaderLanguage;
  static constexpr std::pair<std::string_view, S> stages[] = {
      {"vertex", S::Vertex},
      {"tessellation control", S::TessControl},
      {"tessellation evaluation", S::TessEvaluation},
      {"geometry", S::Geometry},
      {"fragment", S::Fragment},
      {"compute", S::Compute}};
  if (header == "[require]") return SectionInfo{SectionKind::Require};
  if (header == "[vertex data]") return SectionInfo{SectionKind::VertexData};
  if (header == "[test]") return SectionInfo{SectionKind::Test};
  if (header == "[vertex shader passthrough]")
    return SectionInfo{SectionKind::Shader, S::Vertex, L::Passthrough};
  if (header == "[vertex program]")
    return SectionInfo{SectionKind::Shader, S::Vertex, L::ArbAssembly};
  if (header == "[fragment program]")
    return SectionInfo{SectionKind::Shader, S::Fragment, L::ArbAssembly};
  if (header == "[geometry layout]" || header == "[shader include]" ||
      header == "[shader include paths]")
    return SectionInfo{SectionKind::Other};
  for (const auto& [name, stage] : stages) {
    std::string base = "[" + std::string(name) + " shader";
    if (header == base + "]") return SectionInfo{SectionKind::Shader, stage, L::Glsl};
    if (header == base + " spirv]") return SectionInfo{SectionKind::Shader, stage, L::Spirv};
    if (header == base + " specializations]") return SectionInfo{SectionKind::Other};
  }
  return std::nullopt;
}

struct Section {
  const std::string& file;
  SectionInfo info;
  std::string_view header;              // trimmed
  int header_line = 0;                  // 1-based
  std::vector<std::string_view> lines;  // the body line by line, without '\n'
  std::string_view body;                // the body verbatim
  Where at(std::size_t k) const { return {file, header_line + 1 + static_cast<int>(k)}; }
};

// A section runs from its header to the next line starting with '[' (as in piglit), except
// [test], which runs to the end of the file. piglit ignores anything before the first header.
std::vector<Section> split_sections(std::string_view text, const std::string& file) {
  std::vector<std::string_view> lines;
  for (std::size_t begin = 0; begin < text.size();) {
    std::size_t end = std::min(text.find('\n', begin), text.size());
    lines.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  std::vector<Section> sections;
  std::size_t i = 0;
  while (i < lines.size() && !lines[i].starts_with('[')) ++i;
  while (i < lines.size()) {
    const int header_line = static_cast<int>(i) + 1;
    std::string_view header = trim(lines[i]);
    std::optional<SectionInfo> info = section_info(header);
    if (!info) fail(file, header_line, "unknown section '" + std::string(header) + "'");
    std::size_t first = ++i;
    while (i < lines.size() && (info->kind == SectionKind::Test || !lines[i].starts_with('['))) ++i;
    std::size_t begin = first < lines.size() ? lines[first].data() - text.data() : text.size();
    std::size_t end = i < lines.size() ? lines[i].data() - text.data() : text.size();
    sections.push_back({file, *info, header, header_line,
                        std::vector<std::string_view>(lines.begin() + first, lines.begin() + i),
                        text.substr(begin, end - begin)});
  }
  return sections;
}

VertexData parse_vertex_data(const Section& s) {
  VertexData d;
  d.first_line = s.header_line + 1;
  for (std::size_t k = 0; k < s.lines.size(); ++k) {
    std::vector<std::string> words = split_words(strip_comment(s.lines[k]), false);
    if (words.empty()) continue;
    if (d.columns.empty()) {
      for (const std::string& w : words) d.columns.push_back(parse_column(w, s.at(k)));
    } else {
      parse_vertex_row(words, s.at(k), d);
    }
  }
  return d;
}

}  // namespace

ShaderTestFile parse_shader_test(const std::string& text, const std::string& file_name) {
  ShaderTestFile f;
  f.file_name = file_name;
  bool seen_require = false;
  for (const Section& s : split_sections(text, file_name)) {
    auto once = [&](bool seen) {
      if (seen) fail(file_name, s.header_line, "a second " + std::string(s.header) + " section");
    };
    switch (s.info.kind) {
      case SectionKind::Require:
        once(seen_require);
        seen_require = true;
        for (std::size_t k = 0; k < s.lines.size(); ++k)
          parse_requirement(s.lines[k], s.at(k), f.requirements);
        break;
      case SectionKind::Shader:
        f.shaders.push_back(
            {s.info.stage, s.info.language, std::string(s.body), s.header_line + 1});
        break;
      case SectionKind::Other:
        f.other_sections.push_back({std::string(s.header), std::string(s.body), s.header_line + 1});
        break;
      case SectionKind::VertexData:
        once(f.vertex_data.has_value());
        f.vertex_data = parse_vertex_data(s);
        break;
      case SectionKind::Test:
        for (std::size_t k = 0; k < s.lines.size(); ++k) {
          std::string_view command = strip_comment(s.lines[k]);
          if (!command.empty()) f.commands.push_back(parse_command(command, s.at(k)));
        }
        break;
    }
  }
  if (!seen_require) fail(file_name, 1, "no [require] section");
  return f;
}

ShaderTestFile load_shader_test(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.is_open() || in.bad()) throw InputError(path + ": cannot read the file");
  return parse_shader_test(text, path);
}

}  // namespace tessref
