#include "render/transform_feedback.h"

#include <cstring>
#include <stdexcept>

#include "common/error.h"

namespace tessref {
namespace {

// GL 4.5's minimum GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS and _SEPARATE_COMPONENTS.
constexpr std::size_t kMaxInterleavedComponents = 64, kMaxSeparateComponents = 4;

const char* primitive_name(int corners) { return corners == 1 ? "GL_POINTS" : corners == 2 ? "GL_LINES" : "GL_TRIANGLES"; }

}  // namespace

std::string feedback_file_name(std::size_t draw, std::size_t buffer) {
  return "feedback.draw" + std::to_string(draw) + ".buffer" + std::to_string(buffer) + ".bin";
}

FeedbackRecorder::FeedbackRecorder(const Scene& scene, std::size_t draw, const glsl::GlslProgram& program)
    : scene_(scene) {
  const TransformFeedbackSetting& t = *scene.draws.at(draw).transform_feedback;
  out_.draw = draw;
  out_.bytes.resize(t.buffers());
  std::size_t buffer = 0, components = 0;
  for (std::size_t i = 0; i < t.varyings.size(); ++i) {
    const std::string& name = t.varyings[i];
    const std::string key = t.key + ".varyings." + std::to_string(i);
    if (name == "gl_NextBuffer") {
      ++buffer;
      continue;
    }
    Field f;
    f.buffer = t.separate ? i : buffer;
    if (name.rfind("gl_SkipComponents", 0) == 0) {
      f.floats.assign(std::size_t(name.back() - '0'), -1);
    } else {
      try {
        f.floats = program.output_floats(name);
      } catch (const std::invalid_argument& e) {
        throw InputError(scene.source + ": " + key + ": " + e.what() + " (glTransformFeedbackVaryings: the program "
                         "would fail to link)");
      }
      if (t.separate && f.floats.size() > kMaxSeparateComponents)
        throw InputError(scene.source + ": " + key + ": \"" + name + "\" has " + std::to_string(f.floats.size()) +
                         " components; GL guarantees " + std::to_string(kMaxSeparateComponents) +
                         " per separate attribute (GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS)");
    }
    components += f.floats.size();
    fields_.push_back(std::move(f));
  }
  if (!t.separate && components > kMaxInterleavedComponents)
    throw InputError(scene.source + ": " + t.key + ".varyings: " + std::to_string(components) +
                     " components interleaved; GL guarantees " + std::to_string(kMaxInterleavedComponents) +
                     " (GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS)");
}

void FeedbackRecorder::record(int corners, std::size_t count, const std::function<const float*(std::size_t, int)>& vertex) {
  if (out_.corners && corners != out_.corners)
    throw InputError(scene_.source + ": " + scene_.draws[out_.draw].key + ": transform feedback records " +
                     primitive_name(out_.corners) + " and the draw's later primitives are " + primitive_name(corners) +
                     " (GL: GL_INVALID_OPERATION)");
  out_.corners = corners;
  for (std::size_t p = 0; p < count; ++p)
    for (int k = 0; k < corners; ++k) {
      const float* v = vertex(p, k);
      for (const Field& f : fields_) {
        std::vector<std::byte>& bytes = out_.bytes[f.buffer];
        const std::size_t at = bytes.size();
        bytes.resize(at + 4 * f.floats.size());
        for (std::size_t w = 0; w < f.floats.size(); ++w)
          if (f.floats[w] >= 0) std::memcpy(bytes.data() + at + 4 * w, v + f.floats[w], 4);
      }
    }
  out_.primitives += count;
}

}  // namespace tessref
