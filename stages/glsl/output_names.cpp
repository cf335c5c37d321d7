#include "stages/glsl/output_names.h"

#include <cctype>
#include <stdexcept>

namespace tessref::glsl {
namespace {

// "s.member[2]" -> the base name and its accessors: a member name, or an index as digits.
struct Accessor {
  std::string member;  // empty: an index
  std::uint32_t index = 0;
};

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

void parse(const std::string& name, std::string& base, std::vector<Accessor>& path) {
  const auto bad = [&name] { return std::invalid_argument("'" + name + "' is not an output name (NAME, NAME[i], NAME.member)"); };
  std::size_t i = name.find_first_of(".[");
  base = name.substr(0, i);
  if (!is_identifier(base)) throw bad();
  while (i < name.size()) {
    if (name[i] == '.') {
      const std::size_t end = name.find_first_of(".[", i + 1);
      Accessor a;
      a.member = name.substr(i + 1, end == std::string::npos ? std::string::npos : end - i - 1);
      if (!is_identifier(a.member)) throw bad();
      path.push_back(a);
      i = end == std::string::npos ? name.size() : end;
    } else {
      const std::size_t close = name.find(']', i);
      const std::string digits = close == std::string::npos ? "" : name.substr(i + 1, close - i - 1);
      if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) throw bad();
      path.push_back({{}, std::uint32_t(std::stoul(digits))});
      i = close + 1;
    }
  }
}

// A built-in output: its I/O words (gl_Position's four, gl_PointSize, the distance arrays).
std::vector<int> builtin_floats(const VaryingLayout& layout, const std::string& name, const std::string& base,
                                const std::vector<Accessor>& path) {
  const auto floats = [&](std::uint32_t first, int count) {
    std::vector<int> out;
    for (int k = 0; k < count; ++k) out.push_back(layout.float_of(first + std::uint32_t(k)));
    return out;
  };
  if (base == "gl_Position" && path.empty()) return floats(0, 4);
  if (base == "gl_PointSize" && path.empty()) {
    if (!layout.point_size) throw std::invalid_argument("'gl_PointSize' is not written by the stage");
    return floats(kPointSizeWord, 1);
  }
  if ((base == "gl_ClipDistance" || base == "gl_CullDistance") && path.size() <= 1 && (path.empty() || path[0].member.empty())) {
    const bool clip = base == "gl_ClipDistance";
    const int size = clip ? layout.clip : layout.cull;
    if (size == 0) throw std::invalid_argument("'" + base + "' is not written by the stage");
    if (path.empty()) return floats(clip ? kClipDistanceWord : kCullDistanceWord, size);
    if (path[0].index >= std::uint32_t(size))
      throw std::invalid_argument("'" + name + "': the stage's " + base + " has " + std::to_string(size) + " elements");
    return floats((clip ? kClipDistanceWord : kCullDistanceWord) + path[0].index, 1);
  }
  throw std::invalid_argument("'" + name + "' is not a built-in output transform feedback records (gl_Position, "
                              "gl_PointSize, gl_ClipDistance, gl_CullDistance)");
}

}  // namespace

OutputWords output_floats(const StageProgram& last, const VaryingLayout& layout, const std::string& name) {
  std::string base;
  std::vector<Accessor> path;
  parse(name, base, path);
  if (base.rfind("gl_", 0) == 0) return {builtin_floats(layout, name, base, path), 0};
  const shader::Module& m = last.exe->module();
  const char* stage = shader::stage_name(last.stage);
  for (const IoVariable& v : last.io.outputs) {
    if (v.kind != IoKind::User || !v.variable) continue;
    std::uint32_t type = v.variable->type;
    // A block's members are named by the block's name (GL 4.5, 7.3.1.1), a variable by its own.
    const bool block = m.type_decorations.count(type) && m.type_decorations.at(type).block;
    if ((block ? m.name_of(type) : v.variable->name) != base) continue;
    if (block && (path.empty() || path[0].member.empty()))
      throw std::invalid_argument("'" + name + "': a block is recorded member by member ('" + base + ".member')");
    std::uint32_t first = 0;
    std::string walked = base;
    int stream = int(v.variable->decorations.stream.value_or(0));
    for (const Accessor& a : path) {
      const shader::Type& t = m.type(type);
      if (a.member.empty()) {
        if (t.kind != shader::TypeKind::Array)
          throw std::invalid_argument("'" + name + "': " + walked + " is not an array");
        if (a.index >= t.count)
          throw std::invalid_argument("'" + name + "': " + walked + " has " + std::to_string(t.count) + " elements");
        first += a.index * m.type(t.element).words;
        type = t.element;
        walked.append("[").append(std::to_string(a.index)).append("]");
        continue;
      }
      std::size_t k = 0;
      while (k < t.members.size() && !(t.kind == shader::TypeKind::Struct && m.member_names.count({type, std::uint32_t(k)}) &&
                                       m.member_names.at({type, std::uint32_t(k)}) == a.member))
        ++k;
      if (t.kind != shader::TypeKind::Struct || k == t.members.size())
        throw std::invalid_argument("'" + name + "': " + walked + " has no member '" + a.member + "'");
      first += t.member_word[k];
      if (block && walked == base && k < v.variable->member_decorations.size())
        stream = int(v.variable->member_decorations[k].stream.value_or(std::uint32_t(stream)));
      type = t.members[k];
      walked.append(".").append(a.member);
    }
    const std::uint32_t end = first + m.type(type).words;
    OutputWords out{std::vector<int>(end - first, -1), stream};
    for (const IoWord& w : v.words)
      for (int h = 0; h < shader::scalar_words(w.scalar); ++h)
        if (w.var_word + std::uint32_t(h) >= first && w.var_word + std::uint32_t(h) < end)
          out.floats[w.var_word + std::uint32_t(h) - first] = layout.float_of(w.io_word + std::uint32_t(h));
    return out;
  }
  throw std::invalid_argument("'" + name + "' is not an output of the " + std::string(stage) +
                              " (the last stage before the rasterizer)");
}

}  // namespace tessref::glsl
