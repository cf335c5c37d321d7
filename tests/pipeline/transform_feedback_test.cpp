// draws[].transform_feedback on tessref alone: what the buffers hold (each word checked against
// the evaluation shader's formula), the interleaved and separate layouts, the same bytes for any
// thread count and batch size, and the errors a GL linker would give. The same scenes against
// llvmpipe, byte for byte: tests/glref/verify_vs_llvmpipe_test.cpp.
#include <array>
#include <cstring>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "render/transform_feedback.h"
#include "scene/scene_loader.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;

const std::string kDraws = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/";

std::vector<FeedbackBuffers> record(const std::string& file, const std::vector<std::string>& sets = {}, int threads = 2) {
  const Scene scene = load_scene(kDraws + file, sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  Framebuffer fb;
  std::vector<FeedbackBuffers> out;
  render_scene(scene, mesh, Parallel(threads), fb, {}, &out);
  return out;
}

std::string error_of(const std::string& file, const std::vector<std::string>& sets) {
  try {
    record(file, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

template <class T>
T word(const std::vector<std::byte>& bytes, std::size_t w) {
  T v;
  std::memcpy(&v, bytes.data() + 4 * w, 4);
  return v;
}

// The patches' first corners (feedback_*.json's buffer "corners": a 2 x 2 grid of half squares).
glm::vec2 corner(int patch) { return {-1.0f + float(patch % 2), -1.0f + float(patch / 2)}; }

TEST(TransformFeedback, SeparateBuffersHoldEachOutputOfEachVertex) {
  const std::vector<FeedbackBuffers> f = record("feedback_separate.json");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].draw, 0u);
  EXPECT_EQ(f[0].corners, 3);
  EXPECT_EQ(f[0].primitives, 74u);  // the four patches' triangles at their fractional even levels
  const std::size_t vertices = 74 * 3;
  ASSERT_EQ(f[0].bytes.size(), 3u);
  ASSERT_EQ(f[0].bytes[0].size(), vertices * 12);  // vec3 f_coord
  ASSERT_EQ(f[0].bytes[1].size(), vertices * 4);   // int f_patch
  ASSERT_EQ(f[0].bytes[2].size(), vertices * 16);  // gl_Position
  int last_patch = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    const glm::vec3 c(word<float>(f[0].bytes[0], 3 * v), word<float>(f[0].bytes[0], 3 * v + 1), word<float>(f[0].bytes[0], 3 * v + 2));
    const int patch = word<int>(f[0].bytes[1], v);
    ASSERT_GE(patch, last_patch) << v;  // patches in order
    ASSERT_LE(patch, 3) << v;
    last_patch = patch;
    EXPECT_EQ(word<float>(f[0].bytes[2], 4 * v), c.x * 0.5f + corner(patch).x) << v;
    EXPECT_EQ(word<float>(f[0].bytes[2], 4 * v + 1), c.y * 0.5f + corner(patch).y) << v;
    EXPECT_EQ(word<float>(f[0].bytes[2], 4 * v + 2), c.z * 0.5f) << v;
    EXPECT_EQ(word<float>(f[0].bytes[2], 4 * v + 3), 1.0f) << v;
  }
  EXPECT_EQ(last_patch, 3);
}

// gl_Position, gl_SkipComponents1 and f_coord into buffer 0 (8 words a vertex, the skipped one
// zero), gl_NextBuffer, f_patch into buffer 1.
TEST(TransformFeedback, InterleavedBuffersFollowNextBufferAndSkipComponents) {
  const std::vector<FeedbackBuffers> f = record("feedback_interleaved.json");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].primitives, 92u);
  const std::size_t vertices = 92 * 3;
  ASSERT_EQ(f[0].bytes.size(), 2u);
  ASSERT_EQ(f[0].bytes[0].size(), vertices * 32);
  ASSERT_EQ(f[0].bytes[1].size(), vertices * 4);
  for (std::size_t v = 0; v < vertices; ++v) {
    const int patch = word<int>(f[0].bytes[1], v);
    const float x = word<float>(f[0].bytes[0], 8 * v + 5), y = word<float>(f[0].bytes[0], 8 * v + 6);
    EXPECT_EQ(word<float>(f[0].bytes[0], 8 * v), x * 0.5f + corner(patch).x) << v;
    EXPECT_EQ(word<float>(f[0].bytes[0], 8 * v + 1), y * 0.5f + corner(patch).y) << v;
    EXPECT_EQ(word<std::uint32_t>(f[0].bytes[0], 8 * v + 4), 0u) << v;  // skipped
    EXPECT_EQ(word<float>(f[0].bytes[0], 8 * v + 7), 0.0f) << v;         // gl_TessCoord.z on quads
  }
}

// The geometry shader's strips arrive as triangles in GL's order: per input triangle (a, b, c),
// the strip a, b, c, a gives (a, b, c) and, odd, (c, b, a).
TEST(TransformFeedback, GeometryShaderStripsAreRecordedInGlsVertexOrder) {
  const std::vector<FeedbackBuffers> f = record("feedback_geometry.json");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].primitives, 148u);  // two for each of feedback_separate.json's 74
  const std::vector<std::byte>& b = f[0].bytes[0];
  ASSERT_EQ(b.size(), 148u * 3 * 32);
  for (std::size_t t = 0; t < 74; ++t) {
    const auto tag = [&](std::size_t vertex) { return word<int>(b, 8 * vertex + 7); };
    const int base = 4 * int(t);
    EXPECT_EQ(tag(6 * t), base);
    EXPECT_EQ(tag(6 * t + 1), base + 1);
    EXPECT_EQ(tag(6 * t + 2), base + 2);
    EXPECT_EQ(tag(6 * t + 3), base + 2);
    EXPECT_EQ(tag(6 * t + 4), base + 1);
    EXPECT_EQ(tag(6 * t + 5), base + 3);
  }
}

// Stream 0's points into buffer 0, stream 1's into buffer 1 (after gl_NextBuffer), each counted.
TEST(TransformFeedback, EachBufferRecordsTheStreamItsOutputsAreEmittedOn) {
  const std::vector<FeedbackBuffers> f = record("feedback_streams.json");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].corners, 1);
  EXPECT_EQ(f[0].primitives, 222u);
  EXPECT_EQ(f[0].stream_primitives, (std::array<std::uint64_t, 4>{222, 74, 0, 0}));
  EXPECT_EQ(f[0].buffer_streams, (std::vector<int>{0, 1}));
  ASSERT_EQ(f[0].bytes[0].size(), 222u * 28);  // gl_Position, g_coord
  ASSERT_EQ(f[0].bytes[1].size(), 74u * 16);   // g_first
  for (std::size_t t = 0; t < 74; ++t) {
    // Stream 1's point t: triangle t's first corner (stream 0's point 3t) and its index.
    for (int c = 0; c < 3; ++c) EXPECT_EQ(word<float>(f[0].bytes[1], 4 * t + c), word<float>(f[0].bytes[0], 7 * 3 * t + 4 + c)) << t;
    EXPECT_EQ(word<float>(f[0].bytes[1], 4 * t + 3), float(t));
  }
  // Outputs of two streams in one buffer: refused.
  EXPECT_THAT(error_of("feedback_streams.json", {"draws.0.transform_feedback.varyings=[\"g_coord\",\"g_first\"]"}),
              HasSubstr("varyings.1: \"g_first\" is emitted on vertex stream 1 and buffer 0 records stream 0"));
}

TEST(TransformFeedback, SameBytesForAnyThreadCountAndBatchSize) {
  for (const std::string file : {"feedback_interleaved.json", "feedback_separate.json", "feedback_geometry.json",
                                 "feedback_streams.json"}) {
    const std::vector<FeedbackBuffers> one = record(file, {}, 1);
    for (const int threads : {2, 8})
      for (const std::string lanes : {"1", "7", "64"}) {
        const std::vector<FeedbackBuffers> other = record(file, {"shaders.batch_lanes=" + lanes}, threads);
        ASSERT_EQ(one.size(), other.size()) << file;
        for (std::size_t k = 0; k < one.size(); ++k) EXPECT_EQ(one[k].bytes, other[k].bytes) << file << " " << threads << " " << lanes;
      }
  }
}

TEST(TransformFeedback, WhatALinkerRefusesIsRefusedByKey) {
  const std::string f = "feedback_separate.json";
  EXPECT_THAT(error_of(f, {"draws.0.transform_feedback.varyings=[\"f_color\"]"}),
              HasSubstr("draws.0.transform_feedback.varyings.0: 'f_color' is not an output of the tessellation "
                        "evaluation shader (the last stage before the rasterizer) (glTransformFeedbackVaryings: the "
                        "program would fail to link)"));
  EXPECT_THAT(error_of(f, {"draws.0.transform_feedback.varyings=[\"f_coord[1]\"]"}),
              HasSubstr("'f_coord[1]': f_coord is not an array"));
  EXPECT_THAT(error_of(f, {"draws.0.transform_feedback.varyings=[\"gl_PointSize\"]"}),
              HasSubstr("'gl_PointSize' is not written by the stage"));
  EXPECT_THAT(error_of(f, {"draws.0.transform_feedback.varyings=[\"f_coord\",\"gl_SkipComponents1\"]"}),
              HasSubstr("\"gl_SkipComponents1\" is for GL_INTERLEAVED_ATTRIBS only"));
  EXPECT_THAT(error_of(f, {"draws.0.transform_feedback.varyings=[\"f_coord\",\"f_coord\"]"}),
              HasSubstr("\"f_coord\" is named twice"));
  EXPECT_THAT(error_of(f, {"draws.0.transform_feedback.buffer_mode=\"GL_INTERLEAVED_ATTRIBS\"",
                           "draws.0.transform_feedback.varyings=[\"f_coord\",\"gl_NextBuffer\",\"f_patch\",\"gl_NextBuffer\","
                           "\"gl_Position\",\"gl_NextBuffer\",\"gl_SkipComponents4\",\"gl_NextBuffer\",\"gl_SkipComponents2\"]"}),
              HasSubstr("5 buffers; GL guarantees 4 buffers (GL_MAX_TRANSFORM_FEEDBACK_BUFFERS)"));
  EXPECT_THAT(error_of(f, {"draws.0.transform_feedback.buffer_mode=\"GL_FEEDBACK\""}),
              HasSubstr("buffer_mode: expected GL_INTERLEAVED_ATTRIBS or GL_SEPARATE_ATTRIBS, got \"GL_FEEDBACK\""));
}

}  // namespace
}  // namespace tessref
