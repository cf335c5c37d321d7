#include "scene/draw_schema.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "scene/raster_state_schema.h"
#include "scene/scene_schema.h"

namespace tessref {

std::size_t TransformFeedbackSetting::buffers() const {
  if (separate) return varyings.size();
  return 1 + std::size_t(std::count(varyings.begin(), varyings.end(), "gl_NextBuffer"));
}

std::optional<DrawMode> draw_mode_named(const std::string& gl_name) {
  static const std::pair<const char*, DrawMode> kNames[] = {
      {"GL_PATCHES", DrawMode::Patches},         {"GL_TRIANGLES", DrawMode::Triangles},
      {"GL_TRIANGLE_STRIP", DrawMode::TriangleStrip}, {"GL_TRIANGLE_FAN", DrawMode::TriangleFan},
      {"GL_LINES", DrawMode::Lines},             {"GL_LINE_STRIP", DrawMode::LineStrip},
      {"GL_LINE_LOOP", DrawMode::LineLoop},      {"GL_POINTS", DrawMode::Points},
      {"GL_LINES_ADJACENCY", DrawMode::LinesAdjacency}, {"GL_LINE_STRIP_ADJACENCY", DrawMode::LineStripAdjacency},
      {"GL_TRIANGLES_ADJACENCY", DrawMode::TrianglesAdjacency},
      {"GL_TRIANGLE_STRIP_ADJACENCY", DrawMode::TriangleStripAdjacency}};
  for (const auto& [name, mode] : kNames)
    if (gl_name == name) return mode;
  return std::nullopt;
}

namespace {

using nlohmann::json;
using draw::AttribPointer;
using draw::ComponentType;

constexpr std::int64_t kMaxOffset = std::int64_t(1) << 48;  // byte offsets and counts
constexpr std::int64_t kMaxCount = 0x7fffffff;                // GLsizei

const char* const kAttribTypes =
    "GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FIXED, GL_HALF_FLOAT, "
    "GL_FLOAT, GL_DOUBLE, GL_INT_2_10_10_10_REV, GL_UNSIGNED_INT_2_10_10_10_REV, GL_UNSIGNED_INT_10F_11F_11F_REV";

ComponentType attrib_type(JsonObject& o, const std::string& key) {
  o.describe(key, std::string("one of ") + kAttribTypes);
  const std::string s = o.string(key);
  const auto t = draw::component_type(s);
  if (!t) o.fail(key, "expected one of " + std::string(kAttribTypes) + ", got \"" + s + "\"");
  return *t;
}

// The numbers of an inline array (nested arrays flattened), each stored as `type`.
void encode_inline(JsonObject& o, const json& data, ComponentType type, std::vector<std::byte>& out) {
  const std::size_t bytes = draw::component_bytes(type);
  std::size_t index = 0;
  auto put = [&](const json& v, auto&& self) -> void {
    if (v.is_array()) {
      for (const json& e : v) self(e, self);
      return;
    }
    const std::string where = "data[" + std::to_string(index) + "]";
    if (!v.is_number()) o.fail("data", where + ": expected a number, got " + describe_json(v));
    const double d = v.get<double>();
    std::byte b[8] = {};
    auto integral = [&](double lo, double hi) {
      if (!(d == std::floor(d) && d >= lo && d <= hi))
        o.fail("data", where + ": " + format_number(d) + " is not a " + draw::gl_name(type) + " (an integer in [" +
                           format_number(lo) + ", " + format_number(hi) + "])");
    };
    switch (type) {
      case ComponentType::Byte: integral(-128, 127); b[0] = std::byte(std::int8_t(d)); break;
      case ComponentType::UnsignedByte: integral(0, 255); b[0] = std::byte(std::uint8_t(d)); break;
      case ComponentType::Short: { integral(-32768, 32767); const auto x = std::int16_t(d); std::memcpy(b, &x, 2); break; }
      case ComponentType::UnsignedShort: { integral(0, 65535); const auto x = std::uint16_t(d); std::memcpy(b, &x, 2); break; }
      case ComponentType::Int: case ComponentType::Fixed: {
        integral(-2147483648.0, 2147483647.0);
        const auto x = std::int32_t(d);
        std::memcpy(b, &x, 4);
        break;
      }
      case ComponentType::HalfFloat: { const std::uint16_t h = draw::float_to_half(float(d)); std::memcpy(b, &h, 2); break; }
      case ComponentType::Float: {
        const auto f = float(d);
        if (!std::isfinite(f)) o.fail("data", where + ": " + format_number(d) + " overflows single precision");
        std::memcpy(b, &f, 4);
        break;
      }
      case ComponentType::Double: std::memcpy(b, &d, 8); break;
      default: { integral(0, 4294967295.0); const auto x = std::uint32_t(d); std::memcpy(b, &x, 4); }  // packed words
    }
    out.insert(out.end(), b, b + bytes);
    ++index;
  };
  put(data, put);
}

BufferSetting read_buffer(JsonObject o, const std::string& name, const std::filesystem::path& base_dir) {
  BufferSetting b;
  b.name = name;
  o.describe("file", "a file of raw bytes (the buffer's data store), relative to the scene file");
  o.describe("data", "an array of numbers, stored as `type` (little-endian): the buffer written inline");
  const bool file = o.has("file"), data = o.has("data");
  if (file == data) o.fail(file ? "data" : "file", "give exactly one of file and data");
  if (file) {
    const std::filesystem::path p = o.string("file");
    b.file = p.is_relative() ? base_dir / p : p;
  } else {
    const ComponentType type = attrib_type(o, "type");
    encode_inline(o, o.value("data"), type, b.data);
  }
  o.finish();
  return b;
}

std::size_t buffer_index(JsonObject& o, const std::string& key, const std::vector<BufferSetting>& buffers) {
  o.describe(key, "the name of one of the scene's buffers");
  const std::string name = o.string(key);
  for (std::size_t i = 0; i < buffers.size(); ++i)
    if (buffers[i].name == name) return i;
  std::string names;
  for (const BufferSetting& b : buffers) names += (names.empty() ? "" : ", ") + b.name;
  o.fail(key, "no buffer named \"" + name + "\" (buffers: " + (names.empty() ? "none" : names) + ")");
}

// The current value of a disabled array (glVertexAttrib4f, glVertexAttribI4i/I4ui, glVertexAttribL4d):
// 1 to 4 numbers, the rest filled with GL's (0, 0, 0, 1).
draw::AttributeValue read_current(JsonObject& o, const draw::VertexFormat& f) {
  o.describe("current", "1 to 4 numbers: the generic value a disabled array reads (glVertexAttrib*)");
  const json& v = o.value("current");
  if (!v.is_array() || v.empty() || v.size() > 4)
    o.fail("current", "expected an array of 1 to 4 numbers, got " + describe_json(v));
  double x[4] = {0, 0, 0, 1};
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_number()) o.fail("current", "expected numbers, got " + describe_json(v[i]));
    x[i] = v[i].get<double>();
  }
  draw::AttributeValue out;
  for (int i = 0; i < 4; ++i) {
    switch (f.pointer) {
      case AttribPointer::Float: out.words[i] = std::bit_cast<std::uint32_t>(float(x[i])); break;
      case AttribPointer::Double: {
        out.word_count = 8;
        const auto b = std::bit_cast<std::uint64_t>(x[i]);
        out.words[2 * i] = std::uint32_t(b);
        out.words[2 * i + 1] = std::uint32_t(b >> 32);
        break;
      }
      case AttribPointer::Integer: {
        const bool is_unsigned = f.type == ComponentType::UnsignedInt || f.type == ComponentType::UnsignedShort ||
                                 f.type == ComponentType::UnsignedByte;
        if (x[i] != std::floor(x[i]) || x[i] < (is_unsigned ? 0.0 : -2147483648.0) ||
            x[i] > (is_unsigned ? 4294967295.0 : 2147483647.0))
          o.fail("current", format_number(x[i]) + " is not a 32-bit " + (is_unsigned ? "unsigned " : "") +
                                "integer (glVertexAttribI4" + (is_unsigned ? "ui" : "i") + ")");
        out.words[i] = is_unsigned ? std::uint32_t(x[i]) : std::uint32_t(std::int32_t(x[i]));
      }
    }
  }
  return out;
}

VertexArraySetting read_vertex_array(JsonObject o, const std::string& input, const std::vector<BufferSetting>& buffers) {
  VertexArraySetting s;
  s.input = input;
  draw::VertexArray& a = s.array;
  a.key = o.path();  // "draws.0.vertex_arrays.in_position"
  draw::VertexFormat& f = a.format;
  if (o.has("pointer")) {
    o.describe("pointer", "one of glVertexAttribPointer (float inputs), glVertexAttribIPointer (int/uint), "
                          "glVertexAttribLPointer (double)");
    const std::string p = o.string("pointer");
    if (p == "glVertexAttribPointer") f.pointer = AttribPointer::Float;
    else if (p == "glVertexAttribIPointer") f.pointer = AttribPointer::Integer;
    else if (p == "glVertexAttribLPointer") f.pointer = AttribPointer::Double;
    else o.fail("pointer", "expected glVertexAttribPointer, glVertexAttribIPointer or glVertexAttribLPointer, got \"" + p + "\"");
  }
  if (o.has("type")) f.type = attrib_type(o, "type");
  else if (f.pointer == AttribPointer::Double) f.type = ComponentType::Double;
  if (o.has("size")) {
    o.describe("size", "1, 2, 3, 4 or \"GL_BGRA\"");
    const json& v = o.value("size");
    if (v == "GL_BGRA") {
      f.size = 4;
      f.bgra = true;
    } else {
      f.size = o.integer("size", 1, 4);
    }
  }
  if (o.has("normalized")) f.normalized = o.boolean("normalized");
  a.enabled = !o.has("enabled") || o.boolean("enabled");
  o.describe("enabled", "a boolean (default true): glEnableVertexAttribArray; false reads `current`");
  if (const auto error = draw::format_error(f)) o.fail(f.bgra ? "size" : "type", *error);
  if (!a.enabled) {
    a.current = read_current(o, f);
    for (const char* key : {"buffer", "stride", "offset", "divisor"})
      if (o.has(key)) o.fail(key, "a disabled array reads its current value; it has no " + std::string(key));
    o.finish();
    return s;
  }
  a.buffer = buffer_index(o, "buffer", buffers);
  if (o.has("stride")) {
    o.describe("stride", "bytes between elements, 0..2048 (0: tightly packed)");
    const json& v = o.value("stride");
    if (v.is_number() && v.get<double>() < 0) o.fail("stride", "must not be negative (GL_INVALID_VALUE)");
    if (v.is_number() && v.get<double>() > double(draw::kMaxVertexAttribStride))
      o.fail("stride", format_number(v.get<double>()) + " is more than GL_MAX_VERTEX_ATTRIB_STRIDE (2048): GL_INVALID_VALUE");
    a.stride = std::size_t(o.integer("stride", 0, int(draw::kMaxVertexAttribStride)));
  }
  if (o.has("offset")) {
    o.describe("offset", "the pointer argument: a byte offset into the buffer");
    a.offset = std::size_t(o.integer64("offset", 0, kMaxOffset));
  }
  if (o.has("divisor")) {
    o.describe("divisor", "glVertexAttribDivisor: 0 per vertex, N one element every N instances");
    a.divisor = std::uint32_t(o.integer64("divisor", 0, 0xffffffffll));
  }
  o.finish();
  return s;
}

std::optional<draw::ElementArray> read_elements(JsonObject& d, const std::vector<BufferSetting>& buffers) {
  d.describe("elements", "an object {buffer, type, offset}: the element array of glDrawElements*");
  if (!d.has("elements")) return std::nullopt;
  JsonObject o = d.object("elements");
  draw::ElementArray e;
  e.key = d.path_of("elements");
  e.buffer = buffer_index(o, "buffer", buffers);
  o.describe("type", "one of GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT");
  const std::string type = o.string("type");
  if (type == "GL_UNSIGNED_BYTE") e.type = draw::IndexType::UnsignedByte;
  else if (type == "GL_UNSIGNED_SHORT") e.type = draw::IndexType::UnsignedShort;
  else if (type == "GL_UNSIGNED_INT") e.type = draw::IndexType::UnsignedInt;
  else o.fail("type", "expected GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_UNSIGNED_INT, got \"" + type + "\"");
  if (o.has("offset")) {
    o.describe("offset", "the indices argument: a byte offset into the element buffer");
    e.offset = std::size_t(o.integer64("offset", 0, kMaxOffset));
    if (e.offset % draw::index_bytes(e.type))
      o.fail("offset", std::to_string(e.offset) + " is not a multiple of the index size (" +
                           std::to_string(draw::index_bytes(e.type)) + " bytes): GL's alignment rule for indices");
  }
  o.finish();
  return e;
}

// GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT is implementation-dependent, at most 256 (GL 4.5, table
// 23.64): a multiple of 256 works on every driver (llvmpipe reports 16, NVIDIA 256).
// An indexed buffer target's bindings (glBindBufferRange): GL_UNIFORM_BUFFER or
// GL_SHADER_STORAGE_BUFFER, with GL 4.5's minimum binding count and the largest offset alignment
// the spec lets an implementation ask for (256), so that a scene binds on every driver.
struct BufferTarget {
  const char* key;        // "uniform_buffers"
  const char* gl_target;  // "GL_UNIFORM_BUFFER"
  const char* blocks;     // "uniform blocks"
  const char* alignment;  // "GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT"
  int bindings;
};
constexpr std::int64_t kOffsetAlignment = 256;
constexpr BufferTarget kUniformBuffers{"uniform_buffers", "GL_UNIFORM_BUFFER", "uniform blocks (std140/std430)",
                                       "GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT", 72};
constexpr BufferTarget kStorageBuffers{"shader_storage_buffers", "GL_SHADER_STORAGE_BUFFER",
                                       "shader storage blocks (std430, read and written; the range sizes a runtime array)",
                                       "GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT", 8};

std::vector<UniformBufferSetting> read_buffer_bindings(JsonObject& d, const std::vector<BufferSetting>& buffers,
                                                       const BufferTarget& target) {
  d.describe(target.key, std::string("an array of {binding, buffer, offset, size}: glBindBufferRange(") + target.gl_target +
                             ", ...) for the program's " + target.blocks + ", read through their layout");
  std::vector<UniformBufferSetting> out;
  if (!d.has(target.key)) return out;
  const json& list = d.value(target.key);
  if (!list.is_array()) d.fail(target.key, "expected an array of {binding, buffer, offset, size}, got " + describe_json(list));
  for (std::size_t i = 0; i < list.size(); ++i) {
    JsonObject o(list[i], d.path_of(target.key) + "." + std::to_string(i), d.source());
    UniformBufferSetting u;
    u.key = o.path();
    o.describe("binding", "the block binding point (layout(binding = N)), 0.." + std::to_string(target.bindings - 1));
    u.binding = std::uint32_t(o.integer("binding", 0, target.bindings - 1));
    for (const UniformBufferSetting& other : out)
      if (other.binding == u.binding)
        o.fail("binding", "binding " + std::to_string(u.binding) + " is already bound by " + other.key);
    u.buffer = buffer_index(o, "buffer", buffers);
    if (o.has("offset")) {
      o.describe("offset", "a byte offset into the buffer, a multiple of 256 (default 0)");
      u.offset = std::size_t(o.integer64("offset", 0, kMaxOffset));
      if (std::int64_t(u.offset) % kOffsetAlignment)
        o.fail("offset", std::to_string(u.offset) + " is not a multiple of 256: " + target.alignment +
                             " may be as large as 256, and glBindBufferRange refuses an offset that is not a multiple of it");
    }
    if (o.has("size")) {
      o.describe("size", "bytes bound, > 0 (default: the rest of the buffer)");
      u.size = std::size_t(o.integer64("size", 1, kMaxOffset));
    }
    o.finish();
    out.push_back(u);
  }
  return out;
}

draw::DrawCall read_call(JsonObject& o, bool elements) {
  draw::DrawCall c;
  o.describe("count", "vertices (glDrawArrays*) or indices (glDrawElements*), 0..2^31-1");
  c.count = std::size_t(o.integer64("count", 0, kMaxCount));
  o.describe("first", "glDrawArrays*: the first vertex, 0..2^31-1 (default 0)");
  o.describe("instancecount", "instances, 0..2^31-1 (default 1)");
  o.describe("basevertex", "glDrawElements*: added to every index, -2^31..2^31-1 (default 0)");
  o.describe("baseinstance", "added to an instanced array's element number, 0..2^32-1 (default 0)");
  if (o.has("first")) {
    if (elements) o.fail("first", "glDrawElements* takes no first (the element array's offset says where to start)");
    c.first = std::size_t(o.integer64("first", 0, kMaxCount));
  }
  if (o.has("instancecount")) c.instance_count = std::uint32_t(o.integer64("instancecount", 0, kMaxCount));
  if (o.has("basevertex")) {
    if (!elements) o.fail("basevertex", "glDrawArrays* takes no basevertex (first says where to start)");
    c.base_vertex = o.integer64("basevertex", -kMaxCount - 1, kMaxCount);
  }
  if (o.has("baseinstance")) c.base_instance = std::uint32_t(o.integer64("baseinstance", 0, 0xffffffffll));
  return c;
}

// draws[].shaders: a custom program of the draw's own; stages it does not name are absent.
ShaderSettings read_draw_shaders(JsonObject& o, const ShaderSettings& scene_shaders, const std::filesystem::path& base_dir) {
  const json& given = o.value("shaders");
  if (!given.is_object()) o.fail("shaders", "expected an object {vertex, tess_control, tess_evaluation, geometry, fragment, uniforms, textures}, got " + describe_json(given));
  if (given.contains("program") && given["program"] != "custom")
    o.fail("shaders", "a draw's own program is a custom one: leave out program or set it to \"custom\"");
  for (const char* key : {"attributes", "patch_vertices"})
    if (given.contains(key))
      o.fail("shaders", std::string("a draw feeds its inputs through vertex_arrays and patch_vertices; shaders.") + key +
                            " belongs to the mesh path");
  // The keys a draw's shaders take, for the schema; the merged object below is read without one
  // (its filled-in keys are not the user's).
  JsonObject listed(given, o.path_of("shaders"), o.source());
  for (const auto& [key, allowed] : std::initializer_list<std::pair<const char*, const char*>>{
           {"vertex", "a GLSL file (or twin:NAME), relative to the scene file"},
           {"tess_control", "a GLSL file; none: no control shader (the default patch levels apply)"},
           {"tess_evaluation", "a GLSL file; none: the draw is not tessellated"},
           {"geometry", "a GLSL file; none: no geometry shader"},
           {"fragment", "a GLSL file"},
           {"uniforms", "an object of uniform name: value, as the scene's shaders.uniforms"},
           {"textures", "an object of sampler name: image file, as the scene's shaders.textures"}}) {
    listed.has(key);
    listed.describe(key, allowed);
  }
  JsonSource quiet = o.source();
  quiet.schema = nullptr;
  json merged = {{"program", "custom"},
                 {"uniforms", json::object()},
                 {"attributes", json::object()},
                 {"patch_vertices", 3},
                 {"scene_uniforms", scene_shaders.scene_uniforms},
                 {"batch_lanes", scene_shaders.batch_lanes},
                 {"max_instructions", scene_shaders.max_instructions}};
  merged.update(given);
  return read_shaders(JsonObject(merged, o.path_of("shaders"), quiet), quiet, base_dir);
}

// GL 4.5's minimum GL_MAX_TRANSFORM_FEEDBACK_BUFFERS and _SEPARATE_ATTRIBS (a program that uses
// more would not link on every driver).
constexpr std::size_t kMaxFeedbackBuffers = 4;

TransformFeedbackSetting read_transform_feedback(JsonObject o) {
  TransformFeedbackSetting t;
  t.key = o.path();
  o.describe("varyings", "an array of the last vertex stage's output names (\"gl_Position\", \"color\", "
                         "\"array[1]\", \"Block.member\"), with gl_NextBuffer and gl_SkipComponents1..4 when interleaved");
  o.describe("buffer_mode", "GL_INTERLEAVED_ATTRIBS (default: one buffer, gl_NextBuffer starts the next) or "
                            "GL_SEPARATE_ATTRIBS (a buffer per varying)");
  if (o.has("buffer_mode")) {
    const std::string mode = o.string("buffer_mode");
    if (mode != "GL_INTERLEAVED_ATTRIBS" && mode != "GL_SEPARATE_ATTRIBS")
      o.fail("buffer_mode", "expected GL_INTERLEAVED_ATTRIBS or GL_SEPARATE_ATTRIBS, got \"" + mode + "\"");
    t.separate = mode == "GL_SEPARATE_ATTRIBS";
  }
  const json& v = o.value("varyings");
  if (!v.is_array() || v.empty()) o.fail("varyings", "expected a non-empty array of output names, got " + describe_json(v));
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_string() || v[i].get<std::string>().empty())
      o.fail("varyings", "element " + std::to_string(i) + ": expected an output name, got " + describe_json(v[i]));
    const std::string name = v[i].get<std::string>();
    const bool special = name == "gl_NextBuffer" || name.rfind("gl_SkipComponents", 0) == 0;
    if (special && t.separate)
      o.fail("varyings", "\"" + name + "\" is for GL_INTERLEAVED_ATTRIBS only (GL: the program fails to link)");
    if (name.rfind("gl_SkipComponents", 0) == 0 && (name.size() != 18 || name[17] < '1' || name[17] > '4'))
      o.fail("varyings", "\"" + name + "\": gl_SkipComponents1, 2, 3 or 4");
    if (!special && std::find(t.varyings.begin(), t.varyings.end(), name) != t.varyings.end())
      o.fail("varyings", "\"" + name + "\" is named twice (GL: the program fails to link)");
    t.varyings.push_back(name);
  }
  if (t.buffers() > kMaxFeedbackBuffers)
    o.fail("varyings", std::to_string(t.buffers()) + " buffers; GL guarantees " + std::to_string(kMaxFeedbackBuffers) +
                           (t.separate ? " separate attributes" : " buffers (GL_MAX_TRANSFORM_FEEDBACK_BUFFERS)"));
  o.finish();
  return t;
}

DrawSetting read_draw(JsonObject o, const std::vector<BufferSetting>& buffers, const ShaderSettings& scene_shaders,
                      const std::filesystem::path& base_dir) {
  DrawSetting d;
  d.key = o.path();
  o.describe("shaders", "an object {vertex, tess_control, tess_evaluation, geometry, fragment, uniforms, textures}: this draw's own program");
  if (o.has("shaders")) d.shaders = read_draw_shaders(o, scene_shaders, base_dir);
  static constexpr const char* kModes =
      "GL_PATCHES, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_POINTS, "
      "or with a geometry shader GL_LINES_ADJACENCY, GL_LINE_STRIP_ADJACENCY, GL_TRIANGLES_ADJACENCY or "
      "GL_TRIANGLE_STRIP_ADJACENCY";
  o.describe("mode", std::string("one of ") + kModes);
  const std::string mode = o.string("mode");
  if (const auto named = draw_mode_named(mode)) d.mode = *named;
  else o.fail("mode", std::string("expected ") + kModes + ", got \"" + mode + "\"");
  if (o.has("patch_vertices")) {
    o.describe("patch_vertices", "GL_PATCH_VERTICES: 1..32 (GL_MAX_PATCH_VERTICES)");
    const json& v = o.value("patch_vertices");
    if (!v.is_number_integer() || v.get<std::int64_t>() < 1 || v.get<std::int64_t>() > kMaxPatchVertices)
      o.fail("patch_vertices", "glPatchParameteri(GL_PATCH_VERTICES) takes 1..32 (GL_MAX_PATCH_VERTICES); " +
                                   describe_json(v) + " is GL_INVALID_VALUE");
    d.patch_vertices = int(v.get<std::int64_t>());
  }
  if (o.has("patch_default_outer_level")) {
    const std::vector<float> l = o.levels("patch_default_outer_level", 4, 4);
    d.default_outer = {l[0], l[1], l[2], l[3]};
  }
  if (o.has("patch_default_inner_level")) {
    const std::vector<float> l = o.levels("patch_default_inner_level", 2, 2);
    d.default_inner = {l[0], l[1]};
  }
  o.describe("vertex_arrays", "an object of vertex input (name or location): array");
  if (o.has("vertex_arrays")) {
    const json& arrays = o.value("vertex_arrays");
    if (!arrays.is_object()) o.fail("vertex_arrays", "expected an object of input: array, got " + describe_json(arrays));
    for (const auto& [input, value] : arrays.items())
      d.vertex_arrays.push_back(read_vertex_array(JsonObject(value, o.path_of("vertex_arrays") + "." + input, o.source()), input, buffers));
  }
  d.elements = read_elements(o, buffers);
  d.uniform_buffers = read_buffer_bindings(o, buffers, kUniformBuffers);
  d.storage_buffers = read_buffer_bindings(o, buffers, kStorageBuffers);
  o.describe("primitive_restart", "false, \"fixed_index\" (GL_PRIMITIVE_RESTART_FIXED_INDEX) or an index "
                                  "(GL_PRIMITIVE_RESTART with glPrimitiveRestartIndex)");
  if (o.has("primitive_restart")) {
    const json& v = o.value("primitive_restart");
    if (v == false) {
    } else if (v == "fixed_index") {
      d.restart = {true, true, 0};
    } else if (v.is_number_integer() && v.get<std::int64_t>() >= 0 && v.get<std::int64_t>() <= 0xffffffffll) {
      d.restart = {true, false, std::uint32_t(v.get<std::int64_t>())};
    } else {
      o.fail("primitive_restart", "expected false, \"fixed_index\" or an index in [0, 2^32 - 1], got " + describe_json(v));
    }
    if (d.restart.enabled && !d.elements)
      o.fail("primitive_restart", "applies to glDrawElements* only (GL restarts no glDrawArrays* command)", {"elements"});
  }
  d.raster = read_raster_state(o);
  o.describe("clear", "an object {color, depth}: glClearColor/glClearDepth and glClear of those buffers before the "
                      "draw, within its scissor box and write masks, as GL clears");
  if (o.has("clear")) {
    JsonObject c = o.object("clear");
    c.describe("color", "glClearColor: [r, g, b, a]; the colour buffer is cleared to it");
    if (c.has("color")) d.clear_color = c.rgba("color");
    c.describe("depth", "glClearDepth: a number, clamped to [0, 1] as GL does; the depth buffer is cleared to it");
    if (c.has("depth")) d.clear_depth = std::clamp(double(c.number("depth")), 0.0, 1.0);
    if (!d.clear_color && !d.clear_depth) c.fail("color", "give color, depth or both: the buffers glClear clears");
    c.finish();
  }
  o.describe("transform_feedback", "an object {varyings, buffer_mode}: glTransformFeedbackVaryings and transform "
                                   "feedback over the draw; render --transform-feedback writes the buffers");
  if (o.has("transform_feedback")) d.transform_feedback = read_transform_feedback(o.object("transform_feedback"));
  if (o.has("robust_buffer_access")) d.rules.robust_buffer_access = o.boolean("robust_buffer_access");
  o.describe("robust_buffer_access", "a boolean (default false): a fetch outside a buffer reads zero instead of being an error");
  o.describe("calls", "an array of {count, first | basevertex, instancecount, baseinstance}: glMultiDraw* and indirect draws");
  const bool flat = o.has("count");
  o.describe("count", "vertices (glDrawArrays*) or indices (glDrawElements*), 0..2^31-1; or calls");
  if (o.has("calls")) {
    if (flat) o.fail("calls", "give either calls or count (with first, basevertex, instancecount, baseinstance), not both", {"count"});
    const json& calls = o.value("calls");
    if (!calls.is_array() || calls.empty()) o.fail("calls", "expected a non-empty array of calls, got " + describe_json(calls));
    for (std::size_t i = 0; i < calls.size(); ++i) {
      JsonObject c(calls[i], o.path_of("calls") + "." + std::to_string(i), o.source());
      d.calls.push_back(read_call(c, d.elements.has_value()));
      c.finish();
    }
  } else {
    if (!flat) o.fail("count", "missing: the draw call's count (or calls, a list of calls)");
    d.calls.push_back(read_call(o, d.elements.has_value()));
  }
  if (d.mode != DrawMode::Patches && (o.has("patch_vertices") || o.has("patch_default_outer_level") || o.has("patch_default_inner_level")))
    o.fail("mode", "the patch parameters apply to GL_PATCHES only", {"patch_vertices"});
  o.finish();
  return d;
}

}  // namespace

namespace {

std::filesystem::path resolve(const std::filesystem::path& p, const std::filesystem::path& base_dir) {
  return p.is_relative() ? base_dir / p : p;
}

// One colour attachment: a file name alone (GL_RGBA32F), or {internalformat, file}.
ColorAttachmentSetting read_color_attachment(const json& j, const std::string& path, const JsonSource& source,
                                             const std::filesystem::path& base_dir) {
  ColorAttachmentSetting c;
  if (j.is_string()) {
    c.file = resolve(j.get<std::string>(), base_dir);
    return c;
  }
  JsonObject o(j, path, source);
  o.describe("internalformat", "GL_RGBA32F (default), GL_RGBA16F, GL_RGBA8 or GL_SRGB8_ALPHA8");
  if (o.has("internalformat")) {
    const std::string f = o.string("internalformat");
    if (f == "GL_RGBA32F") c.format = ColorFormat::kRgba32F;
    else if (f == "GL_RGBA16F") c.format = ColorFormat::kRgba16F;
    else if (f == "GL_RGBA8") c.format = ColorFormat::kRgba8;
    else if (f == "GL_SRGB8_ALPHA8") c.format = ColorFormat::kSrgb8Alpha8;
    else o.fail("internalformat", "expected GL_RGBA32F, GL_RGBA16F, GL_RGBA8 or GL_SRGB8_ALPHA8, got \"" + f + "\"");
  }
  o.describe("file", "an image file the attachment holds before the first draw (EXR keeps floats; 8-bit files read "
                     "as k/255 and are stored as they are, also in GL_SRGB8_ALPHA8), top row first, the image's size; "
                     "fewer than 4 channels: alpha 1");
  if (o.has("file")) c.file = resolve(o.string("file"), base_dir);
  o.finish();
  return c;
}

void read_framebuffer(JsonObject f, const std::filesystem::path& base_dir, FramebufferSetting& out) {
  f.describe("color", "an array of 1 to 8 colour attachments, draw buffer k taking fragment output location k: each "
                      "{internalformat, file} or a file name alone (GL_RGBA32F); one file name alone: one attachment");
  if (f.has("color")) {
    const json& c = f.value("color");
    out.color.clear();
    if (c.is_array()) {
      if (c.empty() || c.size() > std::size_t(kMaxDrawBuffers))
        f.fail("color", "expected 1 to " + std::to_string(kMaxDrawBuffers) + " attachments (GL_MAX_DRAW_BUFFERS), got " +
                            std::to_string(c.size()));
      for (std::size_t k = 0; k < c.size(); ++k)
        out.color.push_back(read_color_attachment(c[k], f.path_of("color") + "." + std::to_string(k),
                                                  f.source(), base_dir));
    } else if (c.is_string() || c.is_object()) {
      out.color.push_back(read_color_attachment(c, f.path_of("color"), f.source(), base_dir));
    } else {
      f.fail("color", "expected an array of attachments, an attachment {internalformat, file} or a file name, got " +
                          describe_json(c));
    }
  }
  f.describe("depth", "the depth attachment: {internalformat: GL_DEPTH_COMPONENT32F (default) or "
                      "GL_DEPTH_COMPONENT24, file}, or a file name alone (32F); the file's first channel is the window "
                      "depth in [0, 1] (EXR), top row first");
  if (f.has("depth")) {
    const json& d = f.value("depth");
    if (d.is_string()) {
      out.depth_file = resolve(d.get<std::string>(), base_dir);
    } else {
      JsonObject o = f.object("depth");
      o.describe("internalformat", "GL_DEPTH_COMPONENT32F (default) or GL_DEPTH_COMPONENT24");
      if (o.has("internalformat")) {
        const std::string fmt = o.string("internalformat");
        if (fmt == "GL_DEPTH_COMPONENT32F") out.depth_format = DepthFormat::k32F;
        else if (fmt == "GL_DEPTH_COMPONENT24") out.depth_format = DepthFormat::k24;
        else o.fail("internalformat", "expected GL_DEPTH_COMPONENT32F or GL_DEPTH_COMPONENT24, got \"" + fmt + "\"");
      }
      o.describe("file", "an image file whose first channel is the window depth in [0, 1] (EXR), top row first");
      if (o.has("file")) out.depth_file = resolve(o.string("file"), base_dir);
      o.finish();
    }
  }
  f.finish();
}

}  // namespace

void read_draw_keys(JsonObject& root, const JsonSource& source, const std::filesystem::path& base_dir,
                    const ShaderSettings& scene_shaders, std::vector<BufferSetting>& buffers,
                    std::vector<DrawSetting>& draws, FramebufferSetting& framebuffer) {
  root.describe("buffers", "an object of buffer name: {file} or {type, data}");
  if (root.has("buffers")) {
    const json& b = root.value("buffers");
    if (!b.is_object()) root.fail("buffers", "expected an object of name: buffer, got " + describe_json(b));
    for (const auto& [name, value] : b.items())
      buffers.push_back(read_buffer(JsonObject(value, "buffers." + name, source), name, base_dir));
  }
  root.describe("framebuffer", "an object {color, depth}: the attachments a scene of draws draws into and the images "
                                "they hold before the first draw (default: one GL_RGBA32F attachment holding the "
                                "background, GL_DEPTH_COMPONENT32F holding 1)");
  if (root.has("framebuffer")) read_framebuffer(root.object("framebuffer"), base_dir, framebuffer);
  root.describe("draws", "an array of GL draws, drawn in order (replaces mesh and the built-in programs)");
  if (root.has("draws")) {
    const json& d = root.value("draws");
    if (!d.is_array() || d.empty()) root.fail("draws", "expected a non-empty array of draws, got " + describe_json(d));
    for (std::size_t i = 0; i < d.size(); ++i)
      draws.push_back(read_draw(JsonObject(d[i], "draws." + std::to_string(i), source), buffers, scene_shaders, base_dir));
  }
}

const char* draw_keys_example() {
  return R"({
  "buffers": { "b": { "type": "GL_FLOAT", "data": [0] }, "f": { "file": "x.bin" } },
  "framebuffer": { "color": [{ "internalformat": "GL_RGBA8", "file": "c.png" }],
                   "depth": { "internalformat": "GL_DEPTH_COMPONENT24", "file": "d.exr" } },
  "draws": [{
    "shaders": { "vertex": "a.vert", "fragment": "a.frag" },
    "mode": "GL_PATCHES", "patch_vertices": 3,
    "patch_default_outer_level": [1, 1, 1, 1], "patch_default_inner_level": [1, 1],
    "vertex_arrays": {
      "0": { "buffer": "b", "size": 3, "type": "GL_FLOAT", "normalized": false, "pointer": "glVertexAttribPointer",
             "stride": 0, "offset": 0, "divisor": 0, "enabled": true },
      "1": { "enabled": false, "current": [0, 0, 0, 1] }
    },
    "elements": { "buffer": "b", "type": "GL_UNSIGNED_INT", "offset": 0 },
    "primitive_restart": false, "robust_buffer_access": false, "enable": ["GL_DEPTH_TEST"],
    "polygon_mode": "GL_FILL", "depth_func": "GL_LESS", "depth_mask": true, "cull_face": "GL_BACK",
    "front_face": "GL_CCW", "scissor": [0, 0, 1, 1], "color_mask": [true, true, true, true],
    "blend": { "equation": "GL_FUNC_ADD", "equation_alpha": "GL_FUNC_ADD", "src": "GL_ONE", "dst": "GL_ZERO",
               "src_alpha": "GL_ONE", "dst_alpha": "GL_ZERO", "color": [0, 0, 0, 0] },
    "uniform_buffers": [{ "binding": 0, "buffer": "b", "offset": 0, "size": 16 }],
    "shader_storage_buffers": [{ "binding": 0, "buffer": "b", "offset": 0, "size": 16 }],
    "clear": { "color": [0, 0, 0, 1], "depth": 1 },
    "calls": [{ "count": 0, "basevertex": 0, "instancecount": 1, "baseinstance": 0 }]
  }]
})";
}

}  // namespace tessref
