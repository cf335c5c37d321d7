// Shader storage blocks written by every stage, and GL's atomic operations on them
// (tests/data/draws/storage_writes.json): the values GL fixes exactly (invocation counts where
// the spec gives them, each covered pixel shaded once, helper invocations without effects), the
// order tessref documents (docs/executor.md, "Side effects"), and the same bytes for any thread
// count and batch size.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "inspect/inspect_pixel.h"
#include "mesh/mesh_source.h"
#include "render/draw_scene.h"
#include "render/render.h"
#include "render/texture_load.h"
#include "scene/scene_loader.h"

namespace tessref {
namespace {

const std::string kScene = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/storage_writes.json";

struct Written {
  std::vector<std::uint32_t> counters, pixels;
  std::vector<float> records;
  std::vector<glm::vec4> colour;
};

template <class T>
std::vector<T> as(std::span<const std::byte> bytes) {
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

// Renders on 1 thread, then on 2 and 8 threads with 1, 7 and 64 batch lanes, and hands each of
// those results to expect_same(first, other, which).
template <class Render, class ExpectSame>
void for_every_thread_count_and_batch(Render&& render, ExpectSame&& expect_same) {
  const auto one = render(1, std::vector<std::string>{});
  for (const int threads : {2, 8})
    for (const std::string lanes : {"1", "7", "64"})
      expect_same(one, render(threads, std::vector<std::string>{"shaders.batch_lanes=" + lanes}),
                  std::to_string(threads) + " threads, " + lanes + " lanes");
}

Written render(int threads, const std::vector<std::string>& sets = {}) {
  const Scene scene = load_scene(kScene, sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  Framebuffer fb;
  DrawnMemory memory;
  render_scene(scene, mesh, Parallel(threads), fb, {}, nullptr, &memory);
  Written w;
  for (const draw::Buffer& b : memory.buffers) {
    if (b.name == "counters") w.counters = as<std::uint32_t>(b.bytes);
    if (b.name == "pixels") w.pixels = as<std::uint32_t>(b.bytes);
    if (b.name == "records") w.records = as<float>(b.bytes);
  }
  w.colour = fb.color;
  return w;
}

// Counters' words, in the block's order (storage.vert).
enum Counter { kVertices, kPatches, kEvaluations, kFragments, kMinX, kOrBits, kXorBits, kSwapped, kLast, kMaxY };

TEST(StorageBuffers, EveryStageCountsItsInvocationsAndEachAtomicGivesGlsResult) {
  const Written w = render(2);
  ASSERT_EQ(w.counters.size(), 10u);
  EXPECT_EQ(w.counters[kVertices], 16u);  // glDrawArrays of 16 vertices
  EXPECT_EQ(w.counters[kPatches], 4u);    // invocation 0 of each patch
  // Levels 2, 3, 4 and 5 on quads: (L + 1)^2 domain points each, one invocation per point.
  EXPECT_EQ(w.counters[kEvaluations], 9u + 16u + 25u + 36u);
  // Four 16 x 16 pixel squares, each pixel covered once (GL 4.6 14.6.1's shared-edge rule); the
  // quads' helper lanes (the shader takes dFdx) add nothing.
  EXPECT_EQ(w.counters[kFragments], 1024u);
  EXPECT_EQ(std::int32_t(w.counters[kMinX]), -1000);  // atomicMin over x - 1000, x from 0
  EXPECT_EQ(w.counters[kOrBits], 0xffffu);            // x & 31 covers 0..15 (x in 0..15, 32..47)
  std::uint32_t xor_all = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if ((x < 16 || (x >= 32 && x < 48)) && (y < 16 || (y >= 32 && y < 48))) xor_all ^= std::uint32_t(y * 64 + x);
  EXPECT_EQ(w.counters[kXorBits], xor_all);
  // atomicCompSwap(swapped, k, k + 1) succeeds for every fragment in a serial order, and
  // atomicExchange leaves the last fragment's number.
  EXPECT_EQ(w.counters[kSwapped], 1024u);
  EXPECT_EQ(w.counters[kLast], 1023u);
  EXPECT_EQ(w.counters[kMaxY], 47u);
}

TEST(StorageBuffers, FragmentsAndEvaluationsWriteInOneOrder) {
  const Written w = render(2);
  // Each covered pixel holds its fragment's number + 1: a permutation of 1..1024; the rest 0.
  std::vector<std::uint32_t> numbers;
  for (std::uint32_t v : w.pixels)
    if (v) numbers.push_back(v);
  ASSERT_EQ(numbers.size(), 1024u);
  std::sort(numbers.begin(), numbers.end());
  for (std::size_t i = 0; i < numbers.size(); ++i) ASSERT_EQ(numbers[i], i + 1);
  // Record i is the i-th evaluation's (u, v, patch, i); the patches come in order, and each
  // patch's domain points are its level's grid.
  for (std::uint32_t i = 0; i < 86; ++i) {
    EXPECT_EQ(w.records[4 * i + 3], float(i));
    if (i > 0) {
      EXPECT_LE(w.records[4 * (i - 1) + 2], w.records[4 * i + 2]);
    }
  }
  EXPECT_EQ(w.records[4 * 86 + 3], 0.0f);  // past the last evaluation: as uploaded
}

// inspect --pixel shades the pixel's fragments again; with side effects that would run them twice.
TEST(StorageBuffers, InspectPixelRefusesToReplaySideEffects) {
  const Scene scene = load_scene(kScene);
  try {
    inspect_draws_pixel(scene, 5, 5, Parallel(1));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("draws.0: inspect --pixel shades a draw's fragments again"), std::string::npos)
        << e.what();
  }
}

TEST(StorageBuffers, SameBytesForEveryThreadCountAndBatchSize) {
  for_every_thread_count_and_batch(render, [](const Written& one, const Written& other, const std::string& which) {
    EXPECT_EQ(one.counters, other.counters) << which;
    EXPECT_EQ(one.pixels, other.pixels) << which;
    EXPECT_EQ(one.records, other.records) << which;
    EXPECT_TRUE(one.colour == other.colour) << which;
  });
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

// image_writes.json: an r32ui and an r32f image (heightmap.pgm's 8-bit values k, as k and as
// k / 255) written by the evaluation and fragment shaders.
struct Images {
  std::vector<std::uint32_t> counts;
  std::vector<float> colour;
};

Images render_images(int threads, const std::vector<std::string>& sets = {}) {
  const Scene scene = load_scene(std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/image_writes.json", sets);
  std::vector<std::string> warnings;
  Framebuffer fb;
  DrawnMemory memory;
  render_scene(scene, build_mesh(scene.mesh, warnings), Parallel(threads), fb, {}, nullptr, &memory);
  Images out;
  for (const auto& [name, bytes] : memory.images) {
    if (name == "draw0.u_counts") out.counts = as<std::uint32_t>(std::as_bytes(std::span(bytes)));
    if (name == "draw0.u_colour") out.colour = as<float>(std::as_bytes(std::span(bytes)));
  }
  return out;
}

// A texture of the scene as uploaded (before any draw): its level 0's texels as the sampler reads them.
std::vector<float> uploaded(const std::string& uniform) {
  const Scene scene = load_scene(std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/image_writes.json");
  for (const TextureSetting& t : scene.shaders.textures)
    if (t.sampler == uniform) return load_texture(t, uniform, scene).levels.at(0).texels;
  return {};
}

bool covered(int x, int y) { return (x < 8 || (x >= 16 && x < 24)) && (y < 8 || (y >= 16 && y < 24)); }
// The texels imageAtomicMax(p / 2 + (16, 0)) reaches.
bool max_target(int x, int y) { return x >= 16 && x < 28 && (x < 20 || x >= 24) && y < 12 && (y < 4 || y >= 8); }

TEST(Images, StoresAndAtomicsChangeTheTexelsGlSays) {
  const Images w = render_images(2);
  const std::vector<float> counts = uploaded("u_counts"), colour = uploaded("u_colour");
  const auto k = [&](std::size_t i) { return std::bit_cast<std::uint32_t>(counts.at(4 * i)); };  // an integer's bits
  ASSERT_EQ(w.counts.size(), 1024u);
  ASSERT_EQ(w.colour.size(), 1024u);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const std::size_t i = std::size_t(y * 32 + x);
      if (max_target(x, y) || (x == 0 && y == 31)) continue;
      if (x == 31 && y == 31) {
        EXPECT_EQ(w.counts[i], k(i) + 86u);  // one imageAtomicAdd per evaluation (storage_writes' 86)
      } else if (covered(x, y)) {
        EXPECT_EQ(w.counts[i], k(i) + 1000u) << x << ", " << y;  // its fragment's add; helpers add nothing
        // before + imageLoad * imageSize.x + dFdx, in float, left to right (no fused multiply-add)
        const float expected = (float(k(i)) + colour[4 * i] * 32.0f) + 1.0f;
        EXPECT_EQ(w.colour[i], expected) << x << ", " << y;
      } else {
        EXPECT_EQ(w.counts[i], k(i)) << x << ", " << y;
        EXPECT_EQ(w.colour[i], colour[4 * i]) << x << ", " << y;
      }
    }
}

TEST(Images, SameBytesForEveryThreadCountAndBatchSize) {
  for_every_thread_count_and_batch(render_images, [](const Images& one, const Images& other, const std::string& which) {
    EXPECT_EQ(one.counts, other.counts) << which;
    EXPECT_EQ(one.colour, other.colour) << which;
  });
}

TEST(Images, AFormatOtherThanTheImagesIsRefusedByName) {
  try {
    render_images(1, {"shaders.textures.u_counts.internalformat=\"GL_R32I\""});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shaders.textures.u_counts.internalformat: the image is declared GL_R32UI "
                                         "and the texture is GL_R32I"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tessref
