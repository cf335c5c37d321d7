#include "glref/tess_capture.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

#include "glref/gl_context.h"
#include "glref/feedback_draw.h"
#include "glref/gl_error.h"
#include "glref/shader_source.h"

namespace tessref::glref {
namespace {

// One transform-feedback record, interleaved: vec3 tess_coord, int patch_id.
struct FeedbackVertex {
  float coord[3];
  std::int32_t patch;
};
static_assert(sizeof(FeedbackVertex) == 16);

int relevant_outer(TessDomain d) { return d == TessDomain::Triangles ? 3 : d == TessDomain::Quads ? 4 : 2; }
int relevant_inner(TessDomain d) { return d == TessDomain::Triangles ? 1 : d == TessDomain::Quads ? 2 : 0; }

GLenum feedback_mode(const TessLayout& layout) {
  if (layout.point_mode) return GL_POINTS;
  return layout.domain == TessDomain::Isolines ? GL_LINES : GL_TRIANGLES;
}

int layout_key(const TessLayout& l) {
  return static_cast<int>(l.domain) * 64 + static_cast<int>(l.spacing) * 8 +
         static_cast<int>(l.winding) * 2 + (l.point_mode ? 1 : 0);
}

}  // namespace

int vertices_per_primitive(const TessLayout& layout) {
  if (layout.point_mode) return 1;
  return layout.domain == TessDomain::Isolines ? 2 : 3;
}

std::size_t domain_point_bound(const TessLayout& layout, const TessLevels& levels) {
  const int no = relevant_outer(layout.domain), ni = relevant_inner(layout.domain);
  for (int i = 0; i < no; ++i)
    if (!(levels.outer[i] > 0.0f)) return 0;  // also NaN: the spec discards the patch
  int m = 1;
  auto widen = [&m](float v) {
    // NaN inner levels are clamped by the driver; count them as the largest level.
    const float c = std::isnan(v) ? 64.0f : std::clamp(v, 0.0f, 64.0f);
    m = std::max(m, static_cast<int>(std::ceil(c)));
  };
  for (int i = 0; i < no; ++i) widen(levels.outer[i]);
  for (int i = 0; i < ni; ++i) widen(levels.inner[i]);
  // Rounding up to an odd or even segment count. 64 is GL_MAX_TESS_GEN_LEVEL on llvmpipe and
  // NVIDIA; a driver with a larger maximum would overflow this bound, which capture() reports.
  m = std::min(64, m + 1);
  // Quads: sum of outer edges + inner grid <= 4m + (m-1)^2; triangles and isolines have fewer.
  return static_cast<std::size_t>(m + 1) * static_cast<std::size_t>(m + 1);
}

std::size_t emitted_vertex_bound(const TessLayout& layout, const TessLevels& levels) {
  const std::size_t points = domain_point_bound(layout, levels);
  if (layout.point_mode) return points;
  // A planar triangulation of V points has fewer than 2V triangles; isolines fewer than V segments.
  return layout.domain == TessDomain::Isolines ? 2 * points : 6 * points;
}

TessCapture::TessCapture(GlContext& context, const CaptureOptions& options)
    : context_(context), options_(options) {
  context_.make_current();
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &level_buffer_);
  glGenBuffers(1, &feedback_buffer_);
  glGenQueries(1, &query_generated_);
  glGenQueries(1, &query_written_);
  GLint max_block = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
  max_patches_per_upload_ = std::clamp<std::size_t>(static_cast<std::size_t>(max_block) / 32, 1, 1u << 20);
  if (options_.max_patches_per_upload)
    max_patches_per_upload_ = std::min(max_patches_per_upload_, options_.max_patches_per_upload);
  check_gl("TessCapture: creating GL objects");
}

TessCapture::~TessCapture() {
  glDeleteQueries(1, &query_written_);
  glDeleteQueries(1, &query_generated_);
  glDeleteBuffers(1, &feedback_buffer_);
  glDeleteBuffers(1, &level_buffer_);
  glDeleteVertexArrays(1, &vao_);
}

const Program& TessCapture::program_for(const TessLayout& layout) {
  const int key = layout_key(layout);
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  std::vector<ShaderStage> stages = {
      {GL_VERTEX_SHADER, shader_source("tpg_capture.vert"), "tpg_capture.vert"},
      {GL_TESS_CONTROL_SHADER, shader_source("tpg_capture.tesc"), "tpg_capture.tesc"},
      {GL_TESS_EVALUATION_SHADER,
       set_tes_layout(shader_source("tpg_capture.tese"), layout),
       "tpg_capture.tese"},
  };
  Program p = link_program(stages, FeedbackVaryings{{"tess_coord", "patch_id"}, true});
  return programs_.emplace(key, std::move(p)).first->second;
}

void TessCapture::ensure_buffer(unsigned target, unsigned buffer, std::size_t bytes, std::size_t& capacity) {
  glBindBuffer(target, buffer);
  if (bytes <= capacity) return;
  capacity = std::max(bytes, capacity * 2);
  glBufferData(target, static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_COPY);
  check_gl("TessCapture: allocating a buffer");
}

std::vector<std::vector<glm::vec3>> TessCapture::capture(const TessLayout& layout,
                                                         const std::vector<TessLevels>& levels) {
  const auto t0 = std::chrono::steady_clock::now();
  stats_ = CaptureStats{};
  stats_.patches = levels.size();
  std::vector<std::vector<glm::vec3>> result(levels.size());
  // The level buffer is bounded by GL_MAX_SHADER_STORAGE_BLOCK_SIZE: upload in slices.
  for (std::size_t begin = 0; begin < levels.size(); begin += max_patches_per_upload_) {
    const std::size_t n = std::min(max_patches_per_upload_, levels.size() - begin);
    capture_slice(layout, levels.data() + begin, n, result.data() + begin);
  }
  stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

void TessCapture::capture_slice(const TessLayout& layout, const TessLevels* levels, std::size_t count,
                                std::vector<glm::vec3>* result) {
  context_.make_current();
  context_.bind_default_framebuffer();  // surfaceless: a draw needs a bound FBO, discard or not
  const Program& program = program_for(layout);
  program.use();
  const GLint base_location = program.uniform("u_patch_base");  // one uniform, TCS and TES

  // Levels: two vec4 per patch, raw bits.
  std::vector<float> packed(count * 8, 0.0f);
  for (std::size_t i = 0; i < count; ++i) {
    std::memcpy(&packed[i * 8], levels[i].outer.data(), 4 * sizeof(float));
    std::memcpy(&packed[i * 8 + 4], levels[i].inner.data(), 2 * sizeof(float));
  }
  ensure_buffer(GL_SHADER_STORAGE_BUFFER, level_buffer_, packed.size() * sizeof(float), level_capacity_);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(packed.size() * sizeof(float)),
                  packed.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, level_buffer_);

  glBindVertexArray(vao_);
  glPatchParameteri(GL_PATCH_VERTICES, 1);
  glEnable(GL_RASTERIZER_DISCARD);
  check_gl("TessCapture: setting up the capture");

  const GLenum mode = feedback_mode(layout);
  const int vpp = vertices_per_primitive(layout);
  std::vector<FeedbackVertex> records;

  std::vector<std::size_t> point_bounds(count);
  for (std::size_t i = 0; i < count; ++i) point_bounds[i] = domain_point_bound(layout, levels[i]);
  const std::vector<DrawRange> draws =
      split_draws(point_bounds, options_.max_points_per_draw, options_.max_patches_per_draw);
  try {
    for (const DrawRange& draw : draws) {
      const std::size_t first = draw.first, end = draw.first + draw.count;
      std::size_t emitted = 0;
      for (std::size_t i = first; i < end; ++i) emitted += emitted_vertex_bound(layout, levels[i]);
      const std::size_t capacity_vertices = std::max<std::size_t>(emitted, vpp);
      ensure_buffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedback_buffer_,
                    capacity_vertices * sizeof(FeedbackVertex), feedback_capacity_);
      glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedback_buffer_, 0,
                        static_cast<GLsizeiptr>(capacity_vertices * sizeof(FeedbackVertex)));
      glUniform1i(base_location, static_cast<GLint>(first));

      const std::uint64_t written = draw_with_feedback(
          mode, query_generated_, query_written_,
          [&] { glDrawArrays(GL_PATCHES, static_cast<GLint>(first), static_cast<GLsizei>(end - first)); },
          "TessCapture", "patches " + std::to_string(first) + ".." + std::to_string(end - 1) +
                             ": the vertex bound is wrong");

      const std::size_t nv = static_cast<std::size_t>(written) * vpp;
      records.resize(nv);
      if (nv)
        glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0,
                           static_cast<GLsizeiptr>(nv * sizeof(FeedbackVertex)), records.data());
      check_gl("TessCapture: reading transform feedback");

      // Every vertex must carry its own patch's id, patches in draw order, each primitive
      // wholly inside one patch; anything else is the driver mixing up vertices.
      std::int64_t prev = static_cast<std::int64_t>(first);
      std::vector<std::size_t> counts(end - first, 0);
      for (std::size_t v = 0; v < nv; ++v) {
        const std::int64_t id = records[v].patch;
        const std::int64_t prim_id = records[v - v % vpp].patch;
        if (id < static_cast<std::int64_t>(first) || id >= static_cast<std::int64_t>(end) || id < prev ||
            id != prim_id)
          throw GlError("TessCapture: captured vertex " + std::to_string(v) + " of a draw of patches " +
                        std::to_string(first) + ".." + std::to_string(end - 1) + " is tagged patch " +
                        std::to_string(id) + ": the driver mixed up patches (more than 65,535 domain " +
                        "points in one draw?)");
        prev = id;
        ++counts[static_cast<std::size_t>(id) - first];
      }
      // Exact sizes up front: growing large vectors means mmap/munmap churn in glibc.
      for (std::size_t i = first; i < end; ++i) result[i].reserve(result[i].size() + counts[i - first]);
      for (std::size_t v = 0; v < nv; ++v) {
        glm::vec3 c;
        std::memcpy(&c, records[v].coord, sizeof c);  // bit-exact
        result[static_cast<std::size_t>(records[v].patch)].push_back(c);
      }
      // Each patch's own bound must hold too (it sized the buffer).
      for (std::size_t i = first; i < end; ++i)
        if (result[i].size() > emitted_vertex_bound(layout, levels[i]))
          throw GlError("TessCapture: patch " + std::to_string(i) + " emitted " +
                        std::to_string(result[i].size()) + " vertices, above its bound");
      stats_.vertices += nv;
      ++stats_.draws;
    }
  } catch (...) {
    if (glIsEnabled(GL_RASTERIZER_DISCARD)) glDisable(GL_RASTERIZER_DISCARD);
    while (glGetError() != GL_NO_ERROR) {
    }
    throw;
  }
  glDisable(GL_RASTERIZER_DISCARD);
}

std::vector<std::vector<glm::vec3>> capture_tess_coords(GlContext& context, const TessLayout& layout,
                                                        const std::vector<TessLevels>& levels) {
  TessCapture capture(context);
  return capture.capture(layout, levels);
}

}  // namespace tessref::glref
