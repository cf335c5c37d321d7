#pragma once
// draws[].transform_feedback: the bytes GL's transform feedback writes for a draw (OpenGL 4.5,
// 13.2). Each primitive the rasterizer receives, before clipping (after the geometry shader,
// whose strips arrive as separate primitives in GL's vertex order), is recorded vertex by vertex:
// the named outputs' 32-bit words, interleaved into one buffer (gl_NextBuffer starts the next
// buffer, gl_SkipComponentsN leaves N words as they were: zero here) or each into a buffer of
// its own (GL_SEPARATE_ATTRIBS). tessref's buffers grow with the draw, as a GL buffer large
// enough for every primitive would be filled.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"
#include "stages/glsl/glsl_program.h"

namespace tessref {

struct FeedbackBuffers {
  std::size_t draw = 0;                       // into Scene::draws
  std::vector<std::vector<std::byte>> bytes;  // one per buffer binding 0, 1, ...
  std::vector<int> buffer_streams;            // the vertex stream each buffer records
  std::uint64_t primitives = 0;               // GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN (stream 0)
  std::array<std::uint64_t, 4> stream_primitives{};  // the same query indexed by stream
  int corners = 0;                            // vertices per stream-0 primitive (0: none recorded)
};

// The file of each buffer of each draw with a transform_feedback key, in draw and buffer order:
// (draw, "PREFIX.drawD.bufferB.bin"). A capture folder's are "feedback.drawD.bufferB.bin".
std::vector<std::pair<std::size_t, std::string>> feedback_files(const Scene& scene, const std::string& prefix);

// One draw's recording. The constructor resolves the varyings against the program's last vertex
// stage as a GL linker would: InputError naming the scene key for a name that is not an output,
// or more components than GL guarantees (64 interleaved, 4 per separate attribute).
class FeedbackRecorder {
 public:
  FeedbackRecorder(const Scene& scene, std::size_t draw, const glsl::GlslProgram& program);
  // DrawOptions::primitives' signature. A draw records one primitive type (GL: the mode of
  // glBeginTransformFeedback); InputError if a later call changes it. A geometry shader's
  // streams 1..3 go to the buffers whose outputs it emits on them (layout(stream = N)).
  void record(int stream, int corners, std::size_t count, const std::function<const float*(std::size_t, int)>& vertex);
  const FeedbackBuffers& buffers() const { return out_; }

 private:
  struct Field {
    std::size_t buffer = 0;
    std::vector<int> floats;  // the vertex's float for each word; -1: a zero word
  };
  void record_stream(int stream, int corners, std::size_t count, const std::function<const float*(std::size_t, int)>& vertex);

  const Scene& scene_;
  std::vector<Field> fields_;
  FeedbackBuffers out_;
};

}  // namespace tessref
