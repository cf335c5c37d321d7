#include "draw/vertex_fetch.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include "common/error.h"

namespace tessref::draw {
namespace {

std::string bytes_range(std::uint64_t begin, std::uint64_t end) {
  return "bytes [" + std::to_string(begin) + ", " + std::to_string(end) + ")";
}

std::size_t stride_of(const VertexArray& a) { return a.stride ? a.stride : element_bytes(a.format); }

// The element `e` of array `a`, converted; zero bytes where robust access allows a read past the end.
AttributeValue read_element(std::span<const Buffer> buffers, const VertexArray& a, std::uint64_t e,
                            const FetchRules& rules, const char* what, std::uint64_t which) {
  const Buffer& b = buffers[a.buffer];
  const std::size_t size = element_bytes(a.format);
  // offset < 2^48 (the scene format's limit), e < 2^32 and stride <= 2048: no overflow.
  const std::uint64_t begin = std::uint64_t(a.offset) + e * stride_of(a);
  if (begin + size > b.bytes.size()) {
    if (!rules.robust_buffer_access)
      throw InputError(a.key + ": " + what + " " + std::to_string(which) + " reads " +
                       bytes_range(begin, begin + size) + " of buffer '" + b.name + "', which holds " +
                       std::to_string(b.bytes.size()) + " bytes (GL leaves such a read undefined; with "
                       "robust_buffer_access it reads zero, as a robust context may)");
    const std::byte zero[32] = {};
    return convert_element(a.format, zero);
  }
  return convert_element(a.format, b.bytes.data() + begin);
}

// Appends the attribute(s) an element of `a` feeds: a dvec3/dvec4 fills two locations.
void append_words(const AttributeValue& v, std::vector<glsl::VertexAttribute>& attrs,
                  std::size_t first_attr) {
  for (int half = 0; half * 4 < v.word_count; ++half)
    for (int w = 0; w < 4; ++w) attrs[first_attr + std::size_t(half)].words.push_back(v.words[std::size_t(4 * half + w)]);
}

std::size_t start_attributes(const VertexArray& a, std::vector<glsl::VertexAttribute>& attrs, bool constant) {
  const std::size_t first = attrs.size();
  const int locations = a.format.pointer == AttribPointer::Double && a.format.size > 2 ? 2 : 1;
  for (int l = 0; l < locations; ++l) {
    glsl::VertexAttribute out;
    out.location = a.location + std::uint32_t(l);
    out.components = 4;
    out.scalar = a.format.pointer == AttribPointer::Double  ? shader::Scalar::F64
                 : a.format.pointer == AttribPointer::Integer ? (a.format.type == ComponentType::Byte ||
                                                                 a.format.type == ComponentType::Short ||
                                                                 a.format.type == ComponentType::Int
                                                                     ? shader::Scalar::I32
                                                                     : shader::Scalar::U32)
                                                              : shader::Scalar::F32;
    out.constant = constant;
    attrs.push_back(std::move(out));
  }
  return first;
}

}  // namespace

std::size_t index_bytes(IndexType t) {
  return t == IndexType::UnsignedByte ? 1 : t == IndexType::UnsignedShort ? 2 : 4;
}

const char* gl_name(IndexType t) {
  return t == IndexType::UnsignedByte ? "GL_UNSIGNED_BYTE" : t == IndexType::UnsignedShort ? "GL_UNSIGNED_SHORT" : "GL_UNSIGNED_INT";
}

VertexInput fetch_vertices(std::span<const Buffer> buffers, std::span<const VertexArray> arrays,
                           const std::optional<ElementArray>& elements, const PrimitiveRestart& restart,
                           const DrawCall& call, const FetchRules& rules) {
  VertexInput in;
  in.runs.emplace_back();
  if (!elements) {
    // glDrawArrays: no restart (GL applies it to the commands that take an index type only).
    if (call.first + call.count > 0x80000000ull)
      throw InputError("draw: first + count (" + std::to_string(call.first + call.count) +
                       ") puts gl_VertexID past 2^31 - 1");
    in.vertex_ids.resize(call.count);
    in.runs[0].resize(call.count);
    for (std::size_t k = 0; k < call.count; ++k) {
      in.vertex_ids[k] = std::uint32_t(call.first + k);
      in.runs[0][k] = std::uint32_t(k);
    }
  } else {
    const Buffer& b = buffers[elements->buffer];
    const std::size_t isize = index_bytes(elements->type);
    const std::uint64_t end = std::uint64_t(elements->offset) + std::uint64_t(call.count) * isize;  // both < 2^48
    if (end > b.bytes.size())
      throw InputError(elements->key + ": " + std::to_string(call.count) + " " + gl_name(elements->type) +
                       " indices from byte " + std::to_string(elements->offset) + " need " +
                       std::to_string(end) + " bytes; buffer '" + b.name + "' holds " +
                       std::to_string(b.bytes.size()));
    const std::uint32_t restart_index =
        restart.fixed_index ? std::uint32_t((std::uint64_t(1) << (8 * isize)) - 1) : restart.index;
    std::unordered_map<std::int64_t, std::uint32_t> position;  // gl_VertexID -> slot in vertex_ids
    position.reserve(call.count);
    const std::byte* p = b.bytes.data() + elements->offset;
    for (std::size_t k = 0; k < call.count; ++k) {
      std::uint32_t index = 0;
      std::memcpy(&index, p + k * isize, isize);  // little-endian: the low bytes
      if (restart.enabled && index == restart_index) {
        if (!in.runs.back().empty()) in.runs.emplace_back();
        continue;
      }
      const std::int64_t id = std::int64_t(index) + call.base_vertex;
      if (id < 0 || id > 0x7fffffff)
        throw InputError(elements->key + ": index " + std::to_string(index) + " (element " + std::to_string(k) +
                         ") plus basevertex " + std::to_string(call.base_vertex) +
                         " is outside 0..2^31 - 1 (GL leaves it undefined)");
      const auto [it, added] = position.try_emplace(id, std::uint32_t(in.vertex_ids.size()));
      if (added) in.vertex_ids.push_back(std::uint32_t(id));
      in.runs.back().push_back(it->second);
    }
    if (in.runs.size() > 1 && in.runs.back().empty()) in.runs.pop_back();
  }

  for (std::size_t i = 0; i < arrays.size(); ++i) {
    const VertexArray& a = arrays[i];
    if (a.enabled && a.divisor != 0) {
      in.instanced.push_back(i);
      continue;
    }
    const std::size_t first = start_attributes(a, in.per_vertex, !a.enabled);
    if (!a.enabled) {
      append_words(a.current, in.per_vertex, first);
      continue;
    }
    for (std::size_t k = first; k < in.per_vertex.size(); ++k) in.per_vertex[k].words.reserve(4 * in.vertex_ids.size());
    for (const std::uint32_t id : in.vertex_ids)
      append_words(read_element(buffers, a, id, rules, "gl_VertexID", id), in.per_vertex, first);
  }
  return in;
}

void fetch_instanced(std::span<const Buffer> buffers, std::span<const VertexArray> arrays,
                     const VertexInput& input, const DrawCall& call, std::uint32_t instance,
                     const FetchRules& rules, std::vector<glsl::VertexAttribute>& out) {
  for (const std::size_t i : input.instanced) {
    const VertexArray& a = arrays[i];
    const std::uint64_t element = std::uint64_t(instance / a.divisor) + call.base_instance;
    const std::size_t first = start_attributes(a, out, true);
    append_words(read_element(buffers, a, element, rules, "instance", instance), out, first);
  }
}

}  // namespace tessref::draw
