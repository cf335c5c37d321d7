#include "glref/raster_probe.h"

#include <epoxy/gl.h>

#include <string>

#include "glref/gl_context.h"
#include "glref/gl_error.h"
#include "glref/gl_program.h"
#include "glref/render_target.h"

namespace tessref::glref {
namespace {

const char* kVertexShader = R"(#version 450 core
layout(location = 0) in vec4 position;
layout(location = 0) uniform int corners;  // vertices per primitive
flat out int v_id;
void main() {
  gl_Position = position;
  v_id = gl_VertexID / corners;
}
)";

// Attachments 0 and 1: bit (id % 24) of channel id / 24, blended additively. Attachment 2:
// id and gl_FragCoord, unblended (the last fragment wins).
const char* kFragmentShader = R"(#version 450 core
flat in int v_id;
layout(location = 0) out vec4 mask0;
layout(location = 1) out vec4 mask1;
layout(location = 2) out vec4 last;
void main() {
  const int word = v_id / 24;
  const float bit = float(1 << (v_id % 24));
  vec4 m0 = vec4(0.0), m1 = vec4(0.0);
  if (word < 4) m0[word] = bit; else m1[word - 4] = bit;
  mask0 = m0;
  mask1 = m1;
  last = vec4(float(v_id), gl_FragCoord.xyz);
}
)";

}  // namespace

struct CoverageProber::Impl {
  GlContext& context;
  RenderTarget target;
  Program program;
  GLuint vao = 0, vbo = 0;

  Impl(GlContext& c, int w, int h)
      : context(c),
        target(c, {w, h, {ColorFormat::kRgba32F, ColorFormat::kRgba32F, ColorFormat::kRgba32F}, true}),
        program(link_program({{GL_VERTEX_SHADER, kVertexShader, "raster_probe.vert"},
                              {GL_FRAGMENT_SHADER, kFragmentShader, "raster_probe.frag"}})) {
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glEnableVertexAttribArray(0);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    check_gl("CoverageProber: creating buffers");
  }
  ~Impl() {
    context.make_current();
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
  }
};

CoverageProber::CoverageProber(GlContext& context, int width, int height)
    : impl_(std::make_unique<Impl>(context, width, height)) {}

CoverageProber::~CoverageProber() = default;

CoverageProbe CoverageProber::draw(const std::vector<glm::vec4>& clip_positions,
                                   unsigned depth_func, unsigned mode, unsigned polygon_mode) {
  const int corners = mode == GL_TRIANGLES ? 3 : mode == GL_LINES ? 2 : mode == GL_POINTS ? 1 : 0;
  if (corners == 0) throw GlError("CoverageProber::draw: mode must be GL_TRIANGLES, GL_LINES or GL_POINTS");
  if (clip_positions.size() % std::size_t(corners) != 0 ||
      clip_positions.size() / std::size_t(corners) > static_cast<std::size_t>(kProbeMaxTriangles))
    throw GlError("CoverageProber::draw: " + std::to_string(clip_positions.size()) +
                  " vertices, want whole primitives, at most " +
                  std::to_string(kProbeMaxTriangles));
  Impl& s = *impl_;
  s.context.make_current();
  s.target.clear(glm::vec4(0.0f), 1.0f);  // binds the target, viewport = whole target
  // Attachment 2 starts at id -1: "no fragment".
  const glm::vec4 none(-1.0f, 0.0f, 0.0f, 0.0f);
  glClearBufferfv(GL_COLOR, 2, &none[0]);

  glBindBuffer(GL_ARRAY_BUFFER, s.vbo);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(clip_positions.size() * sizeof(glm::vec4)),
               clip_positions.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_MULTISAMPLE);
  glDepthRangef(0.0f, 1.0f);
  if (depth_func) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth_func);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glEnablei(GL_BLEND, 0);
  glEnablei(GL_BLEND, 1);
  glDisablei(GL_BLEND, 2);
  glBlendFunc(GL_ONE, GL_ONE);
  glBlendEquation(GL_FUNC_ADD);
  s.program.use();
  glUniform1i(0, corners);
  glPolygonMode(GL_FRONT_AND_BACK, GLenum(polygon_mode));
  glBindVertexArray(s.vao);
  glDrawArrays(GLenum(mode), 0, GLsizei(clip_positions.size()));
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glBindVertexArray(0);
  glUseProgram(0);
  glDisablei(GL_BLEND, 0);
  glDisablei(GL_BLEND, 1);
  glDisable(GL_DEPTH_TEST);
  check_gl("CoverageProber::draw");

  CoverageProbe out;
  out.width = s.target.width();
  out.height = s.target.height();
  const std::size_t n = std::size_t(out.width) * out.height;
  const std::vector<glm::vec4> m0 = s.target.read_rgba_float(0);
  const std::vector<glm::vec4> m1 = s.target.read_rgba_float(1);
  const std::vector<glm::vec4> last = s.target.read_rgba_float(2);
  out.depth = s.target.read_depth();
  out.mask.assign(n, {0, 0, 0});
  out.last.resize(n);
  out.frag_coord.resize(n);
  const bool sets = polygon_mode == GL_FILL;
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 8 && sets; ++c) {
      const float v = c < 4 ? m0[i][c] : m1[i][c - 4];
      // Integers below 2^24 (each id at most once); the bits of channel c are ids 24c + k.
      const auto bits = static_cast<std::uint64_t>(v);
      if (float(bits) != v || bits >= (1u << 24))
        throw GlError("CoverageProber::draw: pixel " + std::to_string(i) + " channel " +
                      std::to_string(c) + " holds " + std::to_string(v) +
                      ", not a set of ids (a triangle covered it twice?)");
      for (int k = 0; k < 24; ++k)
        if (bits >> k & 1) {
          const int id = 24 * c + k;
          out.mask[i][id / 64] |= std::uint64_t(1) << (id % 64);
        }
    }
    out.last[i] = static_cast<int>(last[i].x);
    out.frag_coord[i] = glm::vec3(last[i].y, last[i].z, last[i].w);
  }
  return out;
}

}  // namespace tessref::glref
