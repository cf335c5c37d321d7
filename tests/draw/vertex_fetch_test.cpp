#include "draw/vertex_fetch.h"

#include <bit>
#include <cstring>

#include <gtest/gtest.h>

#include "common/error.h"

namespace tessref::draw {
namespace {

template <typename T>
Buffer buffer_of(const std::string& name, std::initializer_list<T> values) {
  Buffer b{name, {}};
  for (T v : values) {
    const auto* p = reinterpret_cast<const std::byte*>(&v);
    b.bytes.insert(b.bytes.end(), p, p + sizeof v);
  }
  return b;
}

VertexArray float_array(std::uint32_t location, int size, std::size_t buffer, std::size_t stride = 0,
                        std::size_t offset = 0) {
  VertexArray a;
  a.key = "vertex_arrays." + std::to_string(location);
  a.location = location;
  a.format = {size, false, ComponentType::Float, false, AttribPointer::Float};
  a.buffer = buffer;
  a.stride = stride;
  a.offset = offset;
  return a;
}

float word(const glsl::VertexAttribute& a, std::size_t vertex, int component) {
  return std::bit_cast<float>(a.words[vertex * 4 + std::size_t(component)]);
}

TEST(VertexFetch, DrawArraysRunsFirstToFirstPlusCount) {
  const std::vector<Buffer> buffers{buffer_of<float>("p", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9})};
  const VertexArray arrays[] = {float_array(0, 2, 0)};
  DrawCall call;
  call.first = 2;
  call.count = 3;
  const VertexInput in = fetch_vertices(buffers, arrays, std::nullopt, {}, call);
  EXPECT_EQ(in.vertex_ids, (std::vector<std::uint32_t>{2, 3, 4}));
  ASSERT_EQ(in.runs.size(), 1u);
  EXPECT_EQ(in.runs[0], (std::vector<std::uint32_t>{0, 1, 2}));
  ASSERT_EQ(in.per_vertex.size(), 1u);
  EXPECT_EQ(word(in.per_vertex[0], 0, 0), 4.0f);  // vertex 2: bytes 16..24
  EXPECT_EQ(word(in.per_vertex[0], 2, 1), 9.0f);
  EXPECT_EQ(word(in.per_vertex[0], 2, 3), 1.0f);
}

TEST(VertexFetch, InterleavedStrideAndOffset) {
  // Two vertices of (x, y, z, r, g, b) floats; the colour read at offset 12, stride 24.
  const std::vector<Buffer> buffers{buffer_of<float>("v", {0, 0, 0, 0.25f, 0.5f, 0.75f, 1, 1, 1, 1, 0, 0})};
  const VertexArray arrays[] = {float_array(0, 3, 0, 24, 0), float_array(1, 3, 0, 24, 12)};
  DrawCall call;
  call.count = 2;
  const VertexInput in = fetch_vertices(buffers, arrays, std::nullopt, {}, call);
  EXPECT_EQ(word(in.per_vertex[1], 0, 2), 0.75f);
  EXPECT_EQ(word(in.per_vertex[1], 1, 0), 1.0f);
  EXPECT_EQ(word(in.per_vertex[0], 1, 2), 1.0f);
}

TEST(VertexFetch, ElementsWithBaseVertexKeepGlsVertexIds) {
  std::vector<Buffer> buffers{buffer_of<float>("p", {0, 1, 2, 3, 4, 5, 6, 7}),
                              buffer_of<std::uint16_t>("i", {9, 1, 0, 1, 3})};
  const VertexArray arrays[] = {float_array(0, 1, 0)};
  ElementArray e{"elements", 1, IndexType::UnsignedShort, 2};  // skips the first index
  DrawCall call;
  call.count = 4;
  call.base_vertex = 2;
  const VertexInput in = fetch_vertices(buffers, arrays, e, {}, call);
  // Indices 1 0 1 3 + basevertex 2: vertices 3 2 3 5, each shaded once.
  EXPECT_EQ(in.vertex_ids, (std::vector<std::uint32_t>{3, 2, 5}));
  EXPECT_EQ(in.runs[0], (std::vector<std::uint32_t>{0, 1, 0, 2}));
  EXPECT_EQ(word(in.per_vertex[0], 2, 0), 5.0f);
}

TEST(VertexFetch, PrimitiveRestartSplitsRunsBeforeBaseVertex) {
  std::vector<Buffer> buffers{buffer_of<float>("p", {0, 1, 2, 3, 4, 5, 6, 7}),
                              buffer_of<std::uint8_t>("i", {0, 1, 255, 2, 3, 255, 255, 4})};
  const VertexArray arrays[] = {float_array(0, 1, 0)};
  ElementArray e{"elements", 1, IndexType::UnsignedByte, 0};
  DrawCall call;
  call.count = 8;
  call.base_vertex = 1;
  const VertexInput fixed = fetch_vertices(buffers, arrays, e, {true, true, 0}, call);
  ASSERT_EQ(fixed.runs.size(), 3u);  // consecutive restarts make no empty run
  EXPECT_EQ(fixed.runs[1], (std::vector<std::uint32_t>{2, 3}));
  EXPECT_EQ(fixed.vertex_ids.back(), 5u);
  // GL_PRIMITIVE_RESTART with index 2: 255 is an index like any other (and reads past the buffer).
  EXPECT_THROW(fetch_vertices(buffers, arrays, e, {true, false, 2}, call), InputError);
  const VertexInput off = fetch_vertices(buffers, arrays, e, {true, false, 2}, call, {true});
  EXPECT_EQ(off.runs.size(), 2u);
  EXPECT_EQ(word(off.per_vertex[0], 2, 0), 0.0f);  // vertex 256 read as zero bytes (robust access)
}

TEST(VertexFetch, ReadsPastTheBufferNameTheArrayAndTheBytes) {
  const std::vector<Buffer> buffers{buffer_of<float>("p", {0, 1, 2, 3, 4, 5})};
  const VertexArray arrays[] = {float_array(0, 3, 0)};
  DrawCall call;
  call.count = 3;
  try {
    fetch_vertices(buffers, arrays, std::nullopt, {}, call);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "vertex_arrays.0: gl_VertexID 2 reads bytes [24, 36) of buffer 'p', which holds 24 bytes "
                           "(GL leaves such a read undefined; with robust_buffer_access it reads zero, as a robust "
                           "context may)");
  }
  const VertexInput robust = fetch_vertices(buffers, arrays, std::nullopt, {}, call, {true});
  EXPECT_EQ(word(robust.per_vertex[0], 2, 0), 0.0f);
  EXPECT_EQ(word(robust.per_vertex[0], 2, 3), 1.0f);  // the missing w still defaults to 1
}

TEST(VertexFetch, IndexRangePastTheElementBuffer) {
  std::vector<Buffer> buffers{buffer_of<float>("p", {0}), buffer_of<std::uint32_t>("i", {0, 0})};
  const VertexArray arrays[] = {float_array(0, 1, 0)};
  DrawCall call;
  call.count = 3;
  EXPECT_THROW(fetch_vertices(buffers, arrays, ElementArray{"elements", 1, IndexType::UnsignedInt, 0}, {}, call),
               InputError);
}

TEST(VertexFetch, InstancedArraysAndDisabledArrays) {
  const std::vector<Buffer> buffers{buffer_of<float>("p", {0, 1, 2}), buffer_of<float>("o", {10, 20, 30, 40})};
  std::vector<VertexArray> arrays{float_array(0, 1, 0), float_array(1, 1, 1)};
  arrays[1].divisor = 2;
  VertexArray current;
  current.location = 2;
  current.enabled = false;
  current.current.words = {std::bit_cast<std::uint32_t>(0.5f), 0, 0, std::bit_cast<std::uint32_t>(1.0f)};
  arrays.push_back(current);
  DrawCall call;
  call.count = 3;
  call.instance_count = 4;
  call.base_instance = 1;
  const VertexInput in = fetch_vertices(buffers, arrays, std::nullopt, {}, call);
  ASSERT_EQ(in.instanced, (std::vector<std::size_t>{1}));
  ASSERT_EQ(in.per_vertex.size(), 2u);
  EXPECT_TRUE(in.per_vertex[1].constant);
  EXPECT_EQ(in.per_vertex[1].location, 2u);
  const float expected[] = {20, 20, 30, 30};  // instance / 2 + baseinstance 1
  for (std::uint32_t i = 0; i < 4; ++i) {
    std::vector<glsl::VertexAttribute> out;
    fetch_instanced(buffers, arrays, in, call, i, {}, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(out[0].constant);
    EXPECT_EQ(out[0].location, 1u);
    EXPECT_EQ(word(out[0], 0, 0), expected[i]) << i;
  }
}

TEST(VertexFetch, DoubleVec4TakesTwoLocations) {
  const std::vector<Buffer> buffers{buffer_of<double>("d", {1.0, 2.0, 3.0, 4.0})};
  VertexArray a;
  a.location = 3;
  a.format = {4, false, ComponentType::Double, false, AttribPointer::Double};
  DrawCall call;
  call.count = 1;
  const VertexInput in = fetch_vertices(buffers, std::span<const VertexArray>(&a, 1), std::nullopt, {}, call);
  ASSERT_EQ(in.per_vertex.size(), 2u);
  EXPECT_EQ(in.per_vertex[1].location, 4u);
  double z;
  const std::uint64_t b = std::uint64_t(in.per_vertex[1].words[0]) | (std::uint64_t(in.per_vertex[1].words[1]) << 32);
  std::memcpy(&z, &b, 8);
  EXPECT_EQ(z, 3.0);
}

}  // namespace
}  // namespace tessref::draw
