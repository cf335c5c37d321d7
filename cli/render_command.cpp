// `tessref render`: a scene to an image, with a one-line summary of what the pipeline did.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli/commands.h"
#include "cli/scene_name.h"
#include "cli/dump_budget.h"
#include "common/error.h"
#include "common/parallel.h"
#include "mesh/camera.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "io/output_files.h"
#include "render/render.h"
#include "render/draw_scene.h"
#include "render/storage_files.h"
#include "render/transform_feedback.h"
#include "scene/scene_loader.h"
#include "io/tess_dump.h"
#include "inspect/fragment_dump.h"
#include "check/check.h"
#include "render/glsl_scene.h"

namespace tessref::cli {
namespace {

struct RenderOptions {
  std::string scene;  // empty: the built-in default scene
  std::string output = "tessref.png";
  std::string depth, normals, dump_tess;
  std::string dump_fragments;  // --dump-fragments FILE.exr (inspect/fragment_dump.h)
  int threads = 0;
  std::uint64_t max_dump_bytes = 0;  // 0: the free space of the dump's file system
  int repeat = 1;              // frames rendered; the image is the last one's
  bool report_repeat = false;  // --repeat given: print per-stage medians over the frames
  std::vector<std::string> sets;
  bool check = false;  // --check: NaN and infinity in every stage's outputs (check/check.h)
  std::vector<std::string> check_ranges;  // --check-range NAME=LO,HI (check/check_range.h)
  std::vector<std::string> draw_buffers;  // --draw-buffer K=FILE: draw buffer K (1..7) as an image
  std::string transform_feedback;  // --transform-feedback PREFIX: PREFIX.drawD.bufferB.bin
  std::string storage_buffers;     // --storage-buffers PREFIX: PREFIX.NAME.bin
  std::string images;              // --images PREFIX: PREFIX.NAME.bin
};



// --draw-buffer K=FILE, checked against the scene: a scene of draws has framebuffer.color's
// attachments, the mesh path draw buffers 0 and 1 (its normals).
std::pair<int, std::string> parse_draw_buffer(const std::string& arg, const Scene& scene) {
  const std::size_t eq = arg.find('=');
  const std::string k = arg.substr(0, eq == std::string::npos ? 0 : eq);
  const int available = scene.draws.empty() ? 2 : int(scene.framebuffer.color.size());
  if (eq == std::string::npos || eq + 1 == arg.size() || k.size() != 1 || k[0] < '1' || k[0] > '7')
    throw InputError("--draw-buffer: expected K=FILE with K in 1..7 (draw buffer 0 is -o), got '" + arg + "'");
  if (k[0] - '0' >= available)
    throw InputError("--draw-buffer " + arg + ": the scene's framebuffer has " + std::to_string(available) +
                     " draw buffer" + (available == 1 ? "" : "s") + " (framebuffer.color)");
  return {k[0] - '0', arg.substr(eq + 1)};
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A progress line on stderr, only for a terminal and only once the run has taken a second: what
// it is doing ("rendering", "writing FILE"), the share of the draw done and the time so far. Its
// own thread redraws it five times a second, and only when the text changed: a draw that reports
// rarely (one batch of a slow fragment shader) still shows that it is alive, and a fast one does
// not flood the terminal.
class ProgressLine {
 public:
  ProgressLine() : start_(Clock::now()) {
    if (isatty(STDERR_FILENO) == 1) ticker_ = std::thread([this] { run(); });
  }
  ~ProgressLine() { stop(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(double fraction) { fraction_.store(fraction, std::memory_order_relaxed); }
  void stage(std::string what) {
    std::lock_guard lock(mutex_);
    stage_ = std::move(what);
  }
  // Clears the line; nothing is drawn after it (call before printing anything else).
  void stop() {
    if (!ticker_.joinable()) return;
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    ticker_.join();
    if (!last_.empty()) std::fprintf(stderr, "\r%*s\r", int(last_.size()), "");
    std::fflush(stderr);
  }

 private:
  void run() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(200), [&] { return done_; })) {
      const double elapsed = seconds_since(start_);
      if (elapsed < 1.0) continue;
      char line[200];
      if (stage_ == "rendering") {
        const double f = std::clamp(fraction_.load(std::memory_order_relaxed), 0.0, 1.0);
        const int width = 30, filled = static_cast<int>(f * width + 0.5);
        std::snprintf(line, sizeof line, "rendering [%s%s] %3d%%  %.0f s", std::string(filled, '#').c_str(),
                      std::string(width - filled, ' ').c_str(), static_cast<int>(f * 100.0 + 0.5), elapsed);
      } else {
        std::snprintf(line, sizeof line, "%s  %.0f s", stage_.c_str(), elapsed);
      }
      if (line == last_) continue;
      std::fprintf(stderr, "\r%-*s", int(last_.size()), line);  // padded over a longer last line
      std::fflush(stderr);
      last_ = line;
    }
  }

  const Clock::time_point start_;
  std::atomic<double> fraction_{0.0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::string stage_ = "rendering", last_;
  std::thread ticker_;
};

std::string ms(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f ms", seconds * 1e3);
  return buf;
}

// Per-frame times of one stage over the --repeat frames.
struct StageTimes {
  const char* name;
  std::vector<double> seconds;

  // "54.2 ms (50.1 .. 60.3 ms)": median (the mean of the middle two for an even count), min, max.
  std::string summary() const {
    std::vector<double> v = seconds;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    const double median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s %.1f ms (%.1f .. %.1f ms)", name, median * 1e3, v.front() * 1e3,
                  v.back() * 1e3);
    return buf;
  }
};

// Every file the render wrote, the colour image first.
std::string written_files(const RenderOptions& o, const TessDumpWriter* dump) {
  std::string files = o.output;
  if (!o.depth.empty()) files += ", " + o.depth + " (depth)";
  if (!o.normals.empty()) files += ", " + o.normals + " (normals)";
  for (const std::string& b : o.draw_buffers) files += ", " + b.substr(b.find('=') + 1) + " (draw buffer " + b.substr(0, 1) + ")";
  if (dump)
    files += ", " + o.dump_tess + " (" + std::to_string(dump->records_written()) + " tessellated vertices)";
  return files;
}

// An image of nothing but the background exits 0 (it may be what was asked for), but says why.
void warn_nothing_drawn(const DrawStats& s) {
  const RasterStats& r = s.raster;
  if (r.fragments_depth_failed > 0) {  // the geometry reached pixels: the depth test turned it away
    std::fprintf(stderr,
                 "tessref: warning: nothing was drawn (0 fragments shaded): %llu fragments covered pixels but "
                 "failed the depth test. Check camera.near and camera.far (a huge far / near ratio leaves "
                 "no depth precision), the depth range and, in a scene of draws, depth_func and the initial depth\n",
                 static_cast<unsigned long long>(r.fragments_depth_failed));
    return;
  }
  std::fprintf(stderr,
               "tessref: warning: nothing was drawn (0 fragments shaded): of %llu triangles, "
               "%llu lie outside the view volume, %llu were culled (back-facing or zero area), "
               "%llu passed to the rasterizer covered no pixel centre; %llu patches were "
               "discarded by their levels. Check camera (camera.fit frames the mesh), "
               "cull_back_faces and the tessellation levels\n",
               static_cast<unsigned long long>(r.triangles_in),
               static_cast<unsigned long long>(r.triangles_clipped_away),
               static_cast<unsigned long long>(r.triangles_culled),
               static_cast<unsigned long long>(r.triangles_rasterized),
               static_cast<unsigned long long>(s.tess.patches_discarded));
}

// --check's context: the inspect command's scene arguments, each GLSL stage's source, the ranges.
CheckContext check_context(const RenderOptions& o, const Scene& scene) {
  CheckContext c;
  c.inspect_args = scene_arguments(o.scene, o.sets);
  c.image_height = scene.height;
  if (scene.shaders.program != ShaderProgram::Builtin)
    for (const shader::ShaderSource& src : scene_sources(scene)) {
      CheckSource* dst = src.stage == shader::Stage::Vertex        ? &c.vertex
                         : src.stage == shader::Stage::TessControl ? &c.control
                         : src.stage == shader::Stage::TessEval    ? &c.evaluation
                         : src.stage == shader::Stage::Fragment    ? &c.fragment
                                                                   : nullptr;
      if (dst) *dst = CheckSource{src.file, src.text, src.first_line};
    }
  const std::vector<CheckOutput> outputs = evaluation_output_names(c.evaluation);
  for (const std::string& spec : o.check_ranges) c.ranges.push_back(parse_check_range(spec, outputs));
  return c;
}

void run_render(const RenderOptions& o) {
  Scene scene = load_scene(o.scene, o.sets);
  // Every output checked before any work: its folder, its format, and no two on one file. All
  // are written to temporaries and moved into place together at the end, or none is.
  OutputFiles outputs;
  const std::filesystem::path color_tmp = outputs.add("-o", o.output);
  check_image_path(o.output, ImageKind::Color);
  std::filesystem::path depth_tmp, normals_tmp, dump_tmp;
  if (!o.depth.empty()) {
    depth_tmp = outputs.add("--depth", o.depth);
    check_image_path(o.depth, ImageKind::Depth);
  }
  if (!o.normals.empty()) {
    normals_tmp = outputs.add("--normals", o.normals);
    check_image_path(o.normals, ImageKind::Normals);
  }
  if (!o.dump_tess.empty()) dump_tmp = outputs.add("--dump-tess", o.dump_tess);
  std::vector<std::pair<int, std::string>> buffer_files;
  std::vector<std::filesystem::path> buffer_tmps;
  for (const std::string& arg : o.draw_buffers) {
    buffer_files.push_back(parse_draw_buffer(arg, scene));
    buffer_tmps.push_back(outputs.add("--draw-buffer", buffer_files.back().second));
    check_image_path(buffer_files.back().second, ImageKind::Color);
  }

  std::vector<std::pair<std::size_t, std::string>> feedback_outputs;
  std::vector<std::filesystem::path> feedback_tmps;
  if (!o.transform_feedback.empty()) {
    feedback_outputs = feedback_files(scene, o.transform_feedback);
    if (feedback_outputs.empty())
      throw InputError("--transform-feedback: no draw of the scene has a transform_feedback key "
                       "(draws[].transform_feedback: {varyings, buffer_mode})");
    for (const auto& [draw, file] : feedback_outputs) feedback_tmps.push_back(outputs.add("--transform-feedback", file));
  }
  std::vector<std::pair<std::size_t, std::string>> storage_outputs;
  std::vector<std::filesystem::path> storage_tmps;
  if (!o.storage_buffers.empty()) {
    storage_outputs = storage_buffer_files(scene, o.storage_buffers);
    if (storage_outputs.empty())
      throw InputError("--storage-buffers: no draw of the scene binds a buffer to a shader storage block "
                       "(draws[].shader_storage_buffers)");
    for (const auto& [buffer, file] : storage_outputs) storage_tmps.push_back(outputs.add("--storage-buffers", file));
  }

  auto t = Clock::now();
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  scene.camera = fitted_camera(scene, mesh);
  const double mesh_seconds = seconds_since(t);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());

  const Parallel parallel(o.threads);
  std::unique_ptr<TessDumpWriter> dump;
  std::optional<DumpBudget> budget;
  if (!o.dump_tess.empty()) {
    if (!scene.tessellation.enabled)
      throw InputError("--dump-tess: the scene does not tessellate (tessellation.enabled is false)");
    write_as(dump_tmp, o.dump_tess, [&] { dump = std::make_unique<TessDumpWriter>(dump_tmp.string()); });
    std::vector<std::string> images{o.output};
    for (const std::string& file : {o.depth, o.normals})
      if (!file.empty()) images.push_back(file);
    for (const std::string& b : o.draw_buffers) images.push_back(b.substr(b.find('=') + 1));
    // An image's most: four float channels a pixel uncompressed, and 1 MiB of headers.
    const std::uint64_t image_bytes = std::uint64_t(scene.width) * std::uint64_t(scene.height) * 16 + (1u << 20);
    budget.emplace(o.dump_tess, o.max_dump_bytes, images, image_bytes);
    if (const auto invocations = predicted_tes_invocations(scene, mesh)) budget->check_estimate(*invocations, dump->text());
  }
  // --repeat: every frame renders the same scene again into the same framebuffer memory (as a GL
  // application redraws into its framebuffer); the first also feeds --dump-tess (the records are
  // the same each frame), the last one's framebuffer is written.
  StageTimes vertex{"vertex", {}}, tessellation{"tessellation", {}}, raster{"raster+fs", {}},
      frame{"frame", {}};
  RenderResult result;
  std::vector<FeedbackBuffers> feedback;  // the first frame's
  DrawnMemory memory;  // the first frame's buffers and images after its draws
  const bool wants_memory = !storage_outputs.empty() || !o.images.empty();
  if (!o.images.empty() && scene.draws.empty())
    throw InputError("--images: the scene has no draws (images are bound by draws' shaders.textures)");
  std::unique_ptr<Checker> checker;
  if (o.check || !o.check_ranges.empty()) checker = std::make_unique<Checker>(check_context(o, scene));
  ProgressLine progress;
  try {
    for (int i = 0; i < o.repeat; ++i) {
      DrawOptions options;
      options.normals = !o.normals.empty();
      options.check = checker.get();
      options.progress = [&](double f) { progress.update((i + f) / o.repeat); };
      if (dump && i == 0)
        options.dump_tess = [&](const std::vector<TessDumpRecord>& r) {
          dump->write(r);
          budget->check_written(*dump);
        };
      const auto t0 = Clock::now();
      result.stats = render_scene(scene, mesh, parallel, result.framebuffer, options,
                                  i == 0 && !feedback_outputs.empty() ? &feedback : nullptr,
                                  i == 0 && wants_memory ? &memory : nullptr);
      frame.seconds.push_back(seconds_since(t0));
      vertex.seconds.push_back(result.stats.vertex_seconds);
      tessellation.seconds.push_back(result.stats.tessellation_seconds);
      raster.seconds.push_back(result.stats.raster_seconds);
    }
  } catch (const CheckOffence& e) {
    progress.stop();
    // No image: the temporaries (outputs, the dump) are removed as `outputs` goes.
    std::fprintf(stderr, "tessref render --check: %s, nothing written\n%s\n",
                 e.out_of_range() ? "value out of range" : "non-finite value", e.what());
    set_exit_code(1);
    return;
  }
  progress.stage("writing " + o.output);
  if (dump) write_as(dump_tmp, o.dump_tess, [&] { dump->close(); });

  t = Clock::now();
  const Framebuffer& fb = result.framebuffer;
  write_as(color_tmp, o.output, [&] { write_color_image(fb, color_tmp); });
  if (!o.depth.empty()) write_as(depth_tmp, o.depth, [&] { write_depth_image(fb, depth_tmp); });
  if (!o.normals.empty()) write_as(normals_tmp, o.normals, [&] { write_normals_image(fb, normals_tmp); });
  for (std::size_t i = 0; i < buffer_files.size(); ++i)
    write_as(buffer_tmps[i], buffer_files[i].second,
             [&] { write_color_image(fb, buffer_tmps[i], buffer_files[i].first); });
  // Every draw with the key records (draw_scene_draws), in the files' order.
  std::string output_summary;
  std::size_t k = 0;
  for (const FeedbackBuffers& f : feedback) {
    output_summary += "; transform feedback, draw " + std::to_string(f.draw) + ": " + std::to_string(f.primitives) + " primitives";
    for (const std::vector<std::byte>& bytes : f.bytes) {
      write_binary_file(feedback_tmps[k], feedback_outputs[k].second, bytes);
      output_summary += ", " + feedback_outputs[k++].second + " " + std::to_string(bytes.size()) + " bytes";
    }
  }
  for (std::size_t i = 0; i < storage_outputs.size(); ++i) {
    const std::vector<std::byte>& bytes = memory.buffers.at(storage_outputs[i].first).bytes;
    write_binary_file(storage_tmps[i], storage_outputs[i].second, bytes);
    output_summary += "; " + storage_outputs[i].second + " " + std::to_string(bytes.size()) + " bytes";
  }
  if (!o.images.empty()) {
    if (memory.images.empty())
      throw InputError("--images: no draw binds a texture to an image uniform (shaders.textures naming an image2D ...)");
    for (const auto& [name, stored] : memory.images) {
      const std::string file = memory_file_name(o.images, name);
      const std::filesystem::path tmp = outputs.add("--images", file);
      write_binary_file(tmp, file, std::as_bytes(std::span(stored)));
      output_summary += "; " + file + " " + std::to_string(stored.size()) + " bytes";
    }
  }
  if (!o.dump_fragments.empty()) write_fragment_dump(scene, mesh, parallel, o.dump_fragments);  // draws again
  outputs.commit();
  const double write_seconds = seconds_since(t);
  progress.stop();
  if (checker)
    for (const std::string& w : checker->warnings()) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());

  const DrawStats& s = result.stats;
  for (const std::string& w : s.warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
  std::string tessellated;
  // A scene of draws counts GL's primitives (patches, triangles, lines, points); the mesh path its
  // triangles.
  const bool draws = !scene.draws.empty();
  if (draws ? s.tess.patches_in > 0 : scene.tessellation.enabled)
    tessellated = ", " + std::to_string(s.triangles_generated) + " after tessellation";
  std::printf(
      "tessref render: %s -> %s (%dx%d, %d threads): %llu %s in%s, %llu rasterized, "
      "%llu fragments shaded; mesh %s, vertex %s, tessellation %s, raster+fs %s, write %s%s\n",
      drawn_scene_name(scene, o.sets).c_str(), written_files(o, dump.get()).c_str(), scene.width,
      scene.height, parallel.threads(), static_cast<unsigned long long>(s.triangles_in),
      draws ? "primitives" : "triangles", tessellated.c_str(), static_cast<unsigned long long>(s.raster.triangles_rasterized),
      static_cast<unsigned long long>(s.raster.fragments_shaded), ms(mesh_seconds).c_str(),
      ms(s.vertex_seconds).c_str(), ms(s.tessellation_seconds).c_str(),
      ms(s.raster_seconds).c_str(), ms(write_seconds).c_str(), output_summary.c_str());
  if (s.raster.fragments_shaded == 0) warn_nothing_drawn(s);
  if (o.report_repeat)
    std::printf("tessref render: %d frame%s, median (min .. max): %s, %s, %s, %s\n", o.repeat,
                o.repeat == 1 ? "" : "s", vertex.summary().c_str(), tessellation.summary().c_str(), raster.summary().c_str(),
                frame.summary().c_str());
}

// --repeat N: a whole number of frames in [1, kMaxRepeat] (CLI11 prefixes the option's name).
constexpr int kMaxRepeat = 1000000;
std::string check_repeat(std::string& text) {
  int n = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, n);
  if (ec != std::errc() || ptr != end || n < 1 || n > kMaxRepeat)
    return "expected the number of frames, an integer from 1 to " + std::to_string(kMaxRepeat) +
           ", got \"" + text + "\"";
  return {};
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto opts = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene (JSON) to an image");
  add_scene_options(cmd, opts->scene, opts->sets);
  cmd->add_option("-o,--output", opts->output,
                  "color image; the extension picks the format (.png: 8-bit, .exr: float)")
      ->capture_default_str();
  cmd->add_option("--threads", opts->threads, "worker threads (0: all hardware threads)")
      ->check(kInteger)
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  CLI::Option* repeat = cmd->add_option("--repeat", opts->repeat,
                  "render the frame N times and print each stage's median, min and max time; "
                  "the image is written once, from the last frame")
      ->check(CLI::Validator(check_repeat, ""))
      ->type_name("N")
      ->capture_default_str();
  cmd->add_option("--max-dump-bytes", opts->max_dump_bytes,
                  "refuse a --dump-tess larger than this (default: the free space where it goes)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            std::uint64_t n = 0;
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, n);
            return ec == std::errc() && ptr == end && n >= 1 ? std::string()
                                                              : "expected a number of bytes >= 1, got '" + text + "'";
          },
          ""))
      ->type_name("BYTES");
  cmd->add_flag("--check", opts->check,
                 "test every stage's outputs for NaN and infinity; the first one stops the render "
                 "(exit 1, nothing written) naming the stage, invocation, value and source line");
  cmd->add_option("--check-range", opts->check_ranges,
                  "with --check (implied): values of NAME outside [LO, HI] are offences too; NAME: "
                  "gl_Position[.c], an evaluation shader output[.c], length(NAME), levels, "
                  "gl_TessLevelOuter[i], gl_TessLevelInner[i] (docs/check.md); repeatable")
      ->type_name("NAME=LO,HI")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--depth", opts->depth, "also write window-space depth (.exr)");
  cmd->add_option("--dump-fragments", opts->dump_fragments,
                  "also write each pixel's winning fragment (world P, N, patch_id, triangle, tess_coord, depth) "
                  "as one multi-channel .exr");
  cmd->add_option("--normals", opts->normals, "also write world normals (.exr)");
  cmd->add_option("--draw-buffer", opts->draw_buffers,
                  "also write draw buffer K (fragment output location K, 1..7; 0 is -o) as a colour image; "
                  "repeatable")
      ->type_name("K=FILE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--transform-feedback", opts->transform_feedback,
                  "also write what each draw's transform feedback records (draws[].transform_feedback) to "
                  "PREFIX.drawD.bufferB.bin, one file per buffer, as GL would fill the buffer")
      ->type_name("PREFIX");
  cmd->add_option("--storage-buffers", opts->storage_buffers,
                  "also write every buffer a draw binds to a shader storage block, as the draws left it, to "
                  "PREFIX.NAME.bin (NAME: the buffer's name in the scene)")
      ->type_name("PREFIX");
  cmd->add_option("--images", opts->images,
                  "also write level 0 of every texture a draw binds to an image uniform, as the draws left it, "
                  "to PREFIX.NAME.bin (NAME: the uniform's; drawD.NAME for a draw's own shaders; the texels' "
                  "bytes in their internal format, rows from the bottom)")
      ->type_name("PREFIX");
  cmd->add_option("--dump-tess", opts->dump_tess,
                  "also write every tessellated vertex (patch id, gl_TessCoord, position, normal): "
                  "binary, or text for *.txt (format: io/tess_dump.h)");
  // Generated when help is asked for: the formats from OpenImageIO, the keys from the loader.
  cmd->footer([] {
    return "\nImage formats this build writes (-o): " + writable_image_extensions(ImageKind::Color) +
           "\n  depth (--depth): " + writable_image_extensions(ImageKind::Depth) +
           "\n  normals (--normals): " + writable_image_extensions(ImageKind::Normals) +
           "\n\nScene keys (--set KEY=VALUE; `tessref scene SCENE` prints a scene as read):\n" + scene_keys_text();
  });
  cmd->callback([opts, repeat] {
    opts->report_repeat = repeat->count() > 0;
    run_render(*opts);
  });
}

}  // namespace tessref::cli
