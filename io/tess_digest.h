#pragma once
// A patch's tessellation in 16 bytes: how many vertices were emitted for it and a hash of the
// distinct gl_TessCoord values among them. A capture of a heavy scene keeps every patch's digest
// and the full records of a sample of patches only (glref/reference_capture.h), so that it stays
// small enough to commit while every patch's coordinates are still compared exactly.
//
// File format (tess_patches.bin), little-endian:
//   header, 16 bytes: "TESSPTCH" (8 bytes), uint32 version = 1, uint32 record size = 16
//   records: uint32 patch_id, uint32 emitted vertices, uint64 FNV-1a of the distinct coordinates
//            (their 3 x 32 bits, sorted as unsigned triples, each word mixed in turn)
#include <cstdint>
#include <string>
#include <vector>

#include "stages/tess_stage.h"

namespace tessref {

struct TessPatchDigest {
  std::uint32_t patch_id = 0;
  std::uint32_t emitted = 0;
  std::uint64_t coords_hash = 0;
  bool operator==(const TessPatchDigest&) const = default;
};

// One digest per patch, in the order patches first appear. `emitted` lists the emitted vertices
// as indices into points (3 per triangle); empty: every point is one emitted vertex, in order.
// A patch's vertices must be contiguous in that order (draws emit patch by patch).
std::vector<TessPatchDigest> digest_patches(const std::vector<TessDumpRecord>& points,
                                            const std::vector<std::uint32_t>& emitted = {});

void write_patch_digests(const std::string& path, const std::vector<TessPatchDigest>& digests);
std::vector<TessPatchDigest> read_patch_digests(const std::string& path);  // InputError naming it

}  // namespace tessref
