#include "render/transform_feedback.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "common/error.h"

namespace tessref {
namespace {

// GL 4.5's minimum GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS and _SEPARATE_COMPONENTS.
constexpr std::size_t kMaxInterleavedComponents = 64, kMaxSeparateComponents = 4;

const char* primitive_name(int corners) { return corners == 1 ? "GL_POINTS" : corners == 2 ? "GL_LINES" : "GL_TRIANGLES"; }

}  // namespace

std::vector<std::pair<std::size_t, std::string>> feedback_files(const Scene& scene, const std::string& prefix) {
  std::vector<std::pair<std::size_t, std::string>> files;
  for (std::size_t d = 0; d < scene.draws.size(); ++d)
    if (const auto& t = scene.draws[d].transform_feedback)
      for (std::size_t b = 0; b < t->buffers(); ++b)
        files.emplace_back(d, prefix + ".draw" + std::to_string(d) + ".buffer" + std::to_string(b) + ".bin");
  return files;
}

FeedbackRecorder::FeedbackRecorder(const Scene& scene, std::size_t draw, const glsl::GlslProgram& program)
    : scene_(scene) {
  const TransformFeedbackSetting& t = *scene.draws.at(draw).transform_feedback;
  out_.draw = draw;
  out_.bytes.resize(t.buffers());
  out_.buffer_streams.assign(t.buffers(), -1);
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
      glsl::OutputWords words;
      try {
        words = program.output_floats(name);
      } catch (const std::invalid_argument& e) {
        throw InputError(scene.source + ": " + key + ": " + e.what() + " (glTransformFeedbackVaryings: the program "
                         "would fail to link)");
      }
      f.floats = std::move(words.floats);
      // GL 4.5, 11.1.2.1: one buffer records one vertex stream.
      int& stream = out_.buffer_streams[f.buffer];
      if (stream >= 0 && stream != words.stream)
        throw InputError(scene.source + ": " + key + ": \"" + name + "\" is emitted on vertex stream " +
                         std::to_string(words.stream) + " and buffer " + std::to_string(f.buffer) + " records stream " +
                         std::to_string(stream) + " (one stream a buffer: put gl_NextBuffer between them)");
      stream = words.stream;
      if (t.separate && f.floats.size() > kMaxSeparateComponents)
        throw InputError(scene.source + ": " + key + ": \"" + name + "\" has " + std::to_string(f.floats.size()) +
                         " components; GL guarantees " + std::to_string(kMaxSeparateComponents) +
                         " per separate attribute (GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS)");
    }
    components += f.floats.size();
    fields_.push_back(std::move(f));
  }
  for (int& stream : out_.buffer_streams) stream = std::max(stream, 0);  // skipped words alone: stream 0
  if (!t.separate && components > kMaxInterleavedComponents)
    throw InputError(scene.source + ": " + t.key + ".varyings: " + std::to_string(components) +
                     " components interleaved; GL guarantees " + std::to_string(kMaxInterleavedComponents) +
                     " (GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS)");
}

void FeedbackRecorder::record(int stream, int corners, std::size_t count,
                              const std::function<const float*(std::size_t, int)>& vertex) {
  out_.stream_primitives[std::size_t(stream)] += count;
  if (stream != 0) {
    record_stream(stream, corners, count, vertex);
    return;
  }
  if (out_.corners && corners != out_.corners)
    throw InputError(scene_.source + ": " + scene_.draws[out_.draw].key + ": transform feedback records " +
                     primitive_name(out_.corners) + " and the draw's later primitives are " + primitive_name(corners) +
                     " (GL: GL_INVALID_OPERATION)");
  out_.corners = corners;
  out_.primitives += count;
  record_stream(0, corners, count, vertex);
}

void FeedbackRecorder::record_stream(int stream, int corners, std::size_t count,
                                     const std::function<const float*(std::size_t, int)>& vertex) {
  for (std::size_t p = 0; p < count; ++p)
    for (int k = 0; k < corners; ++k) {
      const float* v = vertex(p, k);
      for (const Field& f : fields_) {
        if (out_.buffer_streams[f.buffer] != stream) continue;
        std::vector<std::byte>& bytes = out_.bytes[f.buffer];
        const std::size_t at = bytes.size();
        bytes.resize(at + 4 * f.floats.size());
        for (std::size_t w = 0; w < f.floats.size(); ++w)
          if (f.floats[w] >= 0) std::memcpy(bytes.data() + at + 4 * w, v + f.floats[w], 4);
      }
    }
}

}  // namespace tessref
