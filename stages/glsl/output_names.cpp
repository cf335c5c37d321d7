#include "stages/glsl/output_names.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string_view>

#include "shader/resource_names.h"

namespace tessref::glsl {
namespace {

bool is_identifier(std::string_view s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

std::invalid_argument not_a_name(const std::string& name) {
  return std::invalid_argument("'" + name + "' is not an output name (NAME, NAME[i], NAME.member)");
}

// A built-in output: its I/O words (gl_Position's four, gl_PointSize, the distance arrays).
std::vector<int> builtin_floats(const VaryingLayout& layout, const std::string& name, const std::string& base,
                                std::string_view accessors) {
  const auto floats = [&](std::uint32_t first, int count) {
    std::vector<int> out;
    for (int k = 0; k < count; ++k) out.push_back(layout.float_of(first + std::uint32_t(k)));
    return out;
  };
  if (base == "gl_Position" && accessors.empty()) return floats(0, 4);
  if (base == "gl_PointSize" && accessors.empty()) {
    if (!layout.point_size) throw std::invalid_argument("'gl_PointSize' is not written by the stage");
    return floats(kPointSizeWord, 1);
  }
  if ((base == "gl_ClipDistance" || base == "gl_CullDistance") && (accessors.empty() || accessors[0] == '[')) {
    const bool clip = base == "gl_ClipDistance";
    const int size = clip ? layout.clip : layout.cull;
    const std::uint32_t first = clip ? kClipDistanceWord : kCullDistanceWord;
    if (size == 0) throw std::invalid_argument("'" + base + "' is not written by the stage");
    if (accessors.empty()) return floats(first, size);
    const std::string_view digits = accessors.substr(1, accessors.size() - 2);
    if (accessors.back() != ']' || digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string_view::npos)
      throw not_a_name(name);
    if (std::stoul(std::string(digits)) >= std::size_t(size))
      throw std::invalid_argument("'" + name + "': the stage's " + base + " has " + std::to_string(size) + " elements");
    return floats(first + std::uint32_t(std::stoul(std::string(digits))), 1);
  }
  throw std::invalid_argument("'" + name + "' is not a built-in output transform feedback records (gl_Position, "
                              "gl_PointSize, gl_ClipDistance, gl_CullDistance)");
}

}  // namespace

OutputWords output_floats(const StageProgram& last, const VaryingLayout& layout, const std::string& name) {
  const std::size_t head = std::min(name.find_first_of(".["), name.size());
  const std::string base = name.substr(0, head);
  const std::string_view accessors = std::string_view(name).substr(head);
  if (!is_identifier(base)) throw not_a_name(name);
  if (base.rfind("gl_", 0) == 0) return {builtin_floats(layout, name, base, accessors), 0};
  const shader::Module& m = last.exe->module();
  for (const IoVariable& v : last.io.outputs) {
    if (v.kind != IoKind::User || !v.variable) continue;
    const std::uint32_t type = v.variable->type;
    // A block's members are named by the block's name (GL 4.5, 7.3.1.1), a variable by its own.
    const bool block = m.type_decorations.count(type) && m.type_decorations.at(type).block;
    if ((block ? m.name_of(type) : v.variable->name) != base) continue;
    if (block && (accessors.empty() || accessors[0] != '.'))
      throw std::invalid_argument("'" + name + "': a block is recorded member by member ('" + base + ".member')");
    const shader::Access a = shader::follow_accessors(m, {type, 0, 1}, base, accessors);
    if (a.malformed) throw not_a_name(name);
    if (!a.why.empty()) throw std::invalid_argument("'" + name + "': " + a.why);
    int stream = int(v.variable->decorations.stream.value_or(0));
    if (block) {  // a block member's own layout(stream = N)
      const std::string member(accessors.substr(1, accessors.find_first_of(".[", 1) - 1));
      for (std::uint32_t k = 0; k < v.variable->member_decorations.size(); ++k)
        if (m.member_names.count({type, k}) && m.member_names.at({type, k}) == member)
          stream = int(v.variable->member_decorations[k].stream.value_or(std::uint32_t(stream)));
    }
    const std::uint32_t first = a.value.word, end = first + m.type(a.value.type).words;
    OutputWords out{std::vector<int>(end - first, -1), stream};
    for (const IoWord& w : v.words)
      for (int h = 0; h < shader::scalar_words(w.scalar); ++h)
        if (w.var_word + std::uint32_t(h) >= first && w.var_word + std::uint32_t(h) < end)
          out.floats[w.var_word + std::uint32_t(h) - first] = layout.float_of(w.io_word + std::uint32_t(h));
    return out;
  }
  throw std::invalid_argument("'" + name + "' is not an output of the " + std::string(shader::stage_name(last.stage)) +
                              " (the last stage before the rasterizer)");
}

}  // namespace tessref::glsl
