#include "verify/compare.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <deque>
#include <fstream>
#include <limits>
#include <unordered_map>

#include "common/error.h"
#include "io/tess_dump.h"
#include "scene/json_input.h"

namespace tessref {
namespace {

// Floats on one integer line, so that adjacent floats differ by 1 (and -0 meets +0).
std::int64_t ordered(float f) {
  const std::int32_t i = std::bit_cast<std::int32_t>(f);
  return i < 0 ? std::int64_t(std::numeric_limits<std::int32_t>::min()) - i : std::int64_t(i);
}

std::uint32_t ulp_distance(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b) ? 0 : UINT32_MAX;
  const std::int64_t d = ordered(a) - ordered(b);
  return std::uint32_t(std::min<std::int64_t>(d < 0 ? -d : d, UINT32_MAX));
}

std::size_t ulp_bucket(std::uint32_t d) {
  if (d <= 2) return d;
  const std::size_t k = std::size_t(std::bit_width(d - 1)) + 1;  // (2^(k-2), 2^(k-1)] -> k
  return std::min<std::size_t>(k, UlpHistogram().size() - 1);
}

// A component finite on one side and not on the other: NaN and infinity compare false with any
// limit, so a distance cannot be trusted to see them.
bool finite_differs(const TessDumpRecord& a, const TessDumpRecord& b) {
  for (int k = 0; k < 3; ++k)
    if (std::isfinite(a.position[k]) != std::isfinite(b.position[k]) ||
        std::isfinite(a.normal[k]) != std::isfinite(b.normal[k]))
      return true;
  return false;
}

// Relative to the longer normal, so that the figure does not depend on whether a shader
// normalizes: a flipped normal gives 2, one scaled by 2 gives 0.5.
double normal_difference(const glm::vec3& a, const glm::vec3& b) {
  const double longer = std::max(glm::length(glm::dvec3(a)), glm::length(glm::dvec3(b)));
  if (!(longer > 0.0)) return 0.0;  // both zero, or not finite (finite_differs counts those)
  const double d = glm::length(glm::dvec3(a) - glm::dvec3(b)) / longer;
  return std::isfinite(d) ? d : 0.0;
}

std::uint64_t coord_key(const glm::vec3& c) {
  // gl_TessCoord on triangles: (u, v) fix w; the key keeps all three for other domains' z.
  const std::uint64_t u = std::bit_cast<std::uint32_t>(c.x), v = std::bit_cast<std::uint32_t>(c.y);
  return (u << 32 | v) ^ (std::uint64_t(std::bit_cast<std::uint32_t>(c.z)) * 0x9E3779B97F4A7C15ull);
}

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// Each image against the size the manifest's scene renders, so that the message names the file
// that is wrong; a capture whose manifest has no size (hand-made) compares depth.exr with color.png.
void check_image_sizes(const std::filesystem::path& dir, const Reference& r) {
  int width = r.color.width, height = r.color.height;
  std::string whose = "color.png";
  const nlohmann::json& scene = r.manifest.contains("scene") ? r.manifest["scene"] : nlohmann::json();
  if (scene.is_object() && scene.contains("image") && scene["image"].is_object() &&
      scene["image"].value("width", nlohmann::json()).is_number_integer() &&
      scene["image"].value("height", nlohmann::json()).is_number_integer()) {
    width = scene["image"]["width"].get<int>();
    height = scene["image"]["height"].get<int>();
    whose = "the scene in manifest.json";
  }
  const auto check = [&](const char* file, int w, int h) {
    if (w != width || h != height)
      throw InputError((dir / file).string() + ": the image is " + size_text(w, h) + ", " + whose + " is " +
                       size_text(width, height));
  };
  check("color.png", r.color.width, r.color.height);
  check("depth.exr", r.depth.width, r.depth.height);
}

// A manifest's count that is not the file's: the file was cut short (at a record boundary, which
// reading cannot see) or edited. Captures made before the counts existed are not checked.
void check_count(const std::filesystem::path& dir, const char* file, std::uint64_t held, const char* key,
                 const nlohmann::json& manifest) {
  const nlohmann::json expected = manifest.value(key, nlohmann::json());
  if (!expected.is_number_unsigned() && !expected.is_number_integer()) return;
  if (expected.get<std::int64_t>() != std::int64_t(held))
    throw InputError((dir / file).string() + ": holds " + std::to_string(held) + " records, manifest.json's " + key +
                     " is " + expected.dump() + " (the file was cut short or edited)");
}

void check_record_counts(const std::filesystem::path& dir, const Reference& r) {
  std::error_code ec;
  if (std::filesystem::exists(dir / "tess.bin", ec))
    check_count(dir, "tess.bin", r.tess.size(), "tess_records_stored", r.manifest);
  if (!r.digests.empty()) {
    std::uint64_t emitted = 0;
    for (const TessPatchDigest& d : r.digests) emitted += d.emitted;
    check_count(dir, "tess_patches.bin", emitted, "tess_records", r.manifest);
  }
}

}  // namespace

std::string ulp_bucket_name(std::size_t bucket) {
  if (bucket <= 2) return std::to_string(bucket);
  const std::size_t last = UlpHistogram().size() - 1;
  if (bucket >= last) return ">" + std::to_string(1u << (last - 2));
  return std::to_string((1u << (bucket - 2)) + 1) + "-" + std::to_string(1u << (bucket - 1));
}

Reference load_reference(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw InputError(dir.string() + ": no such capture folder");
  Reference r;
  const std::filesystem::path manifest = dir / "manifest.json";
  std::error_code missing;
  if (!std::filesystem::exists(manifest, missing))
    throw InputError(manifest.string() + ": missing (is " + dir.string() + " a tessref capture?)");
  r.manifest = read_json_file(manifest, "capture manifest");
  r.color = read_rgb8_image(dir / "color.png");
  r.depth = read_float_image(dir / "depth.exr");
  if (r.depth.channels != 1)
    throw InputError((dir / "depth.exr").string() + ": expected one channel (window-space depth), got " +
                     std::to_string(r.depth.channels));
  check_image_sizes(dir, r);
  if (std::filesystem::exists(dir / "tess.bin", ec)) r.tess = read_tess_dump((dir / "tess.bin").string());
  if (std::filesystem::exists(dir / "tess_patches.bin", ec))
    r.digests = read_patch_digests((dir / "tess_patches.bin").string());
  check_record_counts(dir, r);
  const nlohmann::json stride = r.manifest.value("tess_patch_stride", nlohmann::json(1));
  if (!stride.is_number_integer() || stride.get<std::int64_t>() <= 0 || stride.get<std::int64_t>() > INT32_MAX)
    throw InputError(manifest.string() + ": tess_patch_stride must be a positive integer, got " + stride.dump());
  r.patch_stride = stride.get<std::uint32_t>();
  return r;
}

namespace {

// tessref's emitted vertices of each patch: a range of `indices` (a draw emits patch by patch).
std::unordered_map<std::uint32_t, std::pair<std::size_t, std::size_t>> emitted_ranges(
    const std::vector<TessDumpRecord>& points, const std::vector<std::uint32_t>& indices) {
  std::unordered_map<std::uint32_t, std::pair<std::size_t, std::size_t>> ranges;
  for (std::size_t i = 0; i < indices.size();) {
    const std::uint32_t patch = points[indices[i]].patch_id;
    const std::size_t begin = i;
    while (i < indices.size() && points[indices[i]].patch_id == patch) ++i;
    ranges.emplace(patch, std::pair(begin, i));
  }
  return ranges;
}

}  // namespace

std::vector<EmittedCountDifference> emitted_counts_differ(const std::vector<TessDumpRecord>& reference_emitted,
                                                          const std::vector<TessDumpRecord>& points,
                                                          const std::vector<std::uint32_t>& indices) {
  const auto ranges = emitted_ranges(points, indices);
  std::unordered_map<std::uint32_t, std::size_t> counts;  // the reference's, per patch, in any order
  for (const TessDumpRecord& r : reference_emitted) ++counts[r.patch_id];
  std::vector<EmittedCountDifference> differ;
  for (const auto& [patch, count] : counts) {
    const auto it = ranges.find(patch);
    const std::size_t mine = it == ranges.end() ? 0 : it->second.second - it->second.first;
    if (mine != count) differ.push_back({patch, count, mine});
  }
  std::sort(differ.begin(), differ.end(), [](const auto& a, const auto& b) { return a.patch < b.patch; });
  return differ;
}

std::vector<std::uint32_t> emission_order_differs(const std::vector<TessDumpRecord>& reference_emitted,
                                                  const std::vector<TessDumpRecord>& points,
                                                  const std::vector<std::uint32_t>& indices) {
  const auto ranges = emitted_ranges(points, indices);
  std::vector<std::uint32_t> differ;
  for (std::size_t i = 0; i < reference_emitted.size();) {
    const std::uint32_t patch = reference_emitted[i].patch_id;
    const std::size_t begin = i;
    while (i < reference_emitted.size() && reference_emitted[i].patch_id == patch) ++i;
    const auto it = ranges.find(patch);
    bool same = it != ranges.end() && it->second.second - it->second.first == i - begin;
    for (std::size_t k = 0; same && k < i - begin; ++k)
      same = std::memcmp(&reference_emitted[begin + k].tess_coord, &points[indices[it->second.first + k]].tess_coord,
                         sizeof(glm::vec3)) == 0;
    if (!same) differ.push_back(patch);
  }
  return differ;
}

namespace {

// A triangle as the bits of its three gl_TessCoord values, rotated so that the smallest comes
// first: the same triangle from any first vertex gives one key, and the reversed triangle the key
// with its last two swapped.
using CoordBits = std::array<std::uint32_t, 3>;
using TriangleKey = std::array<CoordBits, 3>;

CoordBits coord_bits(const glm::vec3& c) {
  return {std::bit_cast<std::uint32_t>(c.x), std::bit_cast<std::uint32_t>(c.y), std::bit_cast<std::uint32_t>(c.z)};
}

TriangleKey rotated(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  TriangleKey k{coord_bits(a), coord_bits(b), coord_bits(c)};
  std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
  return k;
}

// tessref's triangles of one patch, sorted for lookups.
std::vector<TriangleKey> patch_triangles(const std::vector<TessDumpRecord>& points, const std::vector<std::uint32_t>& indices,
                                         std::pair<std::size_t, std::size_t> range) {
  std::vector<TriangleKey> keys;
  for (std::size_t t = range.first; t + 2 < range.second; t += 3)
    keys.push_back(rotated(points[indices[t]].tess_coord, points[indices[t + 1]].tess_coord,
                           points[indices[t + 2]].tess_coord));
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace

WindingDifference winding_differs(const std::vector<TessDumpRecord>& reference_emitted,
                                  const std::vector<TessDumpRecord>& points, const std::vector<std::uint32_t>& indices,
                                  const std::function<bool(std::uint32_t)>& triangles) {
  const auto ranges = emitted_ranges(points, indices);
  WindingDifference w;
  for (std::size_t i = 0; i < reference_emitted.size();) {
    const std::uint32_t patch = reference_emitted[i].patch_id;
    const std::size_t begin = i;
    while (i < reference_emitted.size() && reference_emitted[i].patch_id == patch) ++i;
    const auto it = ranges.find(patch);
    if (it == ranges.end() || !triangles(patch)) continue;
    const std::vector<TriangleKey> mine = patch_triangles(points, indices, it->second);
    const auto has = [&](const TriangleKey& k) { return std::binary_search(mine.begin(), mine.end(), k); };
    std::size_t reversed = 0;
    for (std::size_t t = begin; t + 2 < i; t += 3) {
      const glm::vec3 &a = reference_emitted[t].tess_coord, &b = reference_emitted[t + 1].tess_coord,
                      &c = reference_emitted[t + 2].tess_coord;
      // A degenerate triangle (two equal coordinates) has the same key both ways: found first.
      if (!has(rotated(a, b, c)) && has(rotated(a, c, b))) ++reversed;
    }
    if (!reversed) continue;
    if (w.patches.empty()) w.first_patch_triangles = reversed, w.first_patch_total = (i - begin) / 3;
    w.patches.push_back(patch);
    w.triangles += reversed;
  }
  return w;
}

std::vector<std::uint32_t> compare_digests(const std::vector<TessPatchDigest>& reference,
                                           const std::vector<TessPatchDigest>& tessref) {
  std::vector<TessPatchDigest> a(reference), b(tessref);
  const auto by_patch = [](const TessPatchDigest& x, const TessPatchDigest& y) { return x.patch_id < y.patch_id; };
  std::sort(a.begin(), a.end(), by_patch);
  std::sort(b.begin(), b.end(), by_patch);
  std::vector<std::uint32_t> differ;
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i].patch_id < b[j].patch_id)) {
      differ.push_back(a[i++].patch_id);
    } else if (i == a.size() || b[j].patch_id < a[i].patch_id) {
      differ.push_back(b[j++].patch_id);
    } else {
      if (!(a[i] == b[j])) differ.push_back(a[i].patch_id);
      ++i, ++j;
    }
  }
  return differ;
}

TessComparison compare_tess(const std::vector<TessDumpRecord>& reference_emitted,
                            const std::vector<TessDumpRecord>& tessref_points) {
  // Both streams come patch by patch in mesh order (the capture checks its order, the draw emits
  // in it); a stream that does not is put in that order first.
  const auto by_patch = [](const TessDumpRecord& a, const TessDumpRecord& b) { return a.patch_id < b.patch_id; };
  std::vector<TessDumpRecord> ref_sorted, mine_sorted;
  const auto in_order = [&](const std::vector<TessDumpRecord>& s, std::vector<TessDumpRecord>& copy)
      -> const std::vector<TessDumpRecord>& {
    if (std::is_sorted(s.begin(), s.end(), by_patch)) return s;
    copy = s;
    std::stable_sort(copy.begin(), copy.end(), by_patch);
    return copy;
  };
  const std::vector<TessDumpRecord>& ref = in_order(reference_emitted, ref_sorted);
  const std::vector<TessDumpRecord>& mine = in_order(tessref_points, mine_sorted);

  TessComparison c;
  c.reference_vertices = ref.size();
  std::unordered_map<std::uint64_t, std::size_t> generated;  // coordinate -> its first point in `mine`
  std::vector<char> emitted;                                  // per point of the patch in `mine`
  for (std::size_t i = 0, j = 0; i < ref.size() || j < mine.size();) {
    // The next patch either stream has, and its range in each.
    const std::uint32_t patch = std::min(i < ref.size() ? ref[i].patch_id : UINT32_MAX,
                                         j < mine.size() ? mine[j].patch_id : UINT32_MAX);
    const std::size_t i0 = i, j0 = j;
    while (i < ref.size() && ref[i].patch_id == patch) ++i;
    while (j < mine.size() && mine[j].patch_id == patch) ++j;
    ++c.patches;
    generated.clear();
    for (std::size_t k = j0; k < j; ++k) generated.emplace(coord_key(mine[k].tess_coord), k - j0);
    emitted.assign(j - j0, 0);
    bool mismatch = false;
    for (std::size_t k = i0; k < i; ++k) {
      const TessDumpRecord& r = ref[k];
      const auto it = generated.find(coord_key(r.tess_coord));
      const TessDumpRecord* m = it == generated.end() ? nullptr : &mine[j0 + it->second];
      if (!m || std::memcmp(&m->tess_coord, &r.tess_coord, sizeof(glm::vec3)) != 0) {
        ++c.unmatched_vertices;
        mismatch = true;
        continue;
      }
      emitted[it->second] = 1;
      if (finite_differs(r, *m)) {  // counted apart; an infinite distance would only hide which
        ++c.nonfinite_records;
        if (c.first_nonfinite_patch < 0) c.first_nonfinite_patch = patch;
        continue;
      }
      const double distance = glm::length(glm::dvec3(r.position) - glm::dvec3(m->position));
      if (distance > c.max_position_distance) c.max_position_distance = distance, c.worst_distance_patch = patch;
      const double normal = normal_difference(r.normal, m->normal);
      if (normal > c.max_normal_difference) c.max_normal_difference = normal, c.worst_normal_patch = patch;
      for (int k3 = 0; k3 < 3; ++k3) {
        const std::uint32_t dp = ulp_distance(r.position[k3], m->position[k3]);
        const std::uint32_t dn = ulp_distance(r.normal[k3], m->normal[k3]);
        ++c.position_ulps[ulp_bucket(dp)];
        ++c.normal_ulps[ulp_bucket(dn)];
        if (dp > c.max_position_ulp) c.max_position_ulp = dp, c.worst_position_patch = patch;
        c.max_normal_ulp = std::max(c.max_normal_ulp, dn);
      }
    }
    // Every coordinate tessref generated must have been emitted.
    if (std::size_t(std::count(emitted.begin(), emitted.end(), 1)) != generated.size()) mismatch = true;
    if (mismatch) {
      ++c.patches_mismatched;
      if (c.first_mismatched_patch < 0) c.first_mismatched_patch = patch;
      c.mismatched_patches.push_back(patch);
    }
  }
  return c;
}

CoverageComparison compare_coverage(const FloatImage& reference_depth, const Framebuffer& fb) {
  if (reference_depth.width != fb.width || reference_depth.height != fb.height || reference_depth.channels != 1)
    throw InputError("the reference depth image is " + std::to_string(reference_depth.width) + "x" +
                     std::to_string(reference_depth.height) + ", the scene renders " + std::to_string(fb.width) +
                     "x" + std::to_string(fb.height));
  const int w = fb.width, h = fb.height;
  CoverageComparison c;
  c.pixels = std::uint64_t(w) * h;
  // Top row first in both, as images are written.
  std::vector<char> mine(c.pixels), theirs(c.pixels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      mine[i] = fb.depth[fb.index(x, h - 1 - y)] < 1.0f;
      theirs[i] = reference_depth.pixels[i] < 1.0f;
      c.covered_tessref += mine[i];
      c.covered_reference += theirs[i];
    }
  // Distance (4-neighbour steps) from tessref's silhouette, by a breadth-first sweep from it.
  std::vector<int> distance(c.pixels, -1);
  std::deque<std::size_t> queue;
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      for (int k = 0; k < 4; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx >= 0 && ny >= 0 && nx < w && ny < h && mine[std::size_t(ny) * w + nx] != mine[i]) {
          distance[i] = 0;
          queue.push_back(i);
          break;
        }
      }
    }
  while (!queue.empty()) {
    const std::size_t i = queue.front();
    queue.pop_front();
    const int x = int(i % w), y = int(i / w);
    for (int k = 0; k < 4; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      const std::size_t j = std::size_t(ny) * w + nx;
      if (distance[j] < 0) distance[j] = distance[i] + 1, queue.push_back(j);
    }
  }
  c.heat.assign(c.pixels, 0.0f);
  for (std::size_t i = 0; i < c.pixels; ++i) {
    if (mine[i] == theirs[i]) continue;
    ++c.mismatched;
    const int d = distance[i] < 0 ? w + h : distance[i];  // no silhouette at all: far
    if (d > 1) ++c.off_silhouette;
    if (c.by_distance.size() <= std::size_t(d)) c.by_distance.resize(d + 1, 0);
    ++c.by_distance[d];
    c.heat[i] = 1.0f + float(d);
  }
  return c;
}

ColorComparison compare_color(const Rgb8Image& reference, const Rgb8Image& tessref) {
  if (reference.width != tessref.width || reference.height != tessref.height)
    throw InputError("the reference color image is " + std::to_string(reference.width) + "x" +
                     std::to_string(reference.height) + ", the scene renders " + std::to_string(tessref.width) +
                     "x" + std::to_string(tessref.height));
  ColorComparison c;
  c.pixels = std::uint64_t(reference.width) * reference.height;
  double squared = 0.0;
  for (std::size_t p = 0; p < c.pixels; ++p) {
    int worst = 0;
    for (int k = 0; k < 3; ++k) {
      const int d = std::abs(int(reference.pixels[3 * p + k]) - int(tessref.pixels[3 * p + k]));
      worst = std::max(worst, d);
      squared += double(d) * d;
    }
    c.within_1 += worst <= 1;
    c.within_2 += worst <= 2;
    c.max_difference = std::max(c.max_difference, worst);
  }
  const double mse = squared / (3.0 * double(std::max<std::uint64_t>(c.pixels, 1)));
  c.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
  return c;
}

}  // namespace tessref
