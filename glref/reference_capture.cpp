#include "glref/reference_capture.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <optional>

#include "common/error.h"
#include "common/hash.h"
#include "glref/gl_context.h"
#include "glref/scene_renderer.h"
#include "render/transform_feedback.h"
#include "io/image_output.h"
#include "io/output_files.h"
#include "io/tess_digest.h"
#include "io/tess_dump.h"

namespace tessref::glref {
namespace {

int gl_integer(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

// FNV-1a, 64 bits, over the scene as read (compact JSON): names the scene a capture belongs to.
std::string scene_hash(const nlohmann::json& scene_json) {
  Fnv1a f;
  for (unsigned char c : scene_json.dump()) f.mix(c);
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(f.h));
  return buf;
}

}  // namespace

CaptureSummary capture_reference(GlContext& context, const Scene& scene, const Mesh& mesh,
                                 const nlohmann::json& scene_json, const std::string& command_line,
                                 const std::filesystem::path& dir, std::size_t max_tess_records) {
  CreatedFolder folder(dir, "the capture folder");  // removed again if the capture fails
  OutputFiles outputs;
  const auto color = outputs.add("color", dir / "color.png");
  const auto depth = outputs.add("depth", dir / "depth.exr");
  const auto tess = outputs.add("tess", dir / "tess.bin");
  const auto digests = outputs.add("tess_patches", dir / "tess_patches.bin");
  const auto manifest_path = outputs.add("manifest", dir / "manifest.json");

  // Transform feedback (draws[].transform_feedback): one file per buffer of each such draw.
  const std::vector<std::pair<std::size_t, std::string>> feedback_names = feedback_files(scene, "feedback");
  std::vector<std::filesystem::path> feedback_tmps;
  for (const auto& [draw, name] : feedback_names) feedback_tmps.push_back(outputs.add("transform feedback", dir / name));

  SceneRenderer renderer(context, scene, mesh);
  const Framebuffer fb = renderer.render();
  nlohmann::json feedback_manifest = nlohmann::json::array();
  if (!feedback_names.empty()) {
    std::size_t k = 0;
    for (const FeedbackBuffers& f : renderer.transform_feedback()) {
      nlohmann::json files = nlohmann::json::array();
      for (const std::vector<std::byte>& bytes : f.bytes) {
        write_binary_file(feedback_tmps[k], (dir / feedback_names[k].second).string(), bytes);
        files.push_back(feedback_names[k++].second);
      }
      feedback_manifest.push_back({{"draw", f.draw}, {"primitives", f.primitives}, {"vertices_per_primitive", f.corners},
                                   {"stream_primitives", f.stream_primitives}, {"files", files}});
    }
  }
  write_as(color, dir / "color.png", [&] { write_rgb8_image(to_rgb8(fb), color); });
  write_as(depth, dir / "depth.exr", [&] { write_depth_image(fb, depth); });
  CaptureSummary summary;
  {
    std::optional<TessDumpWriter> writer;
    write_as(tess, dir / "tess.bin", [&] { writer.emplace(tess.string()); });
    std::vector<TessDumpRecord> records;
    if (!scene.draws.empty())
      records = as_clip_records(renderer.capture_draws_tess());
    else if (scene.tessellation.enabled)
      for (const TessOutputVertex& v : renderer.capture_tess())
        records.push_back(TessDumpRecord{v.patch, v.tess_coord, v.position, v.normal});
    summary.tess_records = records.size();
    write_as(digests, dir / "tess_patches.bin", [&] { write_patch_digests(digests.string(), digest_patches(records)); });
    if (max_tess_records && records.size() > max_tess_records) {
      // Patches are about equally heavy: a stride of records / budget, rounded up, then grown
      // until the sample fits, or only patch 0 is left (kept even when it alone is over).
      std::uint32_t last_patch = 0;
      for (const TessDumpRecord& r : records) last_patch = std::max(last_patch, r.patch_id);
      summary.patch_stride = std::uint32_t(std::min<std::size_t>(
          (records.size() + max_tess_records - 1) / max_tess_records, std::size_t(last_patch) + 1));
      while (summary.patch_stride <= last_patch &&
             std::size_t(std::count_if(records.begin(), records.end(), [&](const TessDumpRecord& r) {
               return r.patch_id % summary.patch_stride == 0;
             })) > max_tess_records)
        ++summary.patch_stride;
      std::erase_if(records, [&](const TessDumpRecord& r) { return r.patch_id % summary.patch_stride != 0; });
    }
    summary.tess_records_stored = records.size();
    write_as(tess, dir / "tess.bin", [&] {
      writer->write(records);
      writer->close();
    });
  }
  context.make_current();
  summary.manifest = {
      {"format", "tessref capture 1"},
      {"gl_vendor", context.vendor()},
      {"gl_renderer", context.renderer()},
      {"gl_version", context.version()},
      {"limits",
       {{"GL_MAX_TESS_GEN_LEVEL", gl_integer(GL_MAX_TESS_GEN_LEVEL)},
        {"GL_MAX_PATCH_VERTICES", gl_integer(GL_MAX_PATCH_VERTICES)},
        {"GL_MAX_TESS_CONTROL_OUTPUT_COMPONENTS", gl_integer(GL_MAX_TESS_CONTROL_OUTPUT_COMPONENTS)},
        {"GL_MAX_TESS_EVALUATION_OUTPUT_COMPONENTS", gl_integer(GL_MAX_TESS_EVALUATION_OUTPUT_COMPONENTS)}}},
      {"scene_source", scene.source},
      {"scene_fnv1a64", scene_hash(scene_json)},
      {"scene", scene_json},
      {"command_line", command_line},
      {"date_utc", utc_now()},
      {"files",
       {{"color", "color.png (8-bit RGB, quantized as tessref's PNGs are)"},
        {"depth", "depth.exr (window-space depth, 1 where nothing was drawn)"},
        {"tess", "tess.bin (--dump-tess binary format; one record per emitted vertex, 3 per triangle, of the "
                 "patches whose id is a multiple of tess_patch_stride)"},
        {"tess_patches", "tess_patches.bin (per patch: emitted vertices and a hash of its distinct gl_TessCoord; "
                         "io/tess_digest.h)"},
        {"transform_feedback", "feedback.drawD.bufferB.bin (what transform feedback wrote into buffer B over draw D, "
                               "as many bytes as its primitives filled)"}}},
      {"tess_values", scene.draws.empty() ? "position and normal: the evaluation shader's outputs at locations 0 and 1"
                                          : "gl_Position: x, y, z as the position, w as the normal's x"},
      {"transform_feedback", feedback_manifest},
      {"tess_records", summary.tess_records},
      {"tess_records_stored", summary.tess_records_stored},
      {"tess_patch_stride", summary.patch_stride}};
  {
    std::ofstream out(manifest_path);
    out << summary.manifest.dump(2) << "\n";
    if (!out.flush()) throw InputError((dir / "manifest.json").string() + ": cannot write");
  }
  outputs.commit();
  folder.keep();
  return summary;
}

}  // namespace tessref::glref
