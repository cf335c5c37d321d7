#include "stages/tpg_cache.h"

#include <bit>

#include "common/hash.h"
#include "stages/tpg_refinement.h"

namespace tessref {

std::size_t TessPattern::bytes() const {
  return sizeof(TessPattern) + points.coords.capacity() * sizeof(glm::vec3) +
         points.indices.capacity() * sizeof(std::uint32_t) +
         3 * coord[0].capacity() * sizeof(float);
}

std::shared_ptr<const TessPattern> make_pattern(const TessLayout& layout, const TessLevels& levels,
                                                const TessProfile& profile, Tessellator tessellator) {
  auto p = std::make_shared<TessPattern>();
  if (tessellator == Tessellator::Uniform) generate_uniform(layout, levels, profile, p->points);
  else if (tessellator == Tessellator::RefinementPattern) generate_refinement_pattern(layout, levels, profile, p->points);
  else generate_tessellation(layout, levels, profile, p->points);
  const std::size_t n = p->points.coords.size();
  const std::size_t padded = (n + kPatternPadding - 1) / kPatternPadding * kPatternPadding;
  for (int c = 0; c < 3; ++c) {
    p->coord[c].assign(padded, 0.0f);
    for (std::size_t i = 0; i < n; ++i) p->coord[c][i] = p->points.coords[i][c];
  }
  return p;
}

TessPatternCache::TessPatternCache(std::size_t max_bytes) : max_bytes_(max_bytes) {}

TessPatternCache& TessPatternCache::shared() {
  static TessPatternCache cache;
  return cache;
}

TessPatternCache::Key TessPatternCache::make_key(const TessLayout& layout, const TessLevels& levels,
                                                 const TessProfile& profile, Tessellator tessellator) {
  Key k{};
  k.tessellator = std::uint8_t(tessellator);
  k.domain = std::uint8_t(layout.domain);
  k.spacing = std::uint8_t(layout.spacing);
  k.winding = std::uint8_t(layout.winding);
  k.point_mode = layout.point_mode;
  k.odd_collapse = profile.odd_level_collapses_near_one;
  k.max_level = profile.max_level;
  for (int i = 0; i < 4; ++i) k.outer[i] = std::bit_cast<std::uint32_t>(levels.outer[i]);
  for (int i = 0; i < 2; ++i) k.inner[i] = std::bit_cast<std::uint32_t>(levels.inner[i]);
  return k;
}

std::size_t TessPatternCache::KeyHash::operator()(const Key& k) const {
  // FNV-1a over the fields (the struct has padding, so not over its bytes).
  Fnv1a f;
  f.mix(k.domain | k.spacing << 8 | k.winding << 16 | k.point_mode << 24 | std::uint64_t(k.odd_collapse) << 32 |
        std::uint64_t(k.tessellator) << 40);
  f.mix(std::uint32_t(k.max_level));
  for (std::uint32_t v : k.outer) f.mix(v);
  for (std::uint32_t v : k.inner) f.mix(v);
  return std::size_t(f.h);
}

std::shared_ptr<const TessPattern> TessPatternCache::get(const TessLayout& layout,
                                                        const TessLevels& levels,
                                                        const TessProfile& profile,
                                                        Tessellator tessellator) {
  const Key key = make_key(layout, levels, profile, tessellator);
  {
    std::shared_lock lock(mutex_);
    auto it = map_.find(key);
    if (it != map_.end()) {
      hits_.fetch_add(1, std::memory_order_relaxed);
      return it->second;
    }
  }
  auto pattern = make_pattern(layout, levels, profile, tessellator);  // outside the lock: other keys proceed
  std::unique_lock lock(mutex_);
  auto [it, inserted] = map_.try_emplace(key, pattern);
  if (!inserted) {
    hits_.fetch_add(1, std::memory_order_relaxed);
    return it->second;  // another thread made it first; theirs and ours are identical
  }
  ++stats_.misses;
  const std::size_t b = pattern->bytes();
  if (bytes_ + b > max_bytes_ && map_.size() > 1) {
    map_.clear();
    map_.emplace(key, pattern);
    bytes_ = 0;
    ++stats_.clears;
  }
  bytes_ += b;
  return pattern;
}

TessPatternCache::Stats TessPatternCache::stats() const {
  std::shared_lock lock(mutex_);
  Stats s = stats_;
  s.hits = hits_.load(std::memory_order_relaxed);
  s.entries = map_.size();
  s.bytes = bytes_;
  return s;
}

void TessPatternCache::clear() {
  std::unique_lock lock(mutex_);
  map_.clear();
  bytes_ = 0;
}

}  // namespace tessref
