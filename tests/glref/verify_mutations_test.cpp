// Planted corruptions of a capture and of tessref's rendering (issue 24, defect 2): `tessref
// verify` must fail each, and for the reason planted. The default scene is captured once on
// llvmpipe at 128 x 128; every case corrupts a copy of it (or verifies it with tessref's scene
// changed) and checks the exit status and the FAIL line (or the bad-input message) that names
// the fault, so that no case passes for an unrelated reason. One control: the unchanged capture
// passes. docs/verification.md "Planted faults" and docs/adversarial.md list the cases.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../pipeline/test_util.h"
#include "default_capture.h"
#include "gl_fixture.h"
#include "io/image_output.h"
#include "io/tess_digest.h"
#include "io/tess_dump.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const std::string& kSmall = test::kCaptureSize;
constexpr std::uint32_t kPatches = 256;
constexpr std::size_t kPerPatch = 759;  // 253 triangles of the default scene's levels (12)

class VerifyMutations : public test::DefaultCapture<VerifyMutations> {
 public:
  static constexpr const char* kName = "VerifyMutations";

 protected:
  // A fresh copy of the capture.
  static std::filesystem::path copy_of_capture(const std::string& name) {
    const std::filesystem::path copy = dir_ / name;
    std::filesystem::remove_all(copy);
    std::filesystem::copy(ref(), copy);
    return copy;
  }

  // A copy whose tess.bin went through `edit`. As a driver's capture of those records would, the
  // manifest then counts what tess.bin holds; tess_patches.bin is kept (the digests of the
  // driver that was captured), so records and digests may disagree, as in a tess.bin edited alone.
  template <typename Edit>
  static std::filesystem::path with_records(const std::string& name, Edit&& edit, bool recount = true) {
    const std::filesystem::path copy = copy_of_capture(name);
    std::vector<TessDumpRecord> records = read_tess_dump(ref() + "/tess.bin");
    edit(records);
    TessDumpWriter writer((copy / "tess.bin").string());
    writer.write(records);
    writer.close();
    if (recount) {
      nlohmann::json m = nlohmann::json::parse(std::ifstream(copy / "manifest.json"));
      m["tess_records_stored"] = records.size();
      std::ofstream(copy / "manifest.json") << m.dump(2);
    }
    return copy;
  }

  template <typename Edit>
  static std::filesystem::path with_color(const std::string& name, Edit&& edit) {
    const std::filesystem::path copy = copy_of_capture(name);
    Rgb8Image color = read_rgb8_image(copy / "color.png");
    edit(color);
    write_rgb8_image(color, copy / "color.png");
    return copy;
  }

  template <typename Edit>
  static std::filesystem::path with_depth(const std::string& name, Edit&& edit) {
    const std::filesystem::path copy = copy_of_capture(name);
    FloatImage depth = read_float_image(copy / "depth.exr");
    const std::vector<std::string> channels = read_channel_names(copy / "depth.exr");
    edit(depth);
    std::filesystem::remove(copy / "depth.exr");
    write_float_channels(copy / "depth.exr", depth.width, depth.height, channels, depth.pixels);
    return copy;
  }

  struct Verdict {
    test::CliRun run;
    nlohmann::json report;  // null when verify wrote none (bad input)
    bool failed_with(const std::string& text) const {
      for (const auto& f : report.value("failures", nlohmann::json::array()))
        if (f.get<std::string>().find(text) != std::string::npos) return true;
      return false;
    }
  };
  static Verdict verify(const std::filesystem::path& capture, const std::string& extra = "") {
    const std::filesystem::path json = dir_ / (capture.filename().string() + "-report.json");
    std::filesystem::remove(json);
    Verdict v{test::run_cli("verify --ref " + capture.string() + kSmall + extra + " --json " + json.string()), {}};
    if (std::filesystem::exists(json)) v.report = nlohmann::json::parse(std::ifstream(json));
    return v;
  }

  // Every emission of patch `patch`'s domain point at record `k` of that patch.
  static std::vector<TessDumpRecord*> emissions_of(std::vector<TessDumpRecord>& records, std::uint32_t patch,
                                                   std::size_t k) {
    const glm::vec3 coord = records[patch * kPerPatch + k].tess_coord;
    std::vector<TessDumpRecord*> out;
    for (TessDumpRecord& r : records)
      if (r.patch_id == patch && r.tess_coord == coord) out.push_back(&r);
    return out;
  }

};

// A verdict of 1 with `reason` in one of its failures (the report's, printed on a FAIL: line):
// the planted fault was found as itself.
#define EXPECT_FAILS_AS(verdict, reason)                                       \
  do {                                                                         \
    EXPECT_EQ((verdict).run.exit_code, 1) << (verdict).run.output;             \
    EXPECT_THAT((verdict).run.output, HasSubstr(": FAIL\n"));                 \
    EXPECT_THAT((verdict).run.output, HasSubstr(reason));                      \
    EXPECT_TRUE((verdict).failed_with(reason)) << (verdict).report.dump(2);    \
    EXPECT_FALSE((verdict).report.value("pass", true));                        \
    EXPECT_GT((verdict).report.value("severity", 0.0), 1.0);                   \
  } while (0)

// A verdict of 2 (a malformed capture) naming the file at fault.
#define EXPECT_BAD_CAPTURE(verdict, message)                       \
  do {                                                             \
    EXPECT_EQ((verdict).run.exit_code, 2) << (verdict).run.output; \
    EXPECT_THAT((verdict).run.output, HasSubstr(message));         \
  } while (0)

TEST_F(VerifyMutations, TheUnchangedCapturePasses) {
  const Verdict v = verify(copy_of_capture("unchanged"));
  EXPECT_EQ(v.run.exit_code, 0) << v.run.output;
  ASSERT_TRUE(v.report.is_object());
  EXPECT_EQ(v.report["failures"].size(), 0u);
  const auto& t = v.report["tessellation"];
  EXPECT_EQ(t["records_compared"], kPatches * kPerPatch);
  EXPECT_EQ(t["winding_differs_triangles"], 0);
  EXPECT_EQ(t["nonfinite_records"], 0);
  EXPECT_LT(t["max_normal_difference"].get<double>(), 1e-4);
  EXPECT_LE(v.report["severity"].get<double>(), 1.0);
}

// --- tess.bin ---------------------------------------------------------------------------------

// Patch ids permuted: every stream, the surface, the silhouette and the colour stay; the same
// patch and gl_TessCoord no longer evaluate to the same point.
TEST_F(VerifyMutations, PermutedPatchesFailOnPositions) {
  const Verdict v = verify(with_records("permuted", [](std::vector<TessDumpRecord>& records) {
    for (TessDumpRecord& r : records) r.patch_id = std::uint32_t((7919u * r.patch_id) % kPatches);
    std::stable_sort(records.begin(), records.end(),
                     [](const TessDumpRecord& a, const TessDumpRecord& b) { return a.patch_id < b.patch_id; });
  }));
  EXPECT_FAILS_AS(v, "evaluated positions differ by up to");
  EXPECT_FALSE(v.failed_with("gl_TessCoord streams"));
}

TEST_F(VerifyMutations, ADroppedPatchFailsOnItsCoordinates) {
  const Verdict v = verify(with_records("dropped", [](std::vector<TessDumpRecord>& records) {
    std::erase_if(records, [](const TessDumpRecord& r) { return r.patch_id == 10; });
  }));
  EXPECT_FAILS_AS(v, "gl_TessCoord streams differ in 1 of 256 patches (first: patch 10)");
}

TEST_F(VerifyMutations, ADuplicatedPatchFailsOnItsCount) {
  const Verdict v = verify(with_records("duplicated", [](std::vector<TessDumpRecord>& records) {
    const std::vector<TessDumpRecord> again(records.begin() + 11 * kPerPatch, records.begin() + 12 * kPerPatch);
    records.insert(records.begin() + 12 * kPerPatch, again.begin(), again.end());
  }));
  EXPECT_FAILS_AS(v, "1 patches emit another number of vertices than tessref's (first: patch 11, 1518 in the capture, "
                     "759 from tessref)");
  EXPECT_FALSE(v.failed_with("gl_TessCoord streams"));
}

// One triangle left out: each of its corners is still emitted by a neighbouring triangle.
TEST_F(VerifyMutations, AMissingTriangleFailsOnTheCount) {
  const Verdict v = verify(with_records("triangle", [](std::vector<TessDumpRecord>& records) {
    records.erase(records.begin() + 77 * kPerPatch + 30, records.begin() + 77 * kPerPatch + 33);
  }));
  EXPECT_FAILS_AS(v, "(first: patch 77, 756 in the capture, 759 from tessref)");
}

// One domain point of patch 90 moved by 1e-3 of the diagonal (4.31), in every triangle using it.
TEST_F(VerifyMutations, OneMovedVertexFailsOnPositions) {
  const Verdict v = verify(with_records("moved", [](std::vector<TessDumpRecord>& records) {
    for (TessDumpRecord* r : emissions_of(records, 90, 0)) r->position.y += 0.00431f;
  }));
  EXPECT_FAILS_AS(v, "evaluated positions differ by up to 0.001 of the diagonal");
  EXPECT_FAILS_AS(v, "worst: patch 90)");
}

// A flipped normal leaves every position, the surface and the images as they were.
TEST_F(VerifyMutations, AFlippedNormalFailsOnNormals) {
  const Verdict v = verify(with_records("flipped", [](std::vector<TessDumpRecord>& records) {
    for (TessDumpRecord* r : emissions_of(records, 120, 40)) r->normal = -r->normal;
  }));
  EXPECT_FAILS_AS(v, "normals differ by up to 2 (|difference| / |longer normal|)");
  EXPECT_FAILS_AS(v, "worst: patch 120)");
  EXPECT_EQ(v.report["failures"].size(), 1u) << v.report["failures"].dump();  // nothing else moved
}

TEST_F(VerifyMutations, ANormalScaledBy2FailsOnNormals) {
  const Verdict v = verify(with_records("scaled", [](std::vector<TessDumpRecord>& records) {
    for (TessDumpRecord& r : records)
      if (r.patch_id == 30) r.normal *= 2.0f;
  }));
  EXPECT_FAILS_AS(v, "normals differ by up to 0.5 ");
  EXPECT_EQ(v.report["failures"].size(), 1u) << v.report["failures"].dump();
}

// Two corners of one triangle swapped: the same coordinates in the same patch, emitted clockwise.
TEST_F(VerifyMutations, ASwappedWindingFails) {
  const Verdict v = verify(with_records("winding", [](std::vector<TessDumpRecord>& records) {
    std::swap(records[64 * kPerPatch + 3 * 7 + 1], records[64 * kPerPatch + 3 * 7 + 2]);
  }));
  EXPECT_FAILS_AS(v, "1 triangles in 1 patches are wound the other way round than tessref's (first: patch 64, 1 of "
                     "its 253 triangles");
  EXPECT_EQ(v.report["failures"].size(), 1u) << v.report["failures"].dump();
  EXPECT_EQ(v.report["tessellation"]["order_differs_patches"], 1);  // reported as well
}

// One patch's records in reverse order: every triangle of it is wound the other way round.
TEST_F(VerifyMutations, APatchInReverseOrderFailsOnWinding) {
  const Verdict v = verify(with_records("reversed", [](std::vector<TessDumpRecord>& records) {
    std::reverse(records.begin() + 5 * kPerPatch, records.begin() + 6 * kPerPatch);
  }));
  EXPECT_FAILS_AS(v, "253 triangles in 1 patches are wound the other way round than tessref's (first: patch 5, "
                     "253 of its 253 triangles");
}

// A primitive generator that rounded one level of patch 200 otherwise (outer 12, 12, 13): that
// patch's records come from a capture made with those levels (its digest is left as it was, as
// in a tess.bin edited alone: the records are compared as well).
TEST_F(VerifyMutations, ADifferentLevelFailsOnCoordinates) {
  const std::string other = (dir_ / "outer13").string();
  const test::CliRun c = test::run_cli("capture --out " + other + kSmall + " --set tessellation.outer=12,12,13");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const std::vector<TessDumpRecord> from = read_tess_dump(other + "/tess.bin");
  const Verdict v = verify(with_records("level", [&](std::vector<TessDumpRecord>& records) {
    std::vector<TessDumpRecord> out(records.begin(), records.begin() + 200 * kPerPatch);
    std::copy_if(from.begin(), from.end(), std::back_inserter(out), [](const TessDumpRecord& r) { return r.patch_id == 200; });
    out.insert(out.end(), records.begin() + 201 * kPerPatch, records.end());
    records = out;
  }));
  // Fractional odd spacing makes 13 segments of either level: the same count, other coordinates.
  EXPECT_EQ(v.report["tessellation"]["emitted_count_differs_patches"], 0);
  EXPECT_FAILS_AS(v, "gl_TessCoord streams differ in 1 of 256 patches (first: patch 200)");
}

TEST_F(VerifyMutations, ACoordinateOneUlpOffFailsOnCoordinates) {
  const Verdict v = verify(with_records("ulp", [](std::vector<TessDumpRecord>& records) {
    for (TessDumpRecord* r : emissions_of(records, 33, 5)) r->tess_coord.y = std::nextafter(r->tess_coord.y, 2.0f);
  }));
  EXPECT_FAILS_AS(v, "gl_TessCoord streams differ in 1 of 256 patches (first: patch 33)");
}

// NaN compares false with every limit: it must be named, not pass as a distance of nothing.
TEST_F(VerifyMutations, ANaNPositionFails) {
  const Verdict v = verify(with_records("nan", [](std::vector<TessDumpRecord>& records) {
    records[150 * kPerPatch + 100].position.x = std::nanf("");
  }));
  EXPECT_FAILS_AS(v, "tess.bin: 1 records hold a NaN or infinite position or normal where tessref's is finite, or the "
                     "reverse (first: patch 150)");
}

TEST_F(VerifyMutations, AnInfiniteNormalFails) {
  const Verdict v = verify(with_records("inf", [](std::vector<TessDumpRecord>& records) {
    records[151 * kPerPatch + 7].normal.z = INFINITY;
  }));
  EXPECT_FAILS_AS(v, "(first: patch 151)");
  EXPECT_TRUE(v.failed_with("NaN or infinite"));
}

TEST_F(VerifyMutations, APatchIdOutOfRangeFails) {
  const Verdict v = verify(with_records("range", [](std::vector<TessDumpRecord>& records) {
    for (std::size_t k = 255 * kPerPatch; k < 256 * kPerPatch; ++k) records[k].patch_id = 4000;
  }));
  EXPECT_FAILS_AS(v, "759 records of tess.bin and 0 digests of tess_patches.bin name a patch the scene does not have "
                     "(first: patch 4000; tessref tessellated patches 0 to 255)");
}

TEST_F(VerifyMutations, ATessBinCutInARecordIsABadCapture) {
  const std::filesystem::path copy = copy_of_capture("cut");
  std::filesystem::resize_file(copy / "tess.bin", std::filesystem::file_size(copy / "tess.bin") - 20);
  EXPECT_BAD_CAPTURE(verify(copy), "tess.bin: the tessellation dump ends in the middle of a record");
}

// Cut at a record boundary, so that reading cannot tell: the manifest's count does.
TEST_F(VerifyMutations, ARecordCountOtherThanTheManifestsIsABadCapture) {
  const Verdict v = verify(with_records(
      "short", [](std::vector<TessDumpRecord>& records) { records.resize(records.size() - 3); }, false));
  EXPECT_BAD_CAPTURE(v, "tess.bin: holds 194301 records, manifest.json's tess_records_stored is 194304");
}

TEST_F(VerifyMutations, AnEditedDigestFailsOnCoordinates) {
  const std::filesystem::path copy = copy_of_capture("digest");
  std::vector<TessPatchDigest> digests = read_patch_digests((copy / "tess_patches.bin").string());
  ASSERT_EQ(digests.size(), kPatches);
  digests[57].coords_hash ^= 1;
  write_patch_digests((copy / "tess_patches.bin").string(), digests);
  EXPECT_FAILS_AS(verify(copy), "gl_TessCoord streams differ in 1 of 256 patches (first: patch 57)");
}

// --- color.png and depth.exr ------------------------------------------------------------------

// How many pixels two images have more than 2/255 apart: each image edit must change enough
// pixels to fail the colour limit (99.99% of 16,384 pixels: at most one may differ).
std::size_t pixels_apart(const Rgb8Image& a, const Rgb8Image& b) {
  std::size_t n = 0;
  for (std::size_t p = 0; p < a.pixels.size() / 3; ++p)
    for (int k = 0; k < 3; ++k)
      if (std::abs(int(a.pixels[3 * p + k]) - int(b.pixels[3 * p + k])) > 2) {
        ++n;
        break;
      }
  return n;
}

TEST_F(VerifyMutations, AShiftedColourRegionFailsOnColour) {
  Rgb8Image before;
  const std::filesystem::path copy = with_color("region", [&](Rgb8Image& c) {
    before = c;
    for (int y = 40; y < 72; ++y)  // a 32 x 32 block moved 6 pixels right
      for (int x = 40; x < 72; ++x)
        for (int k = 0; k < 3; ++k) c.pixels[3 * (y * 128 + x + 6) + k] = before.pixels[3 * (y * 128 + x) + k];
  });
  ASSERT_GT(pixels_apart(before, read_rgb8_image(copy / "color.png")), 20u);
  const Verdict v = verify(copy);
  EXPECT_FAILS_AS(v, "% of pixels within 2/255 (required: 99.99%");
  EXPECT_EQ(v.report["failures"].size(), 1u) << v.report["failures"].dump();
}

TEST_F(VerifyMutations, AMirroredColourImageFailsOnColour) {
  Rgb8Image before;
  const std::filesystem::path copy = with_color("mirrored", [&](Rgb8Image& c) {
    before = c;
    for (int y = 0; y < 128; ++y)  // upside down
      std::copy_n(&before.pixels[3 * 128 * (127 - y)], 3 * 128, &c.pixels[3 * 128 * y]);
  });
  ASSERT_GT(pixels_apart(before, read_rgb8_image(copy / "color.png")), 100u);
  EXPECT_FAILS_AS(verify(copy), "% of pixels within 2/255 (required: 99.99%");
}

TEST_F(VerifyMutations, SwappedColourChannelsFailOnColour) {
  Rgb8Image before;
  const std::filesystem::path copy = with_color("bgr", [&](Rgb8Image& c) {
    before = c;
    for (std::size_t p = 0; p < c.pixels.size(); p += 3) std::swap(c.pixels[p], c.pixels[p + 2]);
  });
  ASSERT_GT(pixels_apart(before, read_rgb8_image(copy / "color.png")), 100u);
  EXPECT_FAILS_AS(verify(copy), "% of pixels within 2/255 (required: 99.99%");
}

// The size check must blame the image that has the other size, not the one read second.
TEST_F(VerifyMutations, AColourImageOfAnotherSizeIsBlamed) {
  const std::filesystem::path copy = copy_of_capture("small_color");
  write_rgb8_image(Rgb8Image{64, 64, std::vector<std::uint8_t>(64 * 64 * 3, 0)}, copy / "color.png");
  const Verdict v = verify(copy);
  EXPECT_BAD_CAPTURE(v, "color.png: the image is 64x64, the scene in manifest.json is 128x128");
  EXPECT_THAT(v.run.output, Not(HasSubstr("depth.exr")));
}

TEST_F(VerifyMutations, ADepthImageOfAnotherSizeIsBlamed) {
  const Verdict v = verify(with_depth("small_depth", [](FloatImage& d) {
    d.width = d.height = 64;
    d.pixels.assign(64 * 64, 1.0f);
  }));
  EXPECT_BAD_CAPTURE(v, "depth.exr: the image is 64x64, the scene in manifest.json is 128x128");
  EXPECT_THAT(v.run.output, Not(HasSubstr("color.png")));
}

// Coverage 3 pixels to the right: pixels 2 and more from the silhouette disagree.
TEST_F(VerifyMutations, AShiftedDepthImageFailsOnTheSilhouette) {
  const Verdict v = verify(with_depth("depth_shift", [](FloatImage& d) {
    const FloatImage before = d;
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x) d.pixels[y * d.width + x] = x < 3 ? 1.0f : before.pixels[y * d.width + x - 3];
  }));
  EXPECT_FAILS_AS(v, "coverage mismatches farther than 0.5 px from the silhouette");
}

// A hole in the middle of the surface: 4 x 4 pixels of depth 1 where the torus covers.
TEST_F(VerifyMutations, AHoleInTheDepthImageFailsOnTheSilhouette) {
  int hole_x = -1, hole_y = -1;
  const Verdict v = verify(with_depth("depth_hole", [&](FloatImage& d) {
    for (int y = 4; y + 8 < d.height && hole_x < 0; ++y)  // the first 8 x 8 block the torus covers whole
      for (int x = 4; x + 8 < d.width && hole_x < 0; ++x) {
        bool covered = true;
        for (int k = 0; k < 64 && covered; ++k) covered = d.pixels[(y + k / 8) * d.width + x + k % 8] < 1.0f;
        if (covered) hole_x = x + 2, hole_y = y + 2;
      }
    for (int k = 0; k < 16; ++k) d.pixels[(hole_y + k / 4) * d.width + hole_x + k % 4] = 1.0f;
  }));
  ASSERT_GE(hole_x, 0);
  EXPECT_FAILS_AS(v, "coverage mismatches farther than 0.5 px from the silhouette");
  EXPECT_GE(v.report["silhouette"]["beyond_limit"].get<int>(), 4);
}

// --- tessref's rendering differs from what was captured ---------------------------------------

TEST_F(VerifyMutations, TessrefAtAnotherLevelFailsOnCoordinates) {
  const Verdict v = verify(copy_of_capture("r_level"), " --set tessellation.outer=12,12,13");
  EXPECT_FAILS_AS(v, "gl_TessCoord streams differ in 256 of 256 patches (first: patch 0)");
  EXPECT_THAT(v.run.output, HasSubstr("was captured from another scene"));
}

TEST_F(VerifyMutations, TessrefWithTheOtherWindingFailsOnWinding) {
  const Verdict v = verify(copy_of_capture("r_winding"), " --set tessellation.winding=cw");
  EXPECT_FAILS_AS(v, "64768 triangles in 256 patches are wound the other way round than tessref's (first: patch 0, "
                     "253 of its 253 triangles");
}

// Linear normals instead of quadratic ones: PN positions do not depend on the normal mode, so
// only the normals (and the shading) tell.
TEST_F(VerifyMutations, TessrefWithAnotherNormalFormulaFailsOnNormals) {
  const Verdict v = verify(copy_of_capture("r_normals"), " --set tessellation.normal_mode=linear");
  EXPECT_FAILS_AS(v, "normals differ by up to");
  EXPECT_FALSE(v.failed_with("evaluated positions"));
  EXPECT_FALSE(v.failed_with("gl_TessCoord streams"));
}

TEST_F(VerifyMutations, TessrefMovedFailsOnPositionsAndDistance) {
  const Verdict v = verify(copy_of_capture("r_moved"), " --set transform.translate=0.01,0,0");
  EXPECT_FAILS_AS(v, "evaluated positions differ by up to");
  EXPECT_FAILS_AS(v, "Hausdorff distance");
}

TEST_F(VerifyMutations, TessrefWithAMovedLightFailsOnColour) {
  const Verdict v = verify(copy_of_capture("r_light"), " --set lights.0.position=6,5,-10");
  EXPECT_FAILS_AS(v, "% of pixels within 2/255 (required: 99.99%");
  EXPECT_FALSE(v.failed_with("gl_TessCoord streams"));
  EXPECT_FALSE(v.failed_with("normals"));
}

}  // namespace
}  // namespace tessref
