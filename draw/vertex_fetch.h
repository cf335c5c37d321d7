#pragma once
// GL's vertex pulling for one draw call: the element array (with primitive restart and the base
// vertex), the vertices the vertex shader runs for, each one's gl_VertexID, and the attribute
// arrays read through their formats, strides, offsets and instance divisors (GL 4.5 core,
// sections 10.3 and 10.4).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "draw/vertex_format.h"
#include "stages/glsl/glsl_program.h"

namespace tessref::draw {

// A buffer object's data store, as the application uploaded it.
struct Buffer {
  std::string name;  // for messages
  std::vector<std::byte> bytes;
};

// One generic vertex attribute: an enabled array (glVertexAttrib*Pointer + glEnableVertexAttribArray
// + glVertexAttribDivisor) or, when disabled, the current value (glVertexAttrib4f, I4i, I4ui, L4d).
struct VertexArray {
  std::string key;  // the scene key that gave it, for messages
  std::uint32_t location = 0;
  bool enabled = true;
  VertexFormat format;
  std::size_t buffer = 0;      // index into the draw's buffers
  std::size_t stride = 0;      // bytes; 0: tightly packed (element_bytes)
  std::size_t offset = 0;      // the pointer argument: a byte offset into the buffer
  std::uint32_t divisor = 0;   // 0: per vertex; N: one element per N instances
  AttributeValue current;      // disabled: the value every vertex reads
};

enum class IndexType { UnsignedByte, UnsignedShort, UnsignedInt };
std::size_t index_bytes(IndexType t);
const char* gl_name(IndexType t);

struct ElementArray {
  std::string key;
  std::size_t buffer = 0;
  IndexType type = IndexType::UnsignedInt;
  std::size_t offset = 0;  // the indices argument: a byte offset into the element buffer
};

// GL_PRIMITIVE_RESTART (any index) or GL_PRIMITIVE_RESTART_FIXED_INDEX (the type's largest).
struct PrimitiveRestart {
  bool enabled = false;
  bool fixed_index = false;
  std::uint32_t index = 0;
};

// One of glDrawArraysInstancedBaseInstance / glDrawElementsInstancedBaseVertexBaseInstance (the
// plain, instanced, base-vertex, multi and indirect forms are special cases or lists of it).
struct DrawCall {
  std::size_t first = 0;           // arrays: the first vertex
  std::size_t count = 0;           // vertices (arrays) or indices (elements)
  std::uint32_t instance_count = 1;
  std::int64_t base_vertex = 0;    // elements: added to every index (after the restart test)
  std::uint32_t base_instance = 0;
};

// GL's robust buffer access (a context with GL_CONTEXT_FLAG_ROBUST_ACCESS_BIT): a fetch outside
// the buffer reads zero bytes instead of being an error. Without it GL leaves such a read
// undefined, and tessref refuses the draw.
struct FetchRules {
  bool robust_buffer_access = false;
};

// What the vertex stage reads for one call: vertex k of the batch has gl_VertexID vertex_ids[k];
// primitives take their vertices by position in that list.
struct VertexInput {
  std::vector<std::uint32_t> vertex_ids;
  // The primitives' vertices, already split at restart indices: each entry lists one restarted
  // run of positions (one run when restart is off, or for glDrawArrays).
  std::vector<std::vector<std::uint32_t>> runs;
  std::vector<glsl::VertexAttribute> per_vertex;  // divisor 0 and disabled arrays
  std::vector<std::size_t> instanced;             // indices of the arrays with a divisor
};

// Reads the element array (when `elements` is set) and the per-vertex attribute arrays. InputError
// naming the array's key for a fetch past a buffer's end (unless robust), an index past the end of
// the element buffer, or gl_VertexID outside 0..2^31-1.
VertexInput fetch_vertices(std::span<const Buffer> buffers, std::span<const VertexArray> arrays,
                           const std::optional<ElementArray>& elements, const PrimitiveRestart& restart,
                           const DrawCall& call, const FetchRules& rules = {});

// The attribute arrays with a divisor for instance `instance` (0-based; the element read is
// instance / divisor + base_instance), appended to `out` as constant attributes.
void fetch_instanced(std::span<const Buffer> buffers, std::span<const VertexArray> arrays,
                     const VertexInput& input, const DrawCall& call, std::uint32_t instance,
                     const FetchRules& rules, std::vector<glsl::VertexAttribute>& out);

}  // namespace tessref::draw
