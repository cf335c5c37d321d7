// tessref's generator against the committed llvmpipe dataset (tests/data/tpg/llvmpipe, written by
// tessref-tpg-reference on Mesa 22.3.6): the same comparison as the live test, where no EGL
// context can be made.
#include <gtest/gtest.h>

#include <bit>
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "stages/tpg.h"
#include "stages/tpg_stream.h"
#include "stages/tpg_sweep.h"

namespace tessref {
namespace {

const std::string kDataset = std::string(TESSREF_SOURCE_DIR) + "/tests/data/tpg/llvmpipe/";

std::vector<std::uint64_t> read_hashes(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::uint64_t> out;
  for (std::string line; std::getline(in, line);)
    out.push_back(std::strtoull(line.c_str(), nullptr, 16));
  return out;
}

class TpgReference : public ::testing::TestWithParam<std::size_t> {};

TEST_P(TpgReference, MatchesCapturedHashes) {
  const std::size_t li = GetParam();
  const TessLayout layout = sweep_layouts()[li];
  const std::string name = sweep_name(layout);
  const auto hashes = read_hashes(kDataset + name + ".hashes");
  ASSERT_GE(hashes.size(), 2000u) << "missing or short dataset " << name;
  const auto levels = sweep_levels(1000 + li, hashes.size(), SweepRange::Full);
  std::size_t matches = 0;
  for (std::size_t i = 0; i < levels.size(); ++i)
    matches += stream_hash(emitted_stream(generate_tessellation(layout, levels[i]))) == hashes[i];
  std::printf("[ llvmpipe dataset ] %s: %zu / %zu streams identical\n", name.c_str(), matches,
              hashes.size());
  EXPECT_EQ(matches, hashes.size());
}

TEST_P(TpgReference, MatchesCapturedFullStreams) {
  const std::size_t li = GetParam();
  const TessLayout layout = sweep_layouts()[li];
  std::ifstream in(kDataset + sweep_name(layout) + ".full");
  ASSERT_TRUE(in) << "missing dataset " << sweep_name(layout);
  const int components = layout.domain == TessDomain::Triangles ? 3 : 2;
  std::size_t patches = 0;
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  const auto levels = sweep_levels(5000 + li, lines.size(), SweepRange::Small);
  for (const std::string& line : lines) {
    std::istringstream ss(line);
    std::size_t index = 0, count = 0;
    ss >> index >> count;
    ASSERT_LT(index, levels.size());
    const auto ours = emitted_stream(generate_tessellation(layout, levels[index]));
    ASSERT_EQ(ours.size(), count) << "patch " << index;
    for (std::size_t v = 0; v < count; ++v)
      for (int k = 0; k < components; ++k) {
        std::string hex;
        ss >> hex;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(ours[v][k]), std::stoul(hex, nullptr, 16))
            << "patch " << index << " vertex " << v << " component " << k;
      }
    ++patches;
  }
  EXPECT_GT(patches, 0u);
}

INSTANTIATE_TEST_SUITE_P(AllLayouts, TpgReference, ::testing::Range<std::size_t>(0, 36),
                         [](const auto& info) { return sweep_name(sweep_layouts()[info.param]); });

}  // namespace
}  // namespace tessref
