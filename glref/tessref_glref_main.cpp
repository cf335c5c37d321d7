// tessref-glref: runs the GL tessellation pipeline on a real driver (llvmpipe through EGL
// surfaceless, or an EGL device) and prints what it produced, in tessref's own formats.

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/error.h"
#include "glref/gl_context.h"
#include "common/malloc_tuning.h"
#include "glref/gl_error.h"
#include "glref/levels_file.h"
#include "glref/tess_capture.h"
#include "glref/tpg_output.h"

namespace {

using namespace tessref;
using namespace tessref::glref;

struct LayoutArgs {
  std::string domain = "triangles", spacing = "equal", winding = "ccw";
  bool point_mode = false;

  void add_to(CLI::App* cmd) {
    cmd->add_option("--domain", domain, "triangles | quads | isolines")->capture_default_str();
    cmd->add_option("--spacing", spacing, "equal | fractional_odd | fractional_even")->capture_default_str();
    cmd->add_option("--winding", winding, "ccw | cw")->capture_default_str();
    cmd->add_flag("--point-mode", point_mode, "TES layout point_mode");
  }
  TessLayout layout() const {
    TessLayout l;
    if (!parse(domain, l.domain)) throw InputError("--domain: unknown domain '" + domain + "'");
    if (!parse(spacing, l.spacing)) throw InputError("--spacing: unknown spacing '" + spacing + "'");
    if (!parse(winding, l.winding)) throw InputError("--winding: unknown winding '" + winding + "'");
    l.point_mode = point_mode;
    return l;
  }
};

// "A,B,C" -> floats (nan, inf, -inf allowed) into dst; unspecified entries keep their value.
template <std::size_t N>
void parse_list(const std::string& option, const std::string& text, std::size_t min_count,
                std::array<float, N>& dst) {
  std::vector<std::string> tokens;
  std::size_t pos = 0;
  while (true) {
    const std::size_t comma = text.find(',', pos);
    tokens.push_back(text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos));
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  if (tokens.size() < min_count || tokens.size() > N)
    throw InputError(option + ": expected " + std::to_string(min_count) + " to " + std::to_string(N) +
                     " comma-separated levels, got '" + text + "'");
  for (std::size_t i = 0; i < tokens.size(); ++i)
    if (!parse_level(tokens[i], dst[i])) throw InputError(option + ": not a number: '" + tokens[i] + "'");
}

void write_all(const std::string& s) {
  if (!s.empty() && std::fwrite(s.data(), 1, s.size(), stdout) != s.size())
    throw std::runtime_error("writing to stdout failed");
}

}  // namespace

int main(int argc, char** argv) {
  tessref::keep_draw_buffers_off_mmap();
  CLI::App app{"tessref-glref: the real-GL reference runner (EGL + OpenGL 4.5 core)"};
  app.require_subcommand(1);
  std::string platform_name = "auto";
  int device_index = -1;
  app.add_option("--platform", platform_name,
                 "EGL platform: auto | surfaceless | device (default: $TESSREF_EGL_PLATFORM or auto)");
  app.add_option("--device", device_index, "EGL device index for --platform device (default: first hardware)");

  auto make_context = [&] {
    GlContextOptions o;
    if (!parse(platform_name, o.platform)) throw InputError("--platform: unknown platform '" + platform_name + "'");
    o.device_index = device_index;
    return std::make_unique<GlContext>(o);
  };

  // info
  CLI::App* info = app.add_subcommand("info", "print the GL renderer and version");
  info->callback([&] {
    auto ctx = make_context();
    std::printf("renderer: %s\nversion: %s\nvendor: %s\negl_vendor: %s\negl_platform: %s\n"
                "max_tess_gen_level: %d\n",
                ctx->renderer().c_str(), ctx->version().c_str(), ctx->vendor().c_str(),
                ctx->egl_vendor().c_str(), to_string(ctx->platform()), ctx->max_tess_gen_level());
  });

  // tpg: one patch
  CLI::App* tpg = app.add_subcommand("tpg", "print the tessellated vertices of one patch, in emission order");
  LayoutArgs tpg_layout;
  tpg_layout.add_to(tpg);
  std::string outer_text, inner_text = "1", format_text = "text";
  tpg->add_option("--outer", outer_text, "outer levels A,B[,C[,D]] (nan, inf allowed; unset = 1)")->required();
  tpg->add_option("--inner", inner_text, "inner levels X[,Y] (unset = 1)")->capture_default_str();
  tpg->add_option("--format", format_text, "text (%.9g) | hex (IEEE-754 bits)")->capture_default_str();
  tpg->callback([&] {
    const TessLayout layout = tpg_layout.layout();
    TessLevels levels;
    parse_list("--outer", outer_text, 2, levels.outer);
    parse_list("--inner", inner_text, 1, levels.inner);
    CoordFormat format;
    if (!parse(format_text, format)) throw InputError("--format: expected text or hex, got '" + format_text + "'");
    auto ctx = make_context();
    const auto coords = capture_tess_coords(*ctx, layout, {levels});
    write_all(format_stream(layout.domain, coords[0], format));
  });

  // tpg-sweep: many patches, the dataset format
  CLI::App* sweep = app.add_subcommand(
      "tpg-sweep", "capture one patch per line of a levels file; print per patch: index, vertex count, hex coords");
  LayoutArgs sweep_layout;
  sweep_layout.add_to(sweep);
  std::string levels_path;
  std::size_t batch = 1024;
  bool show_stats = false;
  sweep->add_option("--levels", levels_path,
                    "file with 'outer0 outer1 outer2 outer3 inner0 inner1' per line ('-' = stdin)")->required();
  sweep->add_option("--batch", batch, "patches per capture call (memory bound)")->capture_default_str();
  sweep->add_flag("--stats", show_stats, "print draws, vertices and level sets per second to stderr");
  sweep->callback([&] {
    const TessLayout layout = sweep_layout.layout();
    const std::vector<TessLevels> all = read_levels_file(levels_path);
    if (batch == 0) throw InputError("--batch must be positive");
    auto ctx = make_context();
    TessCapture capture(*ctx);
    std::size_t draws = 0, vertices = 0;
    double seconds = 0.0;
    for (std::size_t start = 0; start < all.size(); start += batch) {
      const std::size_t end = std::min(all.size(), start + batch);
      const std::vector<TessLevels> chunk(all.begin() + start, all.begin() + end);
      const auto coords = capture.capture(layout, chunk);
      draws += capture.last_stats().draws;
      vertices += capture.last_stats().vertices;
      seconds += capture.last_stats().seconds;
      std::string out;  // flushed every ~1 MB: a level-64 batch formats to gigabytes
      for (std::size_t i = 0; i < coords.size(); ++i) {
        append_sweep_line(out, layout.domain, start + i, coords[i]);
        if (out.size() > (1u << 20)) write_all(out), out.clear();
      }
      write_all(out);
    }
    if (show_stats)
      std::fprintf(stderr, "%zu level sets, %zu draws, %zu vertices, %.3f s capture, %.0f level sets/s (%s)\n",
                   all.size(), draws, vertices, seconds, seconds > 0 ? all.size() / seconds : 0.0,
                   ctx->renderer().c_str());
  });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const InputError& e) {
    std::fprintf(stderr, "tessref-glref: error: %s\n", e.what());
    return 2;
  } catch (const GlError& e) {
    std::fprintf(stderr, "tessref-glref: GL error: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessref-glref: internal error: %s\n", e.what());
    return 3;
  }
  std::fflush(stdout);
  return std::ferror(stdout) ? 1 : 0;
}
