#include "glref/gl_draws.h"

#include <epoxy/gl.h>

#include <utility>

#include "glref/gl_error.h"
#include "glref/gl_raster_state.h"

namespace tessref::glref {
namespace {

GLenum gl_type(draw::ComponentType t) {
  using CT = draw::ComponentType;
  switch (t) {
    case CT::Byte: return GL_BYTE;
    case CT::UnsignedByte: return GL_UNSIGNED_BYTE;
    case CT::Short: return GL_SHORT;
    case CT::UnsignedShort: return GL_UNSIGNED_SHORT;
    case CT::Int: return GL_INT;
    case CT::UnsignedInt: return GL_UNSIGNED_INT;
    case CT::Fixed: return GL_FIXED;
    case CT::HalfFloat: return GL_HALF_FLOAT;
    case CT::Float: return GL_FLOAT;
    case CT::Double: return GL_DOUBLE;
    case CT::Int2101010Rev: return GL_INT_2_10_10_10_REV;
    case CT::UnsignedInt2101010Rev: return GL_UNSIGNED_INT_2_10_10_10_REV;
    case CT::UnsignedInt10F11F11FRev: return GL_UNSIGNED_INT_10F_11F_11F_REV;
  }
  return GL_NONE;
}

GLenum gl_index_type(draw::IndexType t) {
  return t == draw::IndexType::UnsignedByte ? GL_UNSIGNED_BYTE
         : t == draw::IndexType::UnsignedShort ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
}

GLenum gl_mode(DrawMode m) {
  switch (m) {
    case DrawMode::Patches: return GL_PATCHES;
    case DrawMode::Triangles: return GL_TRIANGLES;
    case DrawMode::TriangleStrip: return GL_TRIANGLE_STRIP;
    case DrawMode::TriangleFan: return GL_TRIANGLE_FAN;
    case DrawMode::Lines: return GL_LINES;
    case DrawMode::LineStrip: return GL_LINE_STRIP;
    case DrawMode::LineLoop: return GL_LINE_LOOP;
    case DrawMode::Points: return GL_POINTS;
    case DrawMode::LinesAdjacency: return GL_LINES_ADJACENCY;
    case DrawMode::LineStripAdjacency: return GL_LINE_STRIP_ADJACENCY;
    case DrawMode::TrianglesAdjacency: return GL_TRIANGLES_ADJACENCY;
    case DrawMode::TriangleStripAdjacency: return GL_TRIANGLE_STRIP_ADJACENCY;
  }
  return GL_NONE;
}



// glVertexAttrib4f / I4i / I4ui / L4d with the array's current value.
void set_current(std::uint32_t location, const draw::VertexArray& a) {
  const auto& w = a.current.words;
  switch (a.format.pointer) {
    case draw::AttribPointer::Float: glVertexAttrib4fv(location, reinterpret_cast<const GLfloat*>(w.data())); break;
    case draw::AttribPointer::Integer:
      if (a.format.type == draw::ComponentType::UnsignedInt || a.format.type == draw::ComponentType::UnsignedShort ||
          a.format.type == draw::ComponentType::UnsignedByte)
        glVertexAttribI4uiv(location, w.data());
      else
        glVertexAttribI4iv(location, reinterpret_cast<const GLint*>(w.data()));
      break;
    case draw::AttribPointer::Double: glVertexAttribL4dv(location, reinterpret_cast<const GLdouble*>(w.data())); break;
  }
}

// glVertexAttrib*Pointer for a, its first element `offset` bytes into the bound GL_ARRAY_BUFFER.
void set_pointer(GLuint location, const draw::VertexArray& a, std::size_t offset) {
  const GLint size = a.format.bgra ? GL_BGRA : a.format.size;
  const auto* pointer = reinterpret_cast<const void*>(std::uintptr_t(offset));
  switch (a.format.pointer) {
    case draw::AttribPointer::Float:
      glVertexAttribPointer(location, size, gl_type(a.format.type), a.format.normalized ? GL_TRUE : GL_FALSE,
                            GLsizei(a.stride), pointer);
      break;
    case draw::AttribPointer::Integer:
      glVertexAttribIPointer(location, size, gl_type(a.format.type), GLsizei(a.stride), pointer);
      break;
    case draw::AttribPointer::Double: glVertexAttribLPointer(location, size, GL_DOUBLE, GLsizei(a.stride), pointer); break;
  }
}

}  // namespace

GlDraws::GlDraws(const Scene& scene, const std::vector<draw::Buffer>& buffers, std::vector<unsigned> programs,
                 std::vector<const GlTextures*> textures)
    : scene_(scene), programs_(std::move(programs)), textures_(std::move(textures)) {
  buffers_.resize(buffers.size());
  if (!buffers_.empty()) glGenBuffers(GLsizei(buffers_.size()), buffers_.data());
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[i]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(buffers[i].bytes.size()), buffers[i].bytes.data(), GL_STATIC_DRAW);
    buffer_sizes_.push_back(buffers[i].bytes.size());
  }
  vaos_.resize(scene.draws.size());
  glGenVertexArrays(GLsizei(vaos_.size()), vaos_.data());
  current_.resize(scene.draws.size());
  instanced_.resize(scene.draws.size());
  for (std::size_t d = 0; d < scene.draws.size(); ++d) {
    const DrawSetting& draw = scene.draws[d];
    glBindVertexArray(vaos_[d]);
    for (const VertexArraySetting& s : draw.vertex_arrays) {
      const draw::VertexArray& a = s.array;
      GLint location;
      if (s.input.find_first_not_of("0123456789") == std::string::npos) {
        location = GLint(std::stoul(s.input));
      } else {
        location = glGetAttribLocation(programs_[d], s.input.c_str());
        if (location < 0) throw GlError(a.key + ": the driver reports no active vertex input \"" + s.input + "\"");
      }
      if (!a.enabled) {
        current_[d].push_back({std::uint32_t(location), a});
        continue;
      }
      glBindBuffer(GL_ARRAY_BUFFER, buffers_[a.buffer]);
      set_pointer(GLuint(location), a, a.offset);
      glVertexAttribDivisor(GLuint(location), a.divisor);
      if (a.divisor) instanced_[d].push_back({std::uint32_t(location), a});
      glEnableVertexAttribArray(GLuint(location));
    }
    if (draw.elements) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[draw.elements->buffer]);
    check_gl((draw.key + ": setting up the vertex array").c_str());
  }
  glBindVertexArray(0);
}

GlDraws::~GlDraws() {
  if (!vaos_.empty()) glDeleteVertexArrays(GLsizei(vaos_.size()), vaos_.data());
  if (!buffers_.empty()) glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
}

void GlDraws::bind(std::size_t d, unsigned program) const {
  const DrawSetting& draw = scene_.draws[d];
  glUseProgram(program);
  if (textures_[d]) textures_[d]->bind();
  glBindVertexArray(vaos_[d]);
  for (const auto& [location, a] : current_[d]) set_current(location, a);
  apply_raster_state(draw.raster, scene_.width, scene_.height);
  for (const auto& [target, settings] : {std::pair{GLenum(GL_UNIFORM_BUFFER), &draw.uniform_buffers},
                                         std::pair{GLenum(GL_SHADER_STORAGE_BUFFER), &draw.storage_buffers}})
    for (const UniformBufferSetting& u : *settings) {
      const std::size_t size = u.size.value_or(buffer_sizes_[u.buffer] - u.offset);
      glBindBufferRange(target, u.binding, buffers_[u.buffer], GLintptr(u.offset), GLsizeiptr(size));
    }
  glDisable(GL_PRIMITIVE_RESTART);
  glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  if (draw.restart.enabled && draw.restart.fixed_index) glEnable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  if (draw.restart.enabled && !draw.restart.fixed_index) {
    glEnable(GL_PRIMITIVE_RESTART);
    glPrimitiveRestartIndex(draw.restart.index);
  }
  if (draw.mode == DrawMode::Patches) {
    glPatchParameteri(GL_PATCH_VERTICES, draw.patch_vertices);
    glPatchParameterfv(GL_PATCH_DEFAULT_OUTER_LEVEL, &draw.default_outer.x);
    glPatchParameterfv(GL_PATCH_DEFAULT_INNER_LEVEL, &draw.default_inner.x);
  }
}

void GlDraws::unbind() const {
  glBindVertexArray(0);
  glUseProgram(0);
  reset_raster_state(scene_.width, scene_.height);
  glDisable(GL_PRIMITIVE_RESTART);
  glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
}

namespace {

void issue(const DrawSetting& draw, const draw::DrawCall& c, std::uint32_t instance_count) {
  if (draw.elements)
    glDrawElementsInstancedBaseVertexBaseInstance(
        gl_mode(draw.mode), GLsizei(c.count), gl_index_type(draw.elements->type),
        reinterpret_cast<const void*>(std::uintptr_t(draw.elements->offset)), GLsizei(instance_count),
        GLint(c.base_vertex), c.base_instance);
  else
    glDrawArraysInstancedBaseInstance(gl_mode(draw.mode), GLint(c.first), GLsizei(c.count),
                                      GLsizei(instance_count), c.base_instance);
}

}  // namespace

void GlDraws::draw(const std::function<void(std::size_t, bool)>& around) const {
  for (std::size_t d = 0; d < scene_.draws.size(); ++d) {
    bind(d, programs_[d]);
    const DrawSetting& draw = scene_.draws[d];
    if (draw.clear_color || draw.clear_depth) {  // within the scissor box and masks bind() set
      if (draw.clear_color) glClearColor(draw.clear_color->r, draw.clear_color->g, draw.clear_color->b, draw.clear_color->a);
      if (draw.clear_depth) glClearDepth(*draw.clear_depth);
      glClear((draw.clear_color ? GL_COLOR_BUFFER_BIT : 0) | (draw.clear_depth ? GL_DEPTH_BUFFER_BIT : 0));
    }
    if (around) around(d, true);
    for (const draw::DrawCall& c : draw.calls) issue(draw, c, c.instance_count);
    if (around) around(d, false);
    check_gl((scene_.draws[d].key + ": drawing").c_str());
  }
  unbind();
}

void GlDraws::draw_instance(std::size_t d, std::size_t call, std::uint32_t instance) const {
  const DrawSetting& draw = scene_.draws[d];
  // Instance k reads element floor(k / divisor) + baseinstance (GL 4.5, 10.5); drawn alone as
  // instance 0 it reads element baseinstance, so the pointer moves by the difference.
  for (const auto& [location, a] : instanced_[d]) {
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[a.buffer]);
    const std::size_t stride = a.stride ? a.stride : draw::element_bytes(a.format);
    set_pointer(location, a, a.offset + std::size_t(instance / a.divisor) * stride);
  }
  issue(draw, draw.calls[call], 1);
  for (const auto& [location, a] : instanced_[d]) {
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[a.buffer]);
    set_pointer(location, a, a.offset);
  }
  check_gl((draw.key + ".calls[" + std::to_string(call) + "]: drawing instance " + std::to_string(instance)).c_str());
}

}  // namespace tessref::glref
