#pragma once
// `tessref verify`: tessref's rendering of a scene against a reference that a GL driver produced
// (`tessref capture`: color, depth and the TES outputs by transform feedback). Plain functions
// over the two results; the command (cli/verify_command.cpp) renders and reports.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/image_output.h"
#include "io/tess_digest.h"
#include "raster/framebuffer.h"
#include "stages/tess_stage.h"

namespace tessref {

// A capture folder: manifest.json, color.png, depth.exr, tess.bin (one record per vertex the
// driver emitted, 3 per triangle, in the --dump-tess binary format; io/tess_dump.h) and
// tess_patches.bin (every patch's digest; io/tess_digest.h). A heavy scene's tess.bin holds
// only the patches whose id is a multiple of the manifest's tess_patch_stride.
struct Reference {
  nlohmann::json manifest;
  Rgb8Image color;
  FloatImage depth;  // one channel, top row first; 1 where nothing was drawn
  std::vector<TessDumpRecord> tess;
  std::vector<TessPatchDigest> digests;  // empty in captures made before digests existed
  std::uint32_t patch_stride = 1;
  bool sampled(std::uint32_t patch) const { return patch % patch_stride == 0; }
};
// InputError naming what is missing, and the file at fault when the files disagree: an image of
// another size than the manifest's scene, a tess.bin or tess_patches.bin whose record count is not
// the manifest's (a file cut short or edited).
Reference load_reference(const std::filesystem::path& dir);

// ULP distance buckets: 0, 1, 2, 3-4, 5-8, ..., 2^(k-2)+1 .. 2^(k-1), and the last for the rest.
using UlpHistogram = std::array<std::uint64_t, 14>;
std::string ulp_bucket_name(std::size_t bucket);  // "0", "1", "2", "3-4", ..., ">4096"

struct TessComparison {
  std::uint64_t patches = 0;            // in either stream
  std::uint64_t patches_mismatched = 0; // a reference coordinate tessref did not generate, a
                                        // tessref coordinate the driver never emitted, or counts differ
  std::int64_t first_mismatched_patch = -1;
  std::vector<std::uint32_t> mismatched_patches;  // in patch order
  std::uint64_t reference_vertices = 0, unmatched_vertices = 0;
  UlpHistogram position_ulps{}, normal_ulps{};  // per component, at matched coordinates
  std::uint32_t max_position_ulp = 0, max_normal_ulp = 0;
  std::int64_t worst_position_patch = -1;  // the patch of max_position_ulp
  std::int64_t worst_distance_patch = -1;  // the patch of max_position_distance
  double max_position_distance = 0.0;  // world units, at matched coordinates
  // |n_driver - n_tessref| / max(|n_driver|, |n_tessref|) at matched coordinates: 2 for a flipped
  // normal, 0.5 for one scaled by 2; 0 where both are zero.
  double max_normal_difference = 0.0;
  std::int64_t worst_normal_patch = -1;
  // Matched records where a position or normal component is finite on one side only (a NaN or an
  // infinity the driver wrote where tessref has a number, or the reverse): the distances above
  // cannot see them.
  std::uint64_t nonfinite_records = 0;
  std::int64_t first_nonfinite_patch = -1;
  bool coords_identical() const { return patches_mismatched == 0; }
};
// Patch by patch: every gl_TessCoord the driver emitted must be one tessref generated, bit for
// bit, and every one tessref generated must be emitted; position and normal compared there.
TessComparison compare_tess(const std::vector<TessDumpRecord>& reference_emitted,
                            const std::vector<TessDumpRecord>& tessref_points);

// The patches of the reference stream that emit another number of vertices than tessref's
// triangles (or lines, or points) of that patch: the primitive generator's output for given levels
// is fixed by the specification up to order, so a patch emitted twice, or partly, is a defect.
struct EmittedCountDifference {
  std::uint32_t patch = 0;
  std::size_t reference = 0, tessref = 0;
};
std::vector<EmittedCountDifference> emitted_counts_differ(const std::vector<TessDumpRecord>& reference_emitted,
                                                          const std::vector<TessDumpRecord>& points,
                                                          const std::vector<std::uint32_t>& indices);

// The patches whose emitted stream (the driver's, 3 records a triangle) differs from tessref's
// triangles (`indices` into `points`, 3 a triangle) in order: the same coordinates, bit for bit, in
// the same sequence. The specification leaves the order to the implementation; llvmpipe's is
// tessref's. Only patches present in the reference stream are compared.
std::vector<std::uint32_t> emission_order_differs(const std::vector<TessDumpRecord>& reference_emitted,
                                                  const std::vector<TessDumpRecord>& points,
                                                  const std::vector<std::uint32_t>& indices);

// Triangles the driver emitted wound the other way round than tessref's same triangle (the same
// three gl_TessCoord values, bit for bit, in reversed cyclic order). The order of the triangles and
// the first vertex of each are the implementation's, but the orientation in the domain is fixed by
// the evaluation shader's cw/ccw layout (GL 4.6, 11.2.2.1). Only patches for which
// `triangles(patch)` holds are examined (lines and points have no winding), and only triangles
// tessref also generated (others are coordinate mismatches).
struct WindingDifference {
  std::uint64_t triangles = 0;           // reversed, in all patches
  std::vector<std::uint32_t> patches;    // with a reversed triangle, in stream order
  std::size_t first_patch_triangles = 0; // reversed ones in patches[0]
  std::size_t first_patch_total = 0;     // triangles of patches[0] in the capture
};
WindingDifference winding_differs(const std::vector<TessDumpRecord>& reference_emitted,
                                  const std::vector<TessDumpRecord>& points, const std::vector<std::uint32_t>& indices,
                                  const std::function<bool(std::uint32_t)>& triangles);

// The patches whose digests differ (count or distinct coordinates), or that only one side has.
std::vector<std::uint32_t> compare_digests(const std::vector<TessPatchDigest>& reference,
                                           const std::vector<TessPatchDigest>& tessref);

struct CoverageComparison {
  std::uint64_t pixels = 0, covered_reference = 0, covered_tessref = 0;
  std::uint64_t mismatched = 0;
  std::uint64_t off_silhouette = 0;  // mismatches more than one pixel from tessref's silhouette
  std::vector<std::uint64_t> by_distance;  // mismatches by pixel distance to the silhouette
  std::vector<float> heat;  // per pixel (top row first): 0 agree, else 1 + distance; for an image
};
// Covered = depth below 1 in both. The silhouette: tessref's covered pixels with an uncovered
// 4-neighbour, and uncovered ones with a covered neighbour.
CoverageComparison compare_coverage(const FloatImage& reference_depth, const Framebuffer& fb);

struct ColorComparison {
  std::uint64_t pixels = 0, within_1 = 0, within_2 = 0;  // every channel within 1/255, 2/255
  int max_difference = 0;
  double psnr = 0.0;  // dB over 8-bit channels; infinity when identical
};
ColorComparison compare_color(const Rgb8Image& reference, const Rgb8Image& tessref);

}  // namespace tessref
