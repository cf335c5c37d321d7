#pragma once
// A bounded cache of primitive-generator patterns. A mesh drawn with constant levels makes one
// pattern for all its patches; adaptive levels make a few hundred. The generator's output depends
// only on (layout, levels, profile), so a pattern is generated once and shared (read-only) by every
// patch and thread that asks for the same key: caching never changes a result.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include "stages/tpg.h"
#include "stages/tpg_uniform.h"

namespace tessref {

// One generated patch domain, with gl_TessCoord also as structure of arrays (what the batched
// TES reads), padded with zeros to a multiple of kPatternPadding.
struct TessPattern {
  TessDomainPoints points;
  std::vector<float> coord[3];  // coord[c][i] = points.coords[i][c]
  std::size_t bytes() const;
};
inline constexpr std::size_t kPatternPadding = 16;

class TessPatternCache {
 public:
  // When a new pattern would take the cache past max_bytes, it is emptied first (patterns in use
  // stay alive through their shared_ptr).
  explicit TessPatternCache(std::size_t max_bytes = std::size_t(64) << 20);

  std::shared_ptr<const TessPattern> get(const TessLayout& layout, const TessLevels& levels,
                                         const TessProfile& profile,
                                         Tessellator tessellator = Tessellator::PrimitiveGenerator);

  struct Stats {
    std::uint64_t hits = 0, misses = 0, clears = 0;
    std::size_t entries = 0, bytes = 0;
  };
  Stats stats() const;
  void clear();

  // The cache the executor uses unless TessOptions names another.
  static TessPatternCache& shared();

 private:
  struct Key {
    std::uint8_t domain, spacing, winding, point_mode, odd_collapse;
    std::uint8_t tessellator;  // a uniform pattern is never served for the TPG's levels
    std::int32_t max_level;
    std::uint32_t outer[4], inner[2];  // level bit patterns: NaN and -0 are keys like any other
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };
  static Key make_key(const TessLayout& layout, const TessLevels& levels, const TessProfile& profile,
                      Tessellator tessellator);

  std::size_t max_bytes_;
  mutable std::shared_mutex mutex_;
  std::unordered_map<Key, std::shared_ptr<const TessPattern>, KeyHash> map_;
  std::size_t bytes_ = 0;
  Stats stats_;  // all but hits, under mutex_
  std::atomic<std::uint64_t> hits_{0};
};

// Builds a pattern without the cache (what the cache stores for a key).
std::shared_ptr<const TessPattern> make_pattern(const TessLayout& layout, const TessLevels& levels,
                                                const TessProfile& profile,
                                                Tessellator tessellator = Tessellator::PrimitiveGenerator);

}  // namespace tessref
