#include "draw/vertex_format.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/gtc/packing.hpp>

namespace tessref::draw {
namespace {

struct TypeName {
  ComponentType type;
  const char* name;
};
constexpr TypeName kTypes[] = {
    {ComponentType::Byte, "GL_BYTE"},
    {ComponentType::UnsignedByte, "GL_UNSIGNED_BYTE"},
    {ComponentType::Short, "GL_SHORT"},
    {ComponentType::UnsignedShort, "GL_UNSIGNED_SHORT"},
    {ComponentType::Int, "GL_INT"},
    {ComponentType::UnsignedInt, "GL_UNSIGNED_INT"},
    {ComponentType::Fixed, "GL_FIXED"},
    {ComponentType::HalfFloat, "GL_HALF_FLOAT"},
    {ComponentType::Float, "GL_FLOAT"},
    {ComponentType::Double, "GL_DOUBLE"},
    {ComponentType::Int2101010Rev, "GL_INT_2_10_10_10_REV"},
    {ComponentType::UnsignedInt2101010Rev, "GL_UNSIGNED_INT_2_10_10_10_REV"},
    {ComponentType::UnsignedInt10F11F11FRev, "GL_UNSIGNED_INT_10F_11F_11F_REV"},
};

bool is_integer(ComponentType t) {
  return t == ComponentType::Byte || t == ComponentType::UnsignedByte || t == ComponentType::Short ||
         t == ComponentType::UnsignedShort || t == ComponentType::Int || t == ComponentType::UnsignedInt;
}
bool is_signed(ComponentType t) {
  return t == ComponentType::Byte || t == ComponentType::Short || t == ComponentType::Int;
}

// Component i (0-based) of an element, as GL reads it: sign- or zero-extended to 64 bits.
std::int64_t integer_component(ComponentType t, const std::byte* p, int i) {
  switch (t) {
    case ComponentType::Byte: return std::int8_t(p[i]);
    case ComponentType::UnsignedByte: return std::uint8_t(p[i]);
    case ComponentType::Short: { std::int16_t v; std::memcpy(&v, p + 2 * i, 2); return v; }
    case ComponentType::UnsignedShort: { std::uint16_t v; std::memcpy(&v, p + 2 * i, 2); return v; }
    case ComponentType::Int: case ComponentType::Fixed: { std::int32_t v; std::memcpy(&v, p + 4 * i, 4); return v; }
    default: { std::uint32_t v; std::memcpy(&v, p + 4 * i, 4); return v; }
  }
}

int type_bits(ComponentType t) { return int(component_bytes(t)) * 8; }

std::uint32_t bits_of(float f) { return std::bit_cast<std::uint32_t>(f); }

}  // namespace

std::optional<ComponentType> component_type(std::string_view name) {
  for (const TypeName& t : kTypes)
    if (name == t.name) return t.type;
  return std::nullopt;
}

const char* gl_name(ComponentType type) {
  for (const TypeName& t : kTypes)
    if (t.type == type) return t.name;
  return "?";
}

const char* gl_name(AttribPointer p) {
  switch (p) {
    case AttribPointer::Float: return "glVertexAttribPointer";
    case AttribPointer::Integer: return "glVertexAttribIPointer";
    case AttribPointer::Double: return "glVertexAttribLPointer";
  }
  return "?";
}

std::size_t component_bytes(ComponentType t) {
  switch (t) {
    case ComponentType::Byte: case ComponentType::UnsignedByte: return 1;
    case ComponentType::Short: case ComponentType::UnsignedShort: case ComponentType::HalfFloat: return 2;
    case ComponentType::Double: return 8;
    default: return 4;
  }
}

bool is_packed(ComponentType t) {
  return t == ComponentType::Int2101010Rev || t == ComponentType::UnsignedInt2101010Rev ||
         t == ComponentType::UnsignedInt10F11F11FRev;
}

std::size_t element_bytes(const VertexFormat& f) {
  return is_packed(f.type) ? 4 : component_bytes(f.type) * std::size_t(f.size);
}

std::optional<std::string> format_error(const VertexFormat& f) {
  const std::string call = gl_name(f.pointer);
  const std::string type = gl_name(f.type);
  if (f.size < 1 || f.size > 4) return call + ": size must be 1, 2, 3, 4 or GL_BGRA (GL_INVALID_VALUE)";
  switch (f.pointer) {
    case AttribPointer::Integer:
      if (!is_integer(f.type))
        return call + " takes GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT or GL_UNSIGNED_INT, not " +
               type + " (GL_INVALID_ENUM)";
      if (f.bgra) return call + ": size GL_BGRA is allowed with glVertexAttribPointer only (GL_INVALID_VALUE)";
      if (f.normalized) return call + " has no normalized parameter: integers reach the shader unconverted";
      return std::nullopt;
    case AttribPointer::Double:
      if (f.type != ComponentType::Double) return call + " takes GL_DOUBLE only, not " + type + " (GL_INVALID_ENUM)";
      if (f.bgra) return call + ": size GL_BGRA is allowed with glVertexAttribPointer only (GL_INVALID_VALUE)";
      if (f.normalized) return call + " has no normalized parameter";
      return std::nullopt;
    case AttribPointer::Float: break;
  }
  if (f.bgra) {
    if (f.type != ComponentType::UnsignedByte && f.type != ComponentType::Int2101010Rev &&
        f.type != ComponentType::UnsignedInt2101010Rev)
      return call + ": size GL_BGRA needs type GL_UNSIGNED_BYTE, GL_INT_2_10_10_10_REV or "
                    "GL_UNSIGNED_INT_2_10_10_10_REV, not " + type + " (GL_INVALID_OPERATION)";
    if (!f.normalized) return call + ": size GL_BGRA needs normalized GL_TRUE (GL_INVALID_OPERATION)";
  }
  if ((f.type == ComponentType::Int2101010Rev || f.type == ComponentType::UnsignedInt2101010Rev) && f.size != 4)
    return call + ": type " + type + " needs size 4 or GL_BGRA, not " + std::to_string(f.size) + " (GL_INVALID_OPERATION)";
  if (f.type == ComponentType::UnsignedInt10F11F11FRev && f.size != 3)
    return call + ": type " + type + " needs size 3, not " + std::to_string(f.size) + " (GL_INVALID_OPERATION)";
  if (f.normalized && (f.type == ComponentType::Float || f.type == ComponentType::HalfFloat ||
                       f.type == ComponentType::Double || f.type == ComponentType::Fixed ||
                       f.type == ComponentType::UnsignedInt10F11F11FRev))
    return call + ": normalized applies to integer types; GL ignores it for " + type +
           ", so the scene would say something GL does not do (leave it false)";
  return std::nullopt;
}

// GL fixes the formulas but not their rounding (section 2.3.4.1 allows about one ulp). tessref
// rounds as llvmpipe does, which tests/glref/vertex_formats_vs_llvmpipe_test.cpp checks bit for
// bit: the integer converted to float, times the reciprocal rounded to float.
float unsigned_normalized(std::uint32_t c, int bits) {
  if (bits <= 24) return float(c) * float(1.0 / double((1u << bits) - 1u));
  // 32 bits: the top 23 bits as an exact float fraction, scaled by 2^23 / (2^23 - 1).
  const float top = float(c >> 9) * (1.0f / 8388608.0f);
  return top * float(8388608.0 / 8388607.0);
}

float signed_normalized(std::int32_t c, int bits) {
  const float f = float(c) * float(1.0 / double((std::uint64_t(1) << (bits - 1)) - 1));
  return std::max(f, -1.0f);  // GL 4.2's rule: the most negative value is -1 too
}

float half_to_float(std::uint16_t h) { return glm::unpackHalf1x16(h); }
std::uint16_t float_to_half(float f) { return glm::packHalf1x16(f); }

namespace {
float unsigned_small_float(std::uint32_t bits, int mantissa_bits) {
  const std::uint32_t e = bits >> mantissa_bits, m = bits & ((1u << mantissa_bits) - 1u);
  const float scale = float(1u << mantissa_bits);
  if (e == 0) return std::ldexp(float(m) / scale, -14);
  if (e == 31) return m ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  return std::ldexp(1.0f + float(m) / scale, int(e) - 15);
}
}  // namespace

float unsigned_float11(std::uint32_t bits) { return unsigned_small_float(bits & 0x7ffu, 6); }
float unsigned_float10(std::uint32_t bits) { return unsigned_small_float(bits & 0x3ffu, 5); }

AttributeValue convert_element(const VertexFormat& f, const std::byte* p) {
  AttributeValue out;
  if (f.pointer == AttribPointer::Double) {
    out.word_count = 8;
    for (int i = 0; i < 4; ++i) {
      double d = i == 3 ? 1.0 : 0.0;
      if (i < f.size) std::memcpy(&d, p + 8 * i, 8);
      const auto b = std::bit_cast<std::uint64_t>(d);
      out.words[2 * i] = std::uint32_t(b);
      out.words[2 * i + 1] = std::uint32_t(b >> 32);
    }
    return out;
  }
  if (f.pointer == AttribPointer::Integer) {
    out.words = {0, 0, 0, 1};
    for (int i = 0; i < f.size; ++i) out.words[i] = std::uint32_t(integer_component(f.type, p, i));
    return out;
  }
  float v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  if (is_packed(f.type)) {
    std::uint32_t w;
    std::memcpy(&w, p, 4);
    if (f.type == ComponentType::UnsignedInt10F11F11FRev) {
      v[0] = unsigned_float11(w);
      v[1] = unsigned_float11(w >> 11);
      v[2] = unsigned_float10(w >> 22);
    } else {
      const bool is_signed_type = f.type == ComponentType::Int2101010Rev;
      for (int i = 0; i < 4; ++i) {
        const int bits = i == 3 ? 2 : 10;
        const std::uint32_t field = (w >> (10 * i)) & ((1u << bits) - 1u);
        // Sign extension of the field for the signed type.
        const std::int32_t s = is_signed_type && (field >> (bits - 1)) ? std::int32_t(field) - (1 << bits) : std::int32_t(field);
        if (!f.normalized) v[i] = float(s);
        else v[i] = is_signed_type ? signed_normalized(s, bits) : unsigned_normalized(field, bits);
      }
    }
  } else {
    for (int i = 0; i < f.size; ++i) {
      switch (f.type) {
        case ComponentType::Float: std::memcpy(&v[i], p + 4 * i, 4); break;
        case ComponentType::Double: { double d; std::memcpy(&d, p + 8 * i, 8); v[i] = float(d); break; }
        case ComponentType::HalfFloat: { std::uint16_t h; std::memcpy(&h, p + 2 * i, 2); v[i] = half_to_float(h); break; }
        case ComponentType::Fixed: v[i] = float(std::int32_t(integer_component(f.type, p, i))) / 65536.0f; break;
        default: {
          const std::int64_t c = integer_component(f.type, p, i);
          if (!f.normalized) v[i] = float(c);
          else if (is_signed(f.type)) v[i] = signed_normalized(std::int32_t(c), type_bits(f.type));
          else v[i] = unsigned_normalized(std::uint32_t(c), type_bits(f.type));
        }
      }
    }
  }
  // GL_BGRA: the element's first component is blue (z), its third red (x).
  if (f.bgra) std::swap(v[0], v[2]);
  for (int i = 0; i < 4; ++i) out.words[i] = bits_of(v[i]);
  return out;
}

}  // namespace tessref::draw
