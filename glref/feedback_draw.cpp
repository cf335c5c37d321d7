#include "glref/feedback_draw.h"

#include <epoxy/gl.h>

#include "glref/gl_error.h"

namespace tessref::glref {

std::uint64_t draw_with_feedback(unsigned primitive, unsigned query_generated,
                                 unsigned query_written, const std::function<void()>& draw,
                                 const std::string& what, const std::string& hint) {
  glBeginQuery(GL_PRIMITIVES_GENERATED, query_generated);
  glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, query_written);
  glBeginTransformFeedback(primitive);
  draw();
  glEndTransformFeedback();
  glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
  glEndQuery(GL_PRIMITIVES_GENERATED);
  check_gl((what + ": drawing").c_str());
  GLuint64 generated = 0, written = 0;
  glGetQueryObjectui64v(query_generated, GL_QUERY_RESULT, &generated);
  glGetQueryObjectui64v(query_written, GL_QUERY_RESULT, &written);
  if (written != generated)
    throw GlError(what + ": transform feedback captured " + std::to_string(written) + " of " +
                  std::to_string(generated) + " primitives (" + hint + ")");
  return written;
}

}  // namespace tessref::glref
