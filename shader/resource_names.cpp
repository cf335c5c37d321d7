#include "shader/resource_names.h"

namespace tessref::shader {

Access follow_accessors(const Module& m, NamedValue at, std::string_view head, std::string_view accessors) {
  Access a{at, {}, false, false, {}, 0};
  const auto malformed = [&](std::size_t p) {
    a.why = "'" + std::string(accessors.substr(p)) + "' is not an accessor ([i] or .member)";
    a.malformed = true;
    return a;
  };
  std::string walked(head);
  std::size_t p = 0;
  while (p < accessors.size()) {
    const Type& t = m.type(a.value.type);
    if (accessors[p] == '[') {
      const std::size_t close = accessors.find(']', p);
      const std::string_view digits = close == std::string_view::npos ? "" : accessors.substr(p + 1, close - p - 1);
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) return malformed(p);
      if (t.kind != TypeKind::Array) {
        a.why = walked + " is not an array";
        return a;
      }
      // Past 9 digits an index is past any array's end (and past std::stoul's range).
      const unsigned long i = digits.size() > 9 ? t.count : std::stoul(std::string(digits));
      if (i >= t.count) {
        a.why = walked + " has " + std::to_string(t.count) + " elements";
        a.index_past_end = true, a.index = std::string(digits), a.count = t.count;
        return a;
      }
      a.value = {t.element, a.value.word + std::uint32_t(i) * m.type(t.element).words, t.count - std::uint32_t(i)};
      walked.append("[").append(digits).append("]");
      p = close + 1;
    } else if (accessors[p] == '.') {
      const std::size_t end = accessors.find_first_of(".[", p + 1);
      const std::string member(accessors.substr(p + 1, end == std::string_view::npos ? std::string_view::npos : end - p - 1));
      std::uint32_t k = 0;
      if (t.kind == TypeKind::Struct)
        while (k < t.members.size() && !(m.member_names.count({a.value.type, k}) && m.member_names.at({a.value.type, k}) == member))
          ++k;
      if (t.kind != TypeKind::Struct || k == t.members.size()) {
        a.why = walked + " has no member '" + member + "'";
        return a;
      }
      a.value = {t.members[k], a.value.word + t.member_word[k], 1};
      walked.append(".").append(member);
      p = end == std::string_view::npos ? accessors.size() : end;
    } else {
      return malformed(p);
    }
  }
  return a;
}

}  // namespace tessref::shader
