#include "glref/patch_mesh.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

#include "glref/gl_context.h"
#include "glref/feedback_draw.h"
#include "glref/gl_error.h"
#include "glref/gl_program.h"

namespace tessref::glref {

PatchMesh::PatchMesh(GlContext& context, const PatchMeshData& data)
    : context_(context), patch_vertices_(data.patch_vertices) {
  GLint max_patch_vertices = 0;
  glGetIntegerv(GL_MAX_PATCH_VERTICES, &max_patch_vertices);
  if (data.patch_vertices < 1 || data.patch_vertices > max_patch_vertices)
    throw GlError("PatchMesh: " + std::to_string(data.patch_vertices) + " vertices per patch, 1.." +
                  std::to_string(max_patch_vertices) + " supported");
  if (data.indices.size() % data.patch_vertices != 0)
    throw GlError("PatchMesh: " + std::to_string(data.indices.size()) + " indices are not whole patches of " +
                  std::to_string(data.patch_vertices));
  if (!data.normals.empty() && data.normals.size() != data.positions.size())
    throw GlError("PatchMesh: " + std::to_string(data.normals.size()) + " normals for " +
                  std::to_string(data.positions.size()) + " positions");
  for (std::size_t i = 0; i < data.indices.size(); ++i)
    if (data.indices[i] >= data.positions.size())
      throw GlError("PatchMesh: index " + std::to_string(i) + " = " + std::to_string(data.indices[i]) +
                    " is past the " + std::to_string(data.positions.size()) + " vertices");
  patch_count_ = data.indices.size() / data.patch_vertices;

  context_.make_current();
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  auto upload = [](GLenum target, unsigned& buffer, const void* bytes, std::size_t size) {
    glGenBuffers(1, &buffer);
    glBindBuffer(target, buffer);
    glBufferData(target, static_cast<GLsizeiptr>(size), size ? bytes : nullptr, GL_STATIC_DRAW);
  };
  upload(GL_ARRAY_BUFFER, position_buffer_, data.positions.data(), data.positions.size() * sizeof(glm::vec3));
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glEnableVertexAttribArray(0);
  if (!data.normals.empty()) {
    upload(GL_ARRAY_BUFFER, normal_buffer_, data.normals.data(), data.normals.size() * sizeof(glm::vec3));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
  }
  if (data.tags.size() != (data.tags.empty() ? 0 : data.positions.size()) || data.creases.size() != data.tags.size())
    throw GlError("PatchMesh: tags and creases must come one per position, or not at all");
  if (!data.tags.empty()) {
    upload(GL_ARRAY_BUFFER, tags_buffer_, data.tags.data(), data.tags.size() * sizeof(glm::vec4));
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glEnableVertexAttribArray(2);
    upload(GL_ARRAY_BUFFER, crease_buffer_, data.creases.data(), data.creases.size() * sizeof(glm::vec3));
    glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(3);
  }
  upload(GL_ELEMENT_ARRAY_BUFFER, index_buffer_, data.indices.data(), data.indices.size() * sizeof(std::uint32_t));
  glBindVertexArray(0);
  check_gl("PatchMesh: uploading the mesh");
}

PatchMesh::~PatchMesh() {
  if (query_generated_) glDeleteQueries(1, &query_generated_);
  if (query_written_) glDeleteQueries(1, &query_written_);
  for (unsigned* b : {&position_buffer_, &normal_buffer_, &index_buffer_, &feedback_buffer_, &tags_buffer_, &crease_buffer_})
    if (*b) glDeleteBuffers(1, b);
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

std::vector<std::size_t> PatchMesh::bounds_or_worst_case(const std::vector<std::size_t>& point_bounds) const {
  if (!point_bounds.empty() && point_bounds.size() != patch_count_)
    throw GlError("PatchMesh: " + std::to_string(point_bounds.size()) + " point bounds for " +
                  std::to_string(patch_count_) + " patches");
  if (!point_bounds.empty()) return point_bounds;
  const std::size_t m = static_cast<std::size_t>(context_.max_tess_gen_level()) + 1;
  return std::vector<std::size_t>(patch_count_, m * m);
}

void PatchMesh::draw_range(const DrawRange& d, int base_location) {
  if (base_location >= 0) glUniform1i(base_location, static_cast<GLint>(d.first));
  const std::size_t offset = d.first * patch_vertices_ * sizeof(std::uint32_t);
  glDrawElements(GL_PATCHES, static_cast<GLsizei>(d.count * patch_vertices_), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(offset));
}

std::size_t PatchMesh::draw(const Program& program, const std::vector<std::size_t>& point_bounds,
                            std::size_t max_points_per_draw) {
  const std::vector<std::size_t> bounds = bounds_or_worst_case(point_bounds);
  context_.make_current();
  program.use();
  const GLint base_location = glGetUniformLocation(program.id(), "u_patch_base");
  glBindVertexArray(vao_);
  glPatchParameteri(GL_PATCH_VERTICES, patch_vertices_);
  const std::vector<DrawRange> draws = split_draws(bounds, max_points_per_draw, max_patches_per_draw(patch_vertices_));
  for (const DrawRange& d : draws) draw_range(d, base_location);
  glBindVertexArray(0);
  check_gl("PatchMesh::draw");
  return draws.size();
}

std::vector<std::uint32_t> PatchMesh::capture(const Program& program, int words_per_vertex, unsigned primitive,
                                              const std::vector<std::size_t>& point_bounds,
                                              std::size_t max_points_per_draw) {
  const int vpp = primitive == GL_TRIANGLES ? 3 : primitive == GL_LINES ? 2 : primitive == GL_POINTS ? 1 : 0;
  if (vpp == 0 || words_per_vertex < 1)
    throw GlError("PatchMesh::capture: primitive must be GL_TRIANGLES, GL_LINES or GL_POINTS, words >= 1");
  const std::vector<std::size_t> bounds = bounds_or_worst_case(point_bounds);
  context_.make_current();
  context_.bind_default_framebuffer();
  program.use();
  const GLint base_location = glGetUniformLocation(program.id(), "u_patch_base");
  if (!feedback_buffer_) {
    glGenBuffers(1, &feedback_buffer_);
    glGenQueries(1, &query_generated_);
    glGenQueries(1, &query_written_);
  }
  glBindVertexArray(vao_);
  glPatchParameteri(GL_PATCH_VERTICES, patch_vertices_);
  glEnable(GL_RASTERIZER_DISCARD);
  std::vector<std::uint32_t> out;
  try {
    for (const DrawRange& d : split_draws(bounds, max_points_per_draw, max_patches_per_draw(patch_vertices_))) {
      // Emitted vertices: fewer than 2 triangles (or 1 segment) per domain point.
      std::size_t points = 0;
      for (std::size_t i = d.first; i < d.first + d.count; ++i) points += bounds[i];
      const std::size_t max_vertices = std::max<std::size_t>(points * (vpp == 3 ? 6 : vpp == 2 ? 2 : 1), vpp);
      const std::size_t bytes = max_vertices * words_per_vertex * sizeof(std::uint32_t);
      glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedback_buffer_);
      if (bytes > feedback_capacity_) {
        feedback_capacity_ = std::max(bytes, feedback_capacity_ * 2);
        glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, static_cast<GLsizeiptr>(feedback_capacity_), nullptr,
                     GL_DYNAMIC_COPY);
      }
      glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedback_buffer_, 0, static_cast<GLsizeiptr>(bytes));
      const std::uint64_t written = draw_with_feedback(
          primitive, query_generated_, query_written_, [&] { draw_range(d, base_location); },
          "PatchMesh::capture", "point bounds too small?");
      const std::size_t words = static_cast<std::size_t>(written) * vpp * words_per_vertex;
      const std::size_t at = out.size();
      out.resize(at + words);
      if (words)
        glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, static_cast<GLsizeiptr>(words * sizeof(std::uint32_t)),
                           out.data() + at);
      check_gl("PatchMesh::capture: reading back");
    }
  } catch (...) {
    glDisable(GL_RASTERIZER_DISCARD);
    glBindVertexArray(0);
    while (glGetError() != GL_NO_ERROR) {
    }
    throw;
  }
  glDisable(GL_RASTERIZER_DISCARD);
  glBindVertexArray(0);
  return out;
}

}  // namespace tessref::glref
