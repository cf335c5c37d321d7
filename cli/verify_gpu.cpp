// `tessref verify SCENE --gpu DIR`: tessref's image of an imported frame against the GPU's own
// image of it (DIR/gpu.png from `tessref import`, or any image file). Where they part by more than
// 1/255, it names the first such pixel (reading order: top row first), the draw and the patch
// whose fragment tessref kept there (the pixel's fragments replayed by inspect/inspect_pixel.h),
// and the inspect commands that open them.
#include "cli/verify_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/scene_name.h"
#include "cli/shard.h"
#include "common/error.h"
#include "inspect/inspect_pixel.h"
#include "io/image_output.h"
#include "mesh/camera.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace tessref::cli {
namespace {

std::string with_commas(long long v) {
  std::string s = std::to_string(v);
  for (int i = int(s.size()) - 3; i > 0; i -= 3) s.insert(std::size_t(i), ",");
  return s;
}

// draws.json beside the scene (written by tessref import): which capture call or event each draw was.
std::string capture_call(const std::filesystem::path& scene_dir, std::size_t draw) {
  std::ifstream in(scene_dir / "draws.json");
  if (!in) return {};
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_array() || draw >= j.size() || !j[draw].is_object()) return {};
  const nlohmann::json& d = j[draw];
  for (const char* unit : {"call", "event"})  // an apitrace call number, a RenderDoc event id
    if (d.contains(unit) && d[unit].is_number_integer() && d.contains("name") && d["name"].is_string())
      return std::string(" (capture ") + unit + " " + std::to_string(d[unit].get<long long>()) + ", " +
             d["name"].get<std::string>() + ")";
  return {};
}

// The evaluation shader's emitted triangles of one draw: each corner's gl_Position, and the patch
// (gl_PrimitiveID) it belongs to, in emission order.
struct EmittedVertices {
  std::vector<glm::vec4> positions;
  std::vector<std::uint32_t> patches;
};

// gpu_tes.bin / gpu_tes.json (tessref import of a RenderDoc capture): the driver's emitted
// vertices, gl_Position first in each. Empty when the folder has none.
std::vector<glm::vec4> read_gpu_tes(const std::filesystem::path& dir) {
  std::ifstream layout_file(dir / "gpu_tes.json");
  std::ifstream data(dir / "gpu_tes.bin", std::ios::binary);
  if (!layout_file || !data) return {};
  const nlohmann::json layout = nlohmann::json::parse(layout_file, nullptr, false);
  if (!layout.is_object() || !layout.contains("stride_bytes") || !layout["stride_bytes"].is_number_unsigned() ||
      !layout.contains("outputs") || !layout["outputs"].is_array() || layout["outputs"].empty() ||
      layout["outputs"][0].value("name", "") != "gl_Position")
    throw InputError((dir / "gpu_tes.json").string() + ": not the layout tessref import writes");
  const std::size_t stride = layout["stride_bytes"].get<std::size_t>();
  if (stride < 16 || stride % 4 != 0) throw InputError((dir / "gpu_tes.json").string() + ": stride_bytes " + std::to_string(stride));
  const std::string bytes((std::istreambuf_iterator<char>(data)), std::istreambuf_iterator<char>());
  if (bytes.size() % stride != 0)
    throw InputError((dir / "gpu_tes.bin").string() + ": " + std::to_string(bytes.size()) + " bytes is not a whole number of " +
                     std::to_string(stride) + "-byte vertices");
  std::vector<glm::vec4> out(bytes.size() / stride);
  for (std::size_t v = 0; v < out.size(); ++v) std::memcpy(&out[v], bytes.data() + v * stride, sizeof(glm::vec4));
  return out;
}

// Compares the draw's emitted gl_Position with the GPU's, vertex by vertex in emission order. GL
// fixes neither the rounding of a shader's arithmetic (a driver may fuse a multiply and an add
// where the GLSL does not say precise; tessref never does) nor so the last bits of gl_Position:
// a component within 2^-20 max(1, |w|) of the GPU's passes, and the identical ones are counted.
bool compare_tes(const EmittedVertices& ours, const std::vector<glm::vec4>& gpu, std::size_t draw) {
  std::printf("  evaluation outputs of draw %zu (gl_Position of each emitted triangle's corners): ", draw);
  if (ours.positions.size() != gpu.size()) {
    std::printf("FAIL: the GPU emitted %s vertices, tessref %s\n", with_commas((long long)gpu.size()).c_str(),
                with_commas((long long)ours.positions.size()).c_str());
    return false;
  }
  long long identical = 0;
  std::size_t first = gpu.size(), first_beyond = gpu.size();
  double largest = 0.0;  // relative to max(1, |w|)
  for (std::size_t v = 0; v < gpu.size(); ++v) {
    if (std::memcmp(&ours.positions[v], &gpu[v], sizeof(glm::vec4)) == 0) {
      ++identical;
      continue;
    }
    if (first == gpu.size()) first = v;
    const double scale = std::max(1.0, double(std::fabs(gpu[v].w)));
    double d = 0.0;
    for (int c = 0; c < 4; ++c) d = std::max(d, double(std::fabs(ours.positions[v][c] - gpu[v][c])) / scale);
    largest = std::max(largest, d);
    if (!(d <= std::ldexp(1.0, -20)) && first_beyond == gpu.size()) first_beyond = v;
  }
  const std::string total = with_commas((long long)gpu.size());
  if (first == gpu.size()) {
    std::printf("PASS: %s of %s identical, in the same order\n", total.c_str(), total.c_str());
    return true;
  }
  const std::size_t shown = first_beyond != gpu.size() ? first_beyond : first;
  const glm::vec4 a = ours.positions[shown], b = gpu[shown];
  const std::uint32_t patch = ours.patches[shown] - ours.patches.front();
  std::printf("%s: %s of %s identical, the largest difference %.3g of max(1, |w|) (bound 2^-20); %s vertex %zu "
              "(triangle %zu, patch %u): tessref (%.9g, %.9g, %.9g, %.9g), GPU (%.9g, %.9g, %.9g, %.9g)\n",
              first_beyond == gpu.size() ? "PASS" : "FAIL", with_commas(identical).c_str(), total.c_str(), largest,
              first_beyond == gpu.size() ? "the first that differs:" : "the first beyond the bound:", shown, shown / 3,
              patch, double(a.x), double(a.y), double(a.z), double(a.w), double(b.x), double(b.y), double(b.z),
              double(b.w));
  return first_beyond == gpu.size();
}

// The depth the draws left against the GPU's (gpu_depth.exr from a RenderDoc import), pixel by
// pixel. Window z is not fixed to the bit by GL: llvmpipe interpolates it with float plane
// equations, tessref in double, and a fragment's z differs by some float steps, more on steep
// triangles, where the plane's terms are far larger than z (measured: at most 3 steps of 2^-24
// in docs/draws.md's G-buffer, 9 on the test application's bicubic patch); 16 steps pass.
bool compare_depth(const Framebuffer& fb, const std::filesystem::path& file) {
  const FloatImage gpu = read_float_image(file);
  std::printf("  depth (%s): ", file.filename().string().c_str());
  if (gpu.width != fb.width || gpu.height != fb.height || gpu.channels < 1) {
    std::printf("FAIL: %d x %d, the scene's image %d x %d\n", gpu.width, gpu.height, fb.width, fb.height);
    return false;
  }
  long long identical = 0, beyond = 0;
  double largest = 0.0;
  int first_x = -1, first_y = -1;
  for (int y = 0; y < fb.height; ++y)
    for (int x = 0; x < fb.width; ++x) {
      const float ours = fb.depth[std::size_t(fb.height - 1 - y) * std::size_t(fb.width) + std::size_t(x)];
      const float theirs = gpu.pixels[(std::size_t(y) * std::size_t(gpu.width) + std::size_t(x)) * std::size_t(gpu.channels)];
      if (ours == theirs) {
        ++identical;
        continue;
      }
      const double d = std::fabs(double(ours) - double(theirs));
      largest = std::max(largest, d);
      if (d > 16.0 * std::ldexp(1.0, -24) && beyond++ == 0) first_x = x, first_y = y;
    }
  const long long pixels = (long long)fb.width * fb.height;
  std::printf("%s: %s of %s pixels identical, the largest difference %.3g steps of 2^-24 (bound 16)", beyond ? "FAIL" : "PASS",
              with_commas(identical).c_str(), with_commas(pixels).c_str(), largest * std::ldexp(1.0, 24));
  if (beyond) std::printf("; %s beyond it, the first at (%d, %d)", with_commas(beyond).c_str(), first_x, first_y);
  std::printf("\n");
  return beyond == 0;
}

}  // namespace

int run_verify_gpu(const std::string& scene_path, const std::vector<std::string>& sets, const std::string& gpu,
                   int threads) {
  if (scene_path.empty()) throw InputError("--gpu needs the imported SCENE (DIR/scene.json)");
  std::error_code ec;
  // An import's folder (gpu.png, and from RenderDoc gpu_tes.bin and gpu_depth.exr), or an image.
  const std::filesystem::path gpu_dir = std::filesystem::is_directory(gpu, ec) ? std::filesystem::path(gpu) : std::filesystem::path();
  const std::filesystem::path gpu_image = gpu_dir.empty() ? std::filesystem::path(gpu) : gpu_dir / "gpu.png";
  Scene scene = load_scene(scene_path, sets);
  if (scene.draws.empty()) throw InputError(scene.source + ": --gpu compares a scene of draws (tessref import writes one)");
  const Rgb8Image reference = read_rgb8_image(gpu_image);
  if (reference.width != scene.width || reference.height != scene.height)
    throw InputError("--gpu: " + gpu_image.string() + " is " + std::to_string(reference.width) + " x " +
                     std::to_string(reference.height) + ", the scene's image " + std::to_string(scene.width) + " x " +
                     std::to_string(scene.height));
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  scene.camera = fitted_camera(scene, mesh);
  const Parallel parallel(threads);
  // The chosen draw is the scene's last: keep its evaluation shader's emitted vertices when the
  // import holds the GPU's (gpu_tes.bin).
  const std::vector<glm::vec4> gpu_tes = gpu_dir.empty() ? std::vector<glm::vec4>{} : read_gpu_tes(gpu_dir);
  EmittedVertices emitted;
  std::size_t current_draw = 0;
  DrawOptions options;
  if (!gpu_tes.empty()) {
    options.begin_draw = [&](std::size_t d) { current_draw = d; };
    options.tess_surface = [&](const std::vector<TessDumpRecord>& records, const TriangleBatch& batch) {
      if (current_draw + 1 != scene.draws.size()) return;
      for (std::size_t t = 0; t < batch.triangle_count(); ++t)
        for (int c = 0; c < 3; ++c) {
          const std::size_t v = batch.vertex_index(t, c);
          const float* p = batch.vertex_data(v);
          emitted.positions.emplace_back(p[0], p[1], p[2], p[3]);
          emitted.patches.push_back(v < records.size() ? records[v].patch_id : 0);
        }
    };
  }
  Framebuffer fb;
  render_scene(scene, mesh, parallel, fb, options);
  const Rgb8Image ours = to_rgb8(fb);
  auto outputs_pass = [&] {  // the evaluation outputs and depth, where the import holds the GPU's
    const bool tes = gpu_tes.empty() || compare_tes(emitted, gpu_tes, scene.draws.size() - 1);
    const bool depth = gpu_dir.empty() || !std::filesystem::is_regular_file(gpu_dir / "gpu_depth.exr", ec) ||
                       compare_depth(fb, gpu_dir / "gpu_depth.exr");
    return tes && depth;
  };

  long long differing = 0;
  int largest = 0, first_x = -1, first_y = -1;
  int box[4] = {scene.width, scene.height, -1, -1};  // x0, y0, x1, y1 (y from the top)
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x) {
      const std::size_t at = (std::size_t(y) * std::size_t(scene.width) + std::size_t(x)) * 3;
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(ours.pixels[at + c]) - int(reference.pixels[at + c])));
      if (d <= 1) continue;
      if (differing++ == 0) first_x = x, first_y = y;
      largest = std::max(largest, d);
      box[0] = std::min(box[0], x), box[1] = std::min(box[1], y), box[2] = std::max(box[2], x), box[3] = std::max(box[3], y);
    }
  const long long pixels = (long long)scene.width * scene.height;
  std::printf("tessref verify: %s against %s (%d x %d): ", scene_path.c_str(), gpu_image.string().c_str(), scene.width,
              scene.height);
  if (differing == 0) {
    std::printf("PASS: colour within 1/255 at all %s pixels\n", with_commas(pixels).c_str());
    return outputs_pass() ? 0 : 1;
  }
  std::printf("FAIL: %s of %s pixels differ by more than 1/255 (largest %d/255), within x %d..%d, y %d..%d "
              "(from the top-left)\n",
              with_commas(differing).c_str(), with_commas(pixels).c_str(), largest, box[0], box[2], box[1], box[3]);
  const std::size_t at = (std::size_t(first_y) * std::size_t(scene.width) + std::size_t(first_x)) * 3;
  std::printf("  first differing pixel (%d, %d): tessref (%d, %d, %d), GPU (%d, %d, %d)\n", first_x, first_y,
              ours.pixels[at], ours.pixels[at + 1], ours.pixels[at + 2], reference.pixels[at],
              reference.pixels[at + 1], reference.pixels[at + 2]);
  const std::string scene_word = shell_word(scene_path);
  std::string patch_command;
  try {
    const PixelInspectResult r = inspect_draws_pixel(scene, first_x, first_y, parallel);
    if (!r.winner) {
      std::printf("  in tessref no draw's fragment stays there (the clear, or the framebuffer's first contents, "
                  "show): the GPU drew something tessref did not\n");
    } else {
      const PixelFragment& f = r.fragments[*r.winner];
      const std::size_t draw = f.draw.value_or(0);
      const std::string call = capture_call(std::filesystem::path(scene_path).parent_path(), draw);
      if (f.from_patch) {
        std::printf("  tessref's fragment there: draw %zu%s, patch %zu, triangle %zu, gl_TessCoord (%g, %g, %g)\n", draw,
                    call.c_str(), f.patch, f.triangle, f.tess_coord.x, f.tess_coord.y, f.tess_coord.z);
        patch_command = "tessref inspect " + scene_word + " --draw " + std::to_string(draw) + " --patch " +
                        std::to_string(f.patch) + " --trace";
      } else {
        std::printf("  tessref's fragment there: draw %zu%s, untessellated %s %zu\n", draw, call.c_str(),
                    f.primitive.c_str(), f.triangle);
      }
    }
  } catch (const InputError& e) {
    std::printf("  (its fragments cannot be followed: %s)\n", e.what());
  }
  std::printf("  open it: tessref inspect %s --pixel %d,%d --trace\n", scene_word.c_str(), first_x, first_y);
  if (!patch_command.empty()) std::printf("           %s\n", patch_command.c_str());
  outputs_pass();
  return 1;
}

int run_verify_gpu_folder(const std::string& folder, const std::string& shard_text, int threads) {
  const Shard shard = shard_text.empty() ? Shard{} : parse_shard(shard_text);
  std::vector<std::filesystem::path> imports;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_directory() && std::filesystem::is_regular_file(entry.path() / "scene.json")) imports.push_back(entry.path());
  std::sort(imports.begin(), imports.end());
  if (imports.empty()) throw InputError(folder + ": neither scene.json nor folders holding one (tessref import's output)");
  int passed = 0, taken = 0;
  for (std::size_t i = 0; i < imports.size(); ++i) {
    if (!shard.holds(i)) continue;
    ++taken;
    try {
      if (run_verify_gpu((imports[i] / "scene.json").string(), {}, imports[i].string(), threads) == 0) ++passed;
    } catch (const InputError& e) {
      std::printf("tessref verify: %s: error: %s\n", imports[i].string().c_str(), e.what());
    }
  }
  std::printf("tessref verify: %d of %d imported frames pass (shard %d/%d of %zu)\n", passed, taken, shard.index,
              shard.count, imports.size());
  return passed == taken ? 0 : 1;
}

}  // namespace tessref::cli
