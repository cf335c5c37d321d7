#pragma once
// Vertex attribute formats as glVertexAttribPointer, glVertexAttribIPointer and
// glVertexAttribLPointer describe them, GL's rules on which combinations are legal, and the
// conversion of one element's bytes into the words the vertex shader reads (GL 4.5 core,
// sections 10.2 and 10.3, table 10.3).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tessref::draw {

enum class ComponentType {
  Byte, UnsignedByte, Short, UnsignedShort, Int, UnsignedInt, Fixed, HalfFloat, Float, Double,
  Int2101010Rev, UnsignedInt2101010Rev, UnsignedInt10F11F11FRev,
};

// Which entry point specified the array: the shader input it may feed and how values convert.
enum class AttribPointer {
  Float,    // glVertexAttribPointer: float inputs; integers converted (normalized or not)
  Integer,  // glVertexAttribIPointer: int/uint inputs; integers kept as integers
  Double,   // glVertexAttribLPointer: double inputs, 64 bits kept
};

struct VertexFormat {
  int size = 4;       // components, 1..4 (GL_BGRA: 4, with bgra set)
  bool bgra = false;  // size GL_BGRA: the element stores B, G, R, A
  ComponentType type = ComponentType::Float;
  bool normalized = false;
  AttribPointer pointer = AttribPointer::Float;
};

// "GL_FLOAT" <-> ComponentType; nullopt for a name that is not a vertex attribute type.
std::optional<ComponentType> component_type(std::string_view gl_name);
const char* gl_name(ComponentType t);
const char* gl_name(AttribPointer p);  // "glVertexAttribPointer", ...

// Bytes of one component (of the whole 32-bit word for the packed types).
std::size_t component_bytes(ComponentType t);
bool is_packed(ComponentType t);  // the 2_10_10_10 and 10F_11F_11F types: one word per element
// Bytes of one element: the stride GL uses when the given stride is 0.
std::size_t element_bytes(const VertexFormat& f);

// The rule GL's call would break with this format, stated with the GL error it raises; nullopt
// when GL accepts it. GL ignores `normalized` for floating-point types; a scene that sets it is
// refused too, because it says something GL would not do.
std::optional<std::string> format_error(const VertexFormat& f);

// GL_MAX_VERTEX_ATTRIB_STRIDE (GL 4.4's minimum, which Mesa reports): larger strides are
// GL_INVALID_VALUE.
inline constexpr std::size_t kMaxVertexAttribStride = 2048;

// One element converted: four components (GL fills missing y, z with 0 and w with 1), as 32-bit
// words (float bits, or int/uint bits for glVertexAttribIPointer), or eight words for
// glVertexAttribLPointer (each double low word first).
struct AttributeValue {
  std::array<std::uint32_t, 8> words{};
  int word_count = 4;
};

// Converts the element at `bytes` (element_bytes(f) of them, little-endian). f must be legal.
AttributeValue convert_element(const VertexFormat& f, const std::byte* bytes);

// The conversions on their own, for tests and the inline-data encoder.
float unsigned_normalized(std::uint32_t c, int bits);  // c / (2^b - 1)
float signed_normalized(std::int32_t c, int bits);     // max(c / (2^(b-1) - 1), -1): GL 4.2's rule
float half_to_float(std::uint16_t h);
std::uint16_t float_to_half(float f);  // round to nearest even; for writing inline buffer data
float unsigned_float11(std::uint32_t bits);  // 5-bit exponent, 6-bit mantissa
float unsigned_float10(std::uint32_t bits);  // 5-bit exponent, 5-bit mantissa

}  // namespace tessref::draw
