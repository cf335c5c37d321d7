// The tessellated default scene: image bytes and the --dump-tess stream are identical for 1, 2 and
// 8 threads and for any chunk size; the dump file is what the records say.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/error.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "io/tess_dump.h"

namespace tessref {
namespace {

const std::vector<std::string> kPn12 = {"tessellation.enabled=true", "tessellation.scheme=pn",
                                        "tessellation.inner=12", "tessellation.outer=12",
                                        "tessellation.spacing=fractional_odd"};

struct Rendered {
  std::vector<unsigned char> color, depth, dump;
  DrawStats stats;
};

Rendered render(int threads, std::size_t chunk, const std::vector<std::string>& sets = kPn12) {
  const Scene scene = load_scene("", sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  Rendered r;
  DrawOptions options;
  options.tess_chunk_patches = chunk;
  options.dump_tess = [&](const std::vector<TessDumpRecord>& records) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(records.data());
    r.dump.insert(r.dump.end(), bytes, bytes + records.size() * sizeof(TessDumpRecord));
  };
  const RenderResult result = render_scene(scene, mesh, Parallel(threads), options);
  const auto* c = reinterpret_cast<const unsigned char*>(result.framebuffer.color.data());
  r.color.assign(c, c + result.framebuffer.color.size() * sizeof(glm::vec4));
  const auto* d = reinterpret_cast<const unsigned char*>(result.framebuffer.depth.data());
  r.depth.assign(d, d + result.framebuffer.depth.size() * sizeof(float));
  r.stats = result.stats;
  return r;
}

TEST(TessDeterminism, ThreadsAndChunksDoNotChangeImageOrDump) {
  const Rendered one = render(1, 256);
  // 256 torus triangles at level 12, fractional_odd: 147 domain points per patch (as
  // `tessref tpg --spacing fractional_odd --outer 12,12,12 --inner 12 --point-mode` and llvmpipe).
  EXPECT_EQ(one.stats.tess.patches_in, 256u);
  EXPECT_EQ(one.stats.tess.domain_points, 256u * 147u);
  EXPECT_EQ(one.dump.size(), 256u * 147u * sizeof(TessDumpRecord));
  for (int threads : {2, 8}) {
    for (std::size_t chunk : {std::size_t(7), std::size_t(256), std::size_t(100000)}) {
      const Rendered other = render(threads, chunk);
      EXPECT_TRUE(other.color == one.color) << threads << " threads, chunk " << chunk;
      EXPECT_TRUE(other.depth == one.depth) << threads << " threads, chunk " << chunk;
      EXPECT_TRUE(other.dump == one.dump) << threads << " threads, chunk " << chunk;
      EXPECT_EQ(other.stats.raster.fragments_shaded, one.stats.raster.fragments_shaded);
    }
  }
}

TEST(TessDeterminism, DumpFileFormat) {
  const auto path = std::filesystem::temp_directory_path() / "tessref_dump_test.bin";
  TessDumpRecord r;
  r.patch_id = 7;
  r.tess_coord = {0.25f, 0.5f, 0.25f};
  r.position = {1, 2, 3};
  r.normal = {0, 0, 1};
  {
    TessDumpWriter w(path.string());
    w.write({r, r});
    w.close();
    EXPECT_EQ(w.records_written(), 2u);
  }
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_EQ(bytes.size(), 16u + 2 * 40u);
  EXPECT_EQ(std::string(bytes.data(), 8), "TESSDUMP");
  std::uint32_t patch = 0;
  float coord[3], pos[3];
  std::memcpy(&patch, bytes.data() + 16 + 40, 4);
  std::memcpy(coord, bytes.data() + 16 + 40 + 4, 12);
  std::memcpy(pos, bytes.data() + 16 + 40 + 16, 12);
  EXPECT_EQ(patch, 7u);
  EXPECT_EQ(coord[1], 0.5f);
  EXPECT_EQ(pos[2], 3.0f);
  std::filesystem::remove(path);
  EXPECT_THROW(TessDumpWriter("/nonexistent-dir/x.bin"), InputError);
}

}  // namespace
}  // namespace tessref
