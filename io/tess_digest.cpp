#include "io/tess_digest.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "common/error.h"
#include "common/hash.h"

namespace tessref {
namespace {

using CoordBits = std::array<std::uint32_t, 3>;

CoordBits coord_bits(const glm::vec3& c) {
  CoordBits b;
  std::memcpy(b.data(), &c.x, sizeof b);
  return b;
}

std::uint64_t hash_distinct(std::vector<CoordBits>& coords) {
  std::sort(coords.begin(), coords.end());
  coords.erase(std::unique(coords.begin(), coords.end()), coords.end());
  Fnv1a f;
  for (const CoordBits& c : coords)
    for (std::uint32_t w : c) f.mix(w);
  return f.h;
}

constexpr std::uint32_t kRecordBytes = 16;

}  // namespace

std::vector<TessPatchDigest> digest_patches(const std::vector<TessDumpRecord>& points,
                                            const std::vector<std::uint32_t>& emitted) {
  std::vector<TessPatchDigest> out;
  std::vector<CoordBits> coords;
  const std::size_t n = emitted.empty() ? points.size() : emitted.size();
  for (std::size_t i = 0; i < n;) {
    const std::uint32_t patch = points[emitted.empty() ? i : emitted[i]].patch_id;
    TessPatchDigest d;
    d.patch_id = patch;
    coords.clear();
    for (; i < n; ++i) {
      const TessDumpRecord& r = points[emitted.empty() ? i : emitted[i]];
      if (r.patch_id != patch) break;
      coords.push_back(coord_bits(r.tess_coord));
      ++d.emitted;
    }
    d.coords_hash = hash_distinct(coords);
    out.push_back(d);
  }
  return out;
}

void write_patch_digests(const std::string& path, const std::vector<TessPatchDigest>& digests) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!f) throw InputError(path + ": cannot create: " + std::strerror(errno));
  const std::uint32_t header[2] = {1, kRecordBytes};
  bool ok = std::fwrite("TESSPTCH", 1, 8, f.get()) == 8 && std::fwrite(header, 4, 2, f.get()) == 2;
  for (const TessPatchDigest& d : digests) {
    unsigned char rec[kRecordBytes];
    std::memcpy(rec, &d.patch_id, 4);
    std::memcpy(rec + 4, &d.emitted, 4);
    std::memcpy(rec + 8, &d.coords_hash, 8);
    ok = ok && std::fwrite(rec, 1, sizeof rec, f.get()) == sizeof rec;
  }
  if (!ok || std::fflush(f.get()) != 0) throw InputError(path + ": cannot write: " + std::strerror(errno));
}

std::vector<TessPatchDigest> read_patch_digests(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw InputError(path + ": cannot open: " + std::strerror(errno));
  char magic[8];
  std::uint32_t header[2];
  if (std::fread(magic, 1, 8, f.get()) != 8 || std::memcmp(magic, "TESSPTCH", 8) != 0 ||
      std::fread(header, 4, 2, f.get()) != 2 || header[0] != 1 || header[1] != kRecordBytes)
    throw InputError(path + ": not a patch digest file (version 1, 16-byte records)");
  std::vector<TessPatchDigest> out;
  unsigned char rec[kRecordBytes];
  std::size_t n;
  while ((n = std::fread(rec, 1, sizeof rec, f.get())) == sizeof rec) {
    TessPatchDigest d;
    std::memcpy(&d.patch_id, rec, 4);
    std::memcpy(&d.emitted, rec + 4, 4);
    std::memcpy(&d.coords_hash, rec + 8, 8);
    out.push_back(d);
  }
  if (n != 0) throw InputError(path + ": ends in the middle of a record");
  return out;
}

}  // namespace tessref
