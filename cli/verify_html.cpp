#include "cli/verify_html.h"

#include <algorithm>
#include <map>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <fstream>
#include <iterator>

#include "cli/scene_name.h"
#include "common/error.h"
#include "io/output_files.h"

namespace tessref::cli {
namespace {

using nlohmann::json;

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = 0;
    for (std::size_t k2 = 0; k2 < 3; ++k2) v = v << 8 | (k2 < n ? std::uint8_t(bytes[i + k2]) : 0u);
    for (std::size_t k2 = 0; k2 < 4; ++k2) out += k2 <= n ? k[(v >> (18 - 6 * k2)) & 63] : '=';
  }
  return out;
}

// A scalar as a person reads it: doubles to 4 significant digits, the rest as JSON says.
std::string scalar(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v.get<double>());
    return buf;
  }
  if (v.is_null()) return "-";
  if (v.is_array()) {
    std::string s;
    for (const json& e : v) s += (s.empty() ? "" : ", ") + scalar(e);
    return "[" + s + "]";
  }
  return v.dump();
}

std::string text(const json& report, const char* key, const std::string& fallback = "") {
  return report.contains(key) ? scalar(report[key]) : fallback;
}

bool passed(const json& report) { return report.contains("pass") && report["pass"].is_boolean() && report["pass"]; }

double severity(const json& report) {
  return report.contains("severity") && report["severity"].is_number() ? report["severity"].get<double>() : 0.0;
}

const char* kCss = R"(<style>
body { font-family: sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.4em; } h2 { font-size: 1.15em; margin-top: 1.4em; }
.pass { color: #fff; background: #2a7d2a; padding: 0.1em 0.5em; border-radius: 3px; }
.fail { color: #fff; background: #b22222; padding: 0.1em 0.5em; border-radius: 3px; }
.images { display: flex; flex-wrap: wrap; gap: 12px; }
figure { margin: 0; } figcaption { font-size: 0.9em; color: #555; }
figure img { width: 290px; image-rendering: pixelated; border: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.4em 0; font-size: 0.9em; }
td, th { border: 1px solid #ccc; padding: 0.2em 0.6em; text-align: left; }
th { background: #f0f0f0; } td.num { text-align: right; font-family: monospace; max-width: 36em; }
td.nowrap { white-space: nowrap; }
.zoom { width: 256px; height: 256px; overflow: hidden; position: relative; border: 1px solid #ccc; }
.zoom img { position: absolute; max-width: none; border: none; image-rendering: pixelated; }
.zoom .mark { position: absolute; width: 8px; height: 8px; outline: 2px solid #00e5ff; }
code { background: #f4f4f4; padding: 0 0.2em; }
.tables { display: flex; flex-wrap: wrap; gap: 24px; align-items: flex-start; }
</style>
)";

std::string page(const std::string& title, const std::string& body) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(title) +
         "</title>\n" + kCss + "</head>\n<body>\n" + body + "</body>\n</html>\n";
}

std::string verdict(const json& report) {
  return passed(report) ? "<span class=\"pass\">PASS</span>" : "<span class=\"fail\">FAIL</span>";
}

std::string image(const std::filesystem::path& file, const std::string& caption) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes(std::istreambuf_iterator<char>(in), {});
  const std::string img = bytes.empty() ? "<p>(" + escape(file.string()) + " is missing)</p>"
                                        : "<img alt=\"" + escape(caption) + "\" src=\"data:image/png;base64," +
                                              base64(bytes) + "\">";
  return "<figure>" + img + "<figcaption>" + escape(caption) + "</figcaption></figure>\n";
}

// The 32 x 32 pixels around (cx, cy) of a width x height image, 8 times larger, with the pixel
// itself outlined: ten mismatching pixels are invisible in a thumbnail of a 1024-pixel image.
// The page's own copy of the image is shifted inside a clipping box (no second image file).
std::string zoomed(const std::filesystem::path& file, const std::string& caption, int cx, int cy, int width,
                   int height) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes(std::istreambuf_iterator<char>(in), {});
  if (bytes.empty()) return "";
  constexpr int kSide = 32, kScale = 8;
  const int x0 = std::clamp(cx - kSide / 2, 0, std::max(0, width - kSide));
  const int y0 = std::clamp(cy - kSide / 2, 0, std::max(0, height - kSide));
  const auto px = [](int v) { return std::to_string(v) + "px"; };
  return "<figure><div class=\"zoom\"><img alt=\"" + escape(caption) + "\" src=\"data:image/png;base64," + base64(bytes) +
         "\" style=\"width: " + px(width * kScale) + "; height: " + px(height * kScale) + "; left: " + px(-x0 * kScale) +
         "; top: " + px(-y0 * kScale) + "\"><div class=\"mark\" style=\"left: " + px((cx - x0) * kScale) +
         "; top: " + px((cy - y0) * kScale) + "\"></div></div><figcaption>" + escape(caption) + "</figcaption></figure>\n";
}

// A histogram's buckets ("0", "1", "3-4", "129-256": JSON sorts them as text) in numeric order,
// on one line.
bool is_histogram(const json& j) {
  if (!j.is_object() || j.empty()) return false;
  for (const auto& [key, value] : j.items())
    if (key.empty() || key.find_first_of("0123456789") > 1 || !value.is_number()) return false;
  return true;
}

std::string histogram(const json& j) {
  std::vector<std::pair<double, std::string>> buckets;
  for (const auto& [key, value] : j.items()) {
    const double low = std::atof(key.c_str() + key.find_first_of("0123456789"));
    buckets.push_back({low + (key[0] == '>' ? 0.5 : 0.0), key + ": " + scalar(value)});  // ">2048" after "1025-2048"
  }
  std::sort(buckets.begin(), buckets.end());
  std::string out;
  for (const auto& b : buckets) out += (out.empty() ? "" : ", ") + b.second;
  return out;
}

// What a report key means, for people (the key itself stays in the cell's tooltip). Keys not
// listed are shown with spaces for underscores.
std::string label(const std::string& key) {
  static const std::map<std::string, std::string> kLabels = {
      {"emitted_vertices", "vertices emitted"},
      {"first_mismatched_patch", "first patch whose gl_TessCoord differ"},
      {"patches_mismatched", "patches whose gl_TessCoord differ"},
      {"max_position_ulp", "largest position difference (ULPs)"},
      {"max_normal_ulp", "largest normal difference (ULPs)"},
      {"position_ulps", "position differences (ULPs: count)"},
      {"normal_ulps", "normal differences (ULPs: count)"},
      {"max_position_difference_of_diagonal", "largest position difference / diagonal"},
      {"worst_position_patch", "patch with the largest position difference"},
      {"records_compared", "vertices compared"},
      {"unmatched_vertices", "vertices without a twin"},
      {"patch_stride", "patches sampled: every"},
      {"hausdorff_of_diagonal", "Hausdorff distance / diagonal"},
      {"beyond_limit", "mismatches beyond the limit"},
      {"by_distance_px", "mismatches by distance to the silhouette (px: count)"},
      {"covered_rays", "pixels tessref's surface covers (rays)"},
      {"covered_reference", "pixels the driver covered"},
      {"covered_tessref", "pixels tessref's rasterizer covered"},
      {"max_distance_px", "farthest mismatch from the silhouette (px)"},
      {"mismatched_by_distance", "mismatches by 4-neighbour steps to the silhouette"},
      {"off_silhouette", "mismatches off the silhouette"},
      {"cracked_edges", "cracked shared edges"},
      {"max_gap_of_diagonal", "widest gap / diagonal"},
      {"rays_through", "rays through a crack"},
      {"max_difference_255", "largest channel difference (of 255)"},
      {"psnr_db", "PSNR (dB)"},
      {"within_1_255", "pixels within 1/255"},
      {"within_2_255", "pixels within 2/255"},
      {"color_share_percent", "required share within 2/255 (%)"},
      {"cracks_fail", "cracks fail"},
      {"max_distance_of_diagonal", "largest surface distance allowed / diagonal"},
      {"silhouette_px", "largest silhouette distance allowed (px)"},
  };
  const std::string last = key.substr(key.rfind('.') + 1);
  const auto it = kLabels.find(last);
  std::string prefix = key.substr(0, key.size() - last.size()), text = it != kLabels.end() ? it->second : last;
  if (it == kLabels.end()) std::replace(text.begin(), text.end(), '_', ' ');
  std::replace(prefix.begin(), prefix.end(), '_', ' ');
  std::replace(prefix.begin(), prefix.end(), '.', ':');
  return prefix.empty() ? text : prefix + " " + text;
}

// A value as the row shows it: "none" for the report's "no such thing" (-1 for a patch, an empty list).
std::string shown(const std::string& key, const json& value) {
  if ((value.is_array() && value.empty()) || (value.is_number_integer() && value.get<long long>() == -1 && key.ends_with("patch")))
    return "none";
  return scalar(value);
}

std::string row(const std::string& key, const std::string& value) {
  return "<tr><td title=\"" + escape(key) + "\">" + escape(label(key)) + "</td><td class=\"num\">" + escape(value) +
         "</td></tr>\n";
}

// Every scalar of a section, nested objects flattened to dotted keys; lists of records (the worst
// patches, pixels, edges) have their own tables.
void rows(const json& j, const std::string& prefix, std::string& out) {
  for (const auto& [key, value] : j.items()) {
    const std::string name = prefix + key;
    if (is_histogram(value)) {
      out += row(name, histogram(value));
    } else if (value.is_object()) {
      rows(value, name + ".", out);
    } else if (value.is_array() && !value.empty() && (value[0].is_object() || value[0].is_array())) {
      continue;
    } else {
      out += row(name, shown(name, value));
    }
  }
}

std::string figures(const json& report) {
  static const char* kSections[] = {"tessellation", "surface_distance", "silhouette", "coverage",
                                    "cracks",       "color",            "limits"};
  std::string out = "<h2>Figures</h2>\n<div class=\"tables\">\n";
  for (const char* s : kSections) {
    if (!report.contains(s) || !report[s].is_object()) continue;
    out += "<table><tr><th colspan=\"2\">" + std::string(s) + "</th></tr>\n";
    rows(report[s], "", out);
    out += "</table>\n";
  }
  return out + "</div>\n";
}

// The --set overrides the run was given (the report keeps them).
std::vector<std::string> sets_of(const json& report) {
  std::vector<std::string> sets;
  if (report.contains("sets") && report["sets"].is_array())
    for (const json& set : report["sets"])
      if (set.is_string()) sets.push_back(set.get<std::string>());
  return sets;
}

std::string worst_patches(const json& report) {
  if (!report.contains("surface_distance") || !report["surface_distance"].contains("worst_patches")) return "";
  const json& list = report["surface_distance"]["worst_patches"];
  if (!list.is_array() || list.empty()) return "";
  // The built-in default scene is reported as "<default scene>": the command then takes no SCENE.
  // The run's --set overrides go with it, or the command would inspect another scene.
  std::string file = text(report, "scene", "SCENE");
  if (!file.empty() && file[0] == '<') file.clear();
  const std::string scene = scene_arguments(file, sets_of(report));
  std::string out = "<h2>Worst patches (surface distance)</h2>\n<table><tr><th>patch</th><th>distance / diagonal</th>"
                    "<th>look at it</th></tr>\n";
  for (const json& p : list) {
    const std::string id = p.contains("patch") ? scalar(p["patch"]) : "?";
    out += "<tr><td class=\"num\">" + escape(id) + "</td><td class=\"num\">" +
           escape(p.contains("distance_of_diagonal") ? scalar(p["distance_of_diagonal"]) : "-") +
           "</td><td><code>tessref inspect " + escape(scene) + "--patch " + escape(id) + "</code></td></tr>\n";
  }
  return out + "</table>\n";
}

std::string worst_pixels(const json& report) {
  if (!report.contains("silhouette") || !report["silhouette"].contains("worst_pixels")) return "";
  const json& list = report["silhouette"]["worst_pixels"];
  if (!list.is_array()) return "";
  if (list.empty()) return "<h2>Worst pixels</h2>\n<p>None: every pixel's coverage agrees.</p>\n";
  std::string out = "<h2>Worst pixels (coverage mismatches farthest from the silhouette)</h2>\n"
                    "<table><tr><th>x</th><th>y</th><th>distance (px)</th></tr>\n";
  for (const json& p : list) {
    out += "<tr>";
    for (std::size_t k = 0; k < 3; ++k)
      out += "<td class=\"num\">" + escape(p.is_array() && k < p.size() ? scalar(p[k]) : "-") + "</td>";
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

std::string worst_cracks(const json& report) {
  if (!report.contains("cracks") || !report["cracks"].contains("worst")) return "";
  const json& list = report["cracks"]["worst"];
  if (!list.is_array() || list.empty()) return "";
  std::string out = "<h2>Widest cracks</h2>\n<table><tr><th>patches</th><th>from</th><th>to</th>"
                    "<th>gap / diagonal</th><th>rays through</th></tr>\n";
  for (const json& c : list) {
    out += "<tr>";
    for (const char* k : {"patches", "from", "to", "gap_of_diagonal", "rays_through"})
      out += "<td class=\"num\">" + escape(c.contains(k) ? scalar(c[k]) : "-") + "</td>";
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

std::string list_section(const json& report, const char* key, const char* title) {
  if (!report.contains(key) || !report[key].is_array() || report[key].empty()) return "";
  std::string out = std::string("<h2>") + title + "</h2>\n<ul>\n";
  for (const json& f : report[key]) out += "<li>" + escape(scalar(f)) + "</li>\n";
  return out + "</ul>\n";
}

}  // namespace

VerifyImages verify_images_in(const std::filesystem::path& folder) {
  VerifyImages out;
  for (int k = 0; k < 4; ++k) out[k] = folder / kVerifyImageFiles[k];
  return out;
}

std::string verify_scene_page(const json& report, const VerifyImages& images, const std::string& index_href) {
  const std::string scene = scene_label(text(report, "scene", "(scene)"), sets_of(report));  // as render names it
  std::string body;
  if (!index_href.empty()) body += "<p><a href=\"" + escape(index_href) + "\">&larr; all scenes</a></p>\n";
  char sev[32];
  std::snprintf(sev, sizeof sev, "%.3g", severity(report));
  body += "<h1>" + escape(scene) + ": " + verdict(report) + "</h1>\n<p>against <code>" +
          escape(text(report, "reference")) + "</code> (" + escape(text(report, "driver")) + " " +
          escape(text(report, "driver_version")) + "), " + escape(text(report, "width")) + " x " +
          escape(text(report, "height")) + " pixels; severity <b>" + sev +
          "</b> (the largest measured / limit; above 1 fails)</p>\n";
  body += list_section(report, "failures", "Failures");
  body += list_section(report, "warnings", "Warnings");
  body += "<div class=\"images\">\n" + image(images[1], "driver (reference)") + image(images[0], "tessref") +
          image(images[2], "difference (x8)") +
          image(images[3], "silhouette heat map (yellow: within the limit, red: beyond)") +
          "</div>\n";
  // The worst coverage mismatch, up close.
  const json* worst = report.contains("silhouette") && report["silhouette"].contains("worst_pixels")
                          ? &report["silhouette"]["worst_pixels"] : nullptr;
  if (worst && worst->is_array() && !worst->empty() && (*worst)[0].is_array() && (*worst)[0].size() >= 2 &&
      report.contains("width") && report.contains("height") && report["width"].is_number_integer() &&
      report["height"].is_number_integer()) {
    const int x = (*worst)[0][0].get<int>(), y = (*worst)[0][1].get<int>();
    const int w = report["width"].get<int>(), h = report["height"].get<int>();
    const std::string at = " at pixel " + std::to_string(x) + "," + std::to_string(y);
    body += "<h2>The worst coverage mismatch, 8 times larger (" + std::to_string(x) + ", " + std::to_string(y) +
            ": x from the left, y down)</h2>\n<div class=\"images\">\n" +
            zoomed(images[1], "driver (reference)" + at, x, y, w, h) + zoomed(images[0], "tessref" + at, x, y, w, h) +
            zoomed(images[2], "difference (x8)" + at, x, y, w, h) + "</div>\n";
  }
  body += figures(report) + worst_patches(report) + worst_pixels(report) + worst_cracks(report);
  return page("tessref verify: " + scene, body);
}

std::string verify_index_page(const std::vector<SiteScene>& scenes) {
  std::vector<const SiteScene*> order;
  for (const SiteScene& s : scenes) order.push_back(&s);
  std::stable_sort(order.begin(), order.end(), [](const SiteScene* a, const SiteScene* b) {
    if (severity(a->report) != severity(b->report)) return severity(a->report) > severity(b->report);
    return a->stem < b->stem;
  });
  std::size_t failed = 0;
  for (const SiteScene& s : scenes) failed += !passed(s.report);
  std::string body = "<h1>tessref verify: " + std::to_string(scenes.size()) + " scenes, " +
                     std::to_string(scenes.size() - failed) + " passed, " + std::to_string(failed) +
                     " failed</h1>\n<p>Sorted by severity (the largest measured / limit; above 1 fails), worst "
                     "first.</p>\n<table><tr><th>scene</th><th>verdict</th><th>severity</th><th>driver</th>"
                     "<th>size</th><th>first failure</th></tr>\n";
  for (const SiteScene* s : order) {
    char sev[32];
    std::snprintf(sev, sizeof sev, "%.3g", severity(s->report));
    const json& f = s->report.contains("failures") ? s->report["failures"] : json::array();
    body += "<tr><td><a href=\"" + escape(s->stem) + ".html\">" + escape(s->stem) + "</a></td><td>" +
            verdict(s->report) + "</td><td class=\"num\">" + sev + "</td><td class=\"nowrap\">" + escape(text(s->report, "driver")) +
            "</td><td class=\"num nowrap\">" + escape(text(s->report, "width")) + " x " + escape(text(s->report, "height")) +
            "</td><td>" + escape(f.is_array() && !f.empty() ? scalar(f[0]) : "") + "</td></tr>\n";
  }
  return page("tessref verify campaign", body + "</table>\n");
}

void write_verify_site(const std::filesystem::path& site_folder, const std::vector<SiteScene>& scenes) {
  CreatedFolder folder(site_folder, "the --html folder");  // removed again on failure
  OutputFiles outputs;
  const auto write = [&](const std::filesystem::path& target, const std::string& html) {
    write_text_file(outputs.add("--html", target), target.string(), html);
  };
  write(site_folder / "index.html", verify_index_page(scenes));
  for (const SiteScene& s : scenes) {
    if (s.stem == "index") throw InputError("a scene named 'index' would overwrite the --html index page; rename it");
    write(site_folder / (s.stem + ".html"), verify_scene_page(s.report, verify_images_in(s.image_folder), "index.html"));
  }
  outputs.commit();
  folder.keep();
}

}  // namespace tessref::cli
