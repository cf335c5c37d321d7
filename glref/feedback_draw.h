#pragma once
// A draw inside transform feedback, checked: every primitive the draw generated must have been
// written to the bound feedback buffer (a too-small buffer drops primitives without a GL error).
#include <cstdint>
#include <functional>
#include <string>

namespace tessref::glref {

// Runs draw() between glBeginTransformFeedback(primitive) and its end, counting with the two
// queries (GL_PRIMITIVES_GENERATED, GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN). Returns the
// primitives written; throws GlError naming `what` and `hint` when fewer than generated.
std::uint64_t draw_with_feedback(unsigned primitive, unsigned query_generated,
                                 unsigned query_written, const std::function<void()>& draw,
                                 const std::string& what, const std::string& hint);

}  // namespace tessref::glref
