// Patch digests (io/tess_digest.h): what a small capture keeps of every patch. Equal
// tessellations give equal digests however often a vertex was emitted; any coordinate or count
// that differs shows; the file round-trips and a foreign file is refused.
#include <cmath>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "io/tess_digest.h"
#include "test_util.h"

namespace tessref {
namespace {

std::vector<TessDumpRecord> points() {
  std::vector<TessDumpRecord> p;
  for (std::uint32_t patch = 0; patch < 3; ++patch)
    for (const glm::vec3& c : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(0.5f, 0.5f, 0)})
      p.push_back({patch, c, c, c});
  return p;
}

TEST(TessDigest, AnEmittedStreamAndItsIndexedPointsAgree) {
  const std::vector<TessDumpRecord> p = points();
  // Two triangles a patch, as indices into p, and the same as an emitted stream.
  std::vector<std::uint32_t> indices;
  std::vector<TessDumpRecord> emitted;
  for (std::uint32_t patch = 0; patch < 3; ++patch)
    for (std::uint32_t k : {0u, 3u, 2u, 3u, 1u, 2u}) {
      indices.push_back(4 * patch + k);
      emitted.push_back(p[4 * patch + k]);
    }
  const std::vector<TessPatchDigest> a = digest_patches(emitted), b = digest_patches(p, indices);
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a[1].patch_id, 1u);
  EXPECT_EQ(a[1].emitted, 6u);
  // The same coordinates give the same hash in every patch; one ULP changes it.
  EXPECT_EQ(a[0].coords_hash, a[2].coords_hash);
  emitted[7].tess_coord.x = std::nextafter(emitted[7].tess_coord.x, 2.0f);
  EXPECT_NE(digest_patches(emitted)[1].coords_hash, a[1].coords_hash);
  // One triangle fewer: the count differs.
  emitted.erase(emitted.end() - 3, emitted.end());
  EXPECT_EQ(digest_patches(emitted)[2].emitted, 3u);
}

TEST(TessDigest, FileRoundTripsAndForeignFilesAreRefused) {
  test::TempDir dir;
  const std::vector<TessPatchDigest> d = digest_patches(points());
  const std::string path = (dir.path() / "tess_patches.bin").string();
  write_patch_digests(path, d);
  EXPECT_EQ(read_patch_digests(path), d);
  EXPECT_EQ(std::filesystem::file_size(path), 16u + 16u * 3u);
  const std::string bad = dir.write("bad.bin", "TESSDUMP\x01\0\0\0\x28\0\0\0").string();
  EXPECT_THAT([&] { read_patch_digests(bad); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("not a patch digest file")));
  std::filesystem::resize_file(path, 16 + 16 + 5);
  EXPECT_THAT([&] { read_patch_digests(path); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("ends in the middle of a record")));
}

}  // namespace
}  // namespace tessref
