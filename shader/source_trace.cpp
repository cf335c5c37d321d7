#include "shader/source_trace.h"

#include <cstdio>
#include <cstring>

namespace tessref::shader {
namespace {

thread_local SourceTrace* tl_source_trace = nullptr;

std::string scalar_text(Scalar s, std::uint64_t bits) {
  char buf[40];
  switch (s) {
    case Scalar::F32: {
      float f;
      const auto w = std::uint32_t(bits);
      std::memcpy(&f, &w, sizeof f);
      std::snprintf(buf, sizeof buf, "%.9g", double(f));  // reads back as the same bits
      return buf;
    }
    case Scalar::F64: {
      double d;
      std::memcpy(&d, &bits, sizeof d);
      std::snprintf(buf, sizeof buf, "%.17g", d);
      return buf;
    }
    case Scalar::I32: return std::to_string(std::int32_t(std::uint32_t(bits)));
    case Scalar::U32: return std::to_string(std::uint32_t(bits)) + "u";
    case Scalar::Bool: return bits ? "true" : "false";
    default: return "?";
  }
}

const char* component_name(std::uint32_t i) {
  static const char* names[] = {".x", ".y", ".z", ".w"};
  return i < 4 ? names[i] : "";
}

}  // namespace

std::string TraceValue::component_text(std::size_t i) const { return scalar_text(scalars[i], bits[i]); }

std::string TraceValue::text() const {
  if (scalars.size() == 1) return component_text(0);
  std::string s = "(";
  for (std::size_t i = 0; i < scalars.size(); ++i) {
    if (i) s += ", ";
    s += component_text(i);
  }
  return s + ")";
}

SourceTraceScope::SourceTraceScope(SourceTrace& trace) : previous_(tl_source_trace) { tl_source_trace = &trace; }
SourceTraceScope::~SourceTraceScope() { tl_source_trace = previous_; }
SourceTrace* current_source_trace() { return tl_source_trace; }

std::string access_path(const Module& m, std::uint32_t type, std::uint32_t offset, std::uint32_t words) {
  std::string path;
  for (int depth = 0; depth < 16; ++depth) {
    const Type& t = m.type(type);
    if (offset == 0 && words >= t.words) return path;  // the whole value
    switch (t.kind) {
      case TypeKind::Struct: {
        std::size_t k = t.members.size();
        while (k > 0 && t.member_word[k - 1] > offset) --k;
        if (k == 0) return path;
        --k;
        auto name = m.member_names.find({type, std::uint32_t(k)});
        path += "." + (name != m.member_names.end() && !name->second.empty() ? name->second
                                                                          : "member " + std::to_string(k));
        offset -= t.member_word[k];
        type = t.members[k];
        break;
      }
      case TypeKind::Array:
      case TypeKind::Matrix: {
        const std::uint32_t element = m.type(t.element).words;
        if (element == 0) return path;
        path += "[" + std::to_string(offset / element) + "]";
        offset %= element;
        type = t.element;
        break;
      }
      case TypeKind::Vector: {
        const std::uint32_t w = std::uint32_t(scalar_words(t.scalar));
        if (words > w) {  // a run of components
          path += "[" + std::to_string(offset / w) + ".." + std::to_string((offset + words) / w - 1) + "]";
          return path;
        }
        return path + component_name(offset / w);
      }
      default:
        return path;
    }
  }
  return path;
}

}  // namespace tessref::shader
