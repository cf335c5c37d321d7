// `tessref diff A B`: two images compared with the project's figures (pixels above 1/255 and the
// tolerance, largest difference and where, mean, RMS, PSNR), by OpenImageIO's ImageBufAlgo, with
// an optional difference image. Exit 0 when no pixel differs by more than the tolerance, 1 when
// one does, 2 when an image cannot be read or the sizes differ.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "common/error.h"
#include "io/image_output.h"
#include "io/output_files.h"

namespace tessref::cli {
namespace {

struct DiffArgs {
  std::string a, b, diff_image, tolerance = "0", scale = "16";
  bool json = false;
};

// "2/255" or a plain number, in the images' units (8-bit files read as 0..1).
double parse_tolerance(const std::string& text) {
  try {
    std::size_t used = 0;
    const std::size_t slash = text.find('/');
    double value = std::stod(text.substr(0, slash), &used);
    if (used != text.substr(0, slash).size()) throw std::invalid_argument(text);
    if (slash != std::string::npos) {
      const double denominator = std::stod(text.substr(slash + 1), &used);
      if (used != text.size() - slash - 1 || !(denominator > 0)) throw std::invalid_argument(text);
      value /= denominator;
    }
    if (!(value >= 0) || value == HUGE_VAL) throw std::invalid_argument(text);
    return value;
  } catch (const std::logic_error&) {
    throw InputError("--tolerance: expected a number >= 0 or N/255, got '" + text + "'");
  }
}

// The difference image's gain: a finite number above 0 (NaN would write a black image, a
// negative one clamps every pixel to black, and CLI11's range check printed DBL_MAX in full).
double parse_scale(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(value) || !(value > 0)) throw std::invalid_argument(text);
    return value;
  } catch (const std::logic_error&) {
    throw InputError("--scale: expected a finite number greater than 0, got '" + text + "'");
  }
}

double percent(std::uint64_t n, const ImageFileDiff& d) {
  return 100.0 * double(n) / double(std::uint64_t(d.width) * std::uint64_t(d.height));
}

void run(const DiffArgs& o) {
  const double tolerance = parse_tolerance(o.tolerance);
  const double scale = parse_scale(o.scale);
  const double one_step = 1.0 / 255.0;
  OutputFiles outputs;
  std::filesystem::path diff_tmp;
  if (!o.diff_image.empty()) {
    diff_tmp = outputs.add("--diff", o.diff_image);
    check_image_path(o.diff_image, ImageKind::Color);
  }
  // Both thresholds are open: a difference of exactly 1/255 is not above 1/255. The half step
  // keeps 8-bit values, which reach here as k/255 in float, on the right side of the comparison.
  const ImageFileDiff d = diff_image_files(o.a, o.b, one_step * 1.5, tolerance == 0 ? 0 : tolerance + one_step * 0.5,
                                           diff_tmp, scale);
  outputs.commit();
  const bool within = d.above_fail == 0;
  if (o.json) {
    nlohmann::json j = {{"a", o.a}, {"b", o.b}, {"width", d.width}, {"height", d.height},
                        {"channels", d.channels}, {"tolerance", tolerance}, {"within_tolerance", within},
                        {"pixels_above_tolerance", d.above_fail}, {"pixels_above_1_255", d.above_warn},
                        {"max_difference", d.max_error}, {"max_at", {d.max_x, d.max_y, d.max_channel}},
                        {"mean_difference", d.mean_error}, {"rms_difference", d.rms_error},
                        {"psnr_db", d.psnr}};
    if (!o.diff_image.empty()) j["diff_image"] = o.diff_image;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("tessref diff: %s vs %s (%dx%d, %d channels): %llu pixels (%.4g%%) differ by more than the "
                "tolerance %s, %llu (%.4g%%) by more than 1/255; largest difference %.6g (%.1f/255) at (%d, %d) "
                "channel %d; mean %.3g, RMS %.3g, PSNR %.2f dB%s%s\n",
                o.a.c_str(), o.b.c_str(), d.width, d.height, d.channels,
                static_cast<unsigned long long>(d.above_fail), percent(d.above_fail, d), o.tolerance.c_str(),
                static_cast<unsigned long long>(d.above_warn), percent(d.above_warn, d), d.max_error,
                d.max_error * 255.0, d.max_x, d.max_y, d.max_channel, d.mean_error, d.rms_error, d.psnr,
                o.diff_image.empty() ? "" : "; difference image ", o.diff_image.c_str());
  }
  if (!within) set_exit_code(1);
}

}  // namespace

void add_diff_command(CLI::App& app) {
  auto args = std::make_shared<DiffArgs>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare two images (any format OpenImageIO reads): exit 0 when every pixel is within the "
              "tolerance, 1 when not, 2 when they cannot be compared");
  cmd->add_option("a", args->a, "first image")->required();
  cmd->add_option("b", args->b, "second image")->required();
  cmd->add_option("--tolerance", args->tolerance,
                  "largest channel difference allowed, a number or N/255 (8-bit files read as 0..1)")
      ->capture_default_str();
  cmd->add_option("--diff", args->diff_image, "write |a - b| * scale to this image");
  cmd->add_option("--scale", args->scale, "the difference image's gain, a finite number > 0")->capture_default_str();
  cmd->add_flag("--json", args->json, "print the figures as JSON");
  cmd->callback([args] { run(*args); });
}

}  // namespace tessref::cli
