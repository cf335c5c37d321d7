// `tessref tpg`: the primitive generator on one patch, printed as transform feedback would
// capture a TES that writes gl_TessCoord.
#include <charconv>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "common/error.h"
#include "stages/tpg.h"
#include "stages/tpg_stream.h"

namespace tessref::cli {
namespace {

struct TpgOptions {
  std::string domain = "triangles", spacing = "equal", winding = "ccw", format = "text";
  std::string profile = "llvmpipe";
  bool point_mode = false;
  std::vector<float> outer, inner;
  int max_level = 64;
};

void run_tpg(const TpgOptions& o) {
  TessLayout layout;
  if (!parse(o.domain, layout.domain))
    throw InputError("--domain: '" + o.domain + "' is not triangles, quads or isolines");
  if (!parse(o.spacing, layout.spacing))
    throw InputError("--spacing: '" + o.spacing +
                     "' is not equal, fractional_odd or fractional_even");
  if (!parse(o.winding, layout.winding))
    throw InputError("--winding: '" + o.winding + "' is not ccw or cw");
  layout.point_mode = o.point_mode;

  const std::size_t need_outer = layout.domain == TessDomain::Triangles ? 3
                                 : layout.domain == TessDomain::Quads   ? 4
                                                                        : 2;
  const std::size_t need_inner = layout.domain == TessDomain::Triangles ? 1
                                 : layout.domain == TessDomain::Quads   ? 2
                                                                        : 0;
  if (o.outer.size() != need_outer)
    throw InputError("--outer: " + std::string(to_string(layout.domain)) + " take " +
                     std::to_string(need_outer) + " outer levels, got " +
                     std::to_string(o.outer.size()));
  if (o.inner.size() != need_inner && !(need_inner == 0 && o.inner.empty()))
    throw InputError("--inner: " + std::string(to_string(layout.domain)) + " take " +
                     std::to_string(need_inner) + " inner levels, got " +
                     std::to_string(o.inner.size()));
  TessLevels levels;
  for (std::size_t i = 0; i < o.outer.size(); ++i) levels.outer[i] = o.outer[i];
  for (std::size_t i = 0; i < o.inner.size(); ++i) levels.inner[i] = o.inner[i];

  TessProfile profile;
  if (o.profile == "llvmpipe") profile = TessProfile::llvmpipe();
  else if (o.profile == "spec-literal") profile = TessProfile::spec_literal();
  else throw InputError("--profile: '" + o.profile + "' is not llvmpipe or spec-literal");
  profile.max_level = o.max_level;

  const TessDomainPoints points = generate_tessellation(layout, levels, profile);
  write_stream(std::cout, layout.domain, emitted_stream(points),
               o.format == "hex" ? StreamFormat::Hex : StreamFormat::Text);
}

// One level of a comma-separated list: a decimal number, nan or inf ("" between commas, or a word,
// is said to be one, not read as 0 or counted).
const CLI::Validator kLevel(
    [](std::string& s) -> std::string {
      float f = 0.0f;
      const char* end = s.data() + s.size();
      const auto [ptr, ec] = std::from_chars(s.data(), end, f);
      if (s.empty()) return "expected a level (a number, nan or inf), got an empty value";
      if ((ec != std::errc() && ec != std::errc::result_out_of_range) || ptr != end)
        return "expected a level (a number, nan or inf), got '" + s + "'";
      return {};
    },
    "LEVEL");

}  // namespace

void add_tpg_command(CLI::App& app) {
  auto opts = std::make_shared<TpgOptions>();
  CLI::App* cmd = app.add_subcommand(
      "tpg", "Run the tessellation primitive generator on one patch and print the gl_TessCoord "
             "stream a transform-feedback capture would see (nothing for a discarded patch)");
  cmd->add_option("--domain", opts->domain, "triangles | quads | isolines")->capture_default_str();
  cmd->add_option("--spacing", opts->spacing, "equal | fractional_odd | fractional_even")
      ->capture_default_str();
  cmd->add_option("--winding", opts->winding, "ccw | cw")->capture_default_str();
  cmd->add_flag("--point-mode", opts->point_mode, "layout(point_mode)");
  cmd->add_option("--outer", opts->outer, "outer levels A,B,C[,D] (nan, inf accepted)")
      ->delimiter(',')
      ->check(kLevel)
      ->required();
  cmd->add_option("--inner", opts->inner, "inner levels X[,Y]")->delimiter(',')->check(kLevel);
  cmd->add_option("--format", opts->format, "text (%.9g) | hex (IEEE-754 bits)")
      ->check(CLI::IsMember({"text", "hex"}))
      ->capture_default_str();
  cmd->add_option("--profile", opts->profile,
                  "implementation profile: llvmpipe | spec-literal")
      ->capture_default_str();
  cmd->add_option("--max-level", opts->max_level, "GL_MAX_TESS_GEN_LEVEL (2..64)")
      ->check(kInteger)
      ->check(CLI::Range(2, 64))
      ->capture_default_str();
  cmd->callback([opts] { run_tpg(*opts); });
}

}  // namespace tessref::cli
