#include "glref/patch_mesh.h"

#include <epoxy/gl.h>

#include <string>

#include "glref/gl_context.h"
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
  upload(GL_ELEMENT_ARRAY_BUFFER, index_buffer_, data.indices.data(), data.indices.size() * sizeof(std::uint32_t));
  glBindVertexArray(0);
  check_gl("PatchMesh: uploading the mesh");
}

PatchMesh::~PatchMesh() {
  for (unsigned* b : {&position_buffer_, &normal_buffer_, &index_buffer_})
    if (*b) glDeleteBuffers(1, b);
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

std::size_t PatchMesh::draw(const Program& program, const std::vector<std::size_t>& point_bounds,
                            std::size_t max_points_per_draw) {
  if (!point_bounds.empty() && point_bounds.size() != patch_count_)
    throw GlError("PatchMesh::draw: " + std::to_string(point_bounds.size()) + " point bounds for " +
                  std::to_string(patch_count_) + " patches");
  std::vector<std::size_t> bounds = point_bounds;
  if (bounds.empty()) {
    const std::size_t m = static_cast<std::size_t>(context_.max_tess_gen_level()) + 1;
    bounds.assign(patch_count_, m * m);
  }
  context_.make_current();
  program.use();
  const GLint base_location = glGetUniformLocation(program.id(), "u_patch_base");
  glBindVertexArray(vao_);
  glPatchParameteri(GL_PATCH_VERTICES, patch_vertices_);
  const std::vector<DrawRange> draws = split_draws(bounds, max_points_per_draw, std::size_t(1) << 20);
  for (const DrawRange& d : draws) {
    if (base_location >= 0) glUniform1i(base_location, static_cast<GLint>(d.first));
    const std::size_t offset = d.first * patch_vertices_ * sizeof(std::uint32_t);
    glDrawElements(GL_PATCHES, static_cast<GLsizei>(d.count * patch_vertices_), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(offset));
  }
  glBindVertexArray(0);
  check_gl("PatchMesh::draw");
  return draws.size();
}

}  // namespace tessref::glref
