// `tessref inspect`: one patch of the scene's draw, stage by stage (inspect/inspect.h), as text
// for a terminal or as JSON (--json FILE; structure in docs/inspect.md).
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "common/error.h"
#include "mesh/camera.h"
#include "inspect/inspect.h"
#include "inspect/inspect_fragments.h"
#include "inspect/inspect_pixel.h"
#include "mesh/mesh_source.h"
#include "scene/scene_loader.h"
#include "stages/schemes/pn_triangles.h"
#include "stages/schemes/quadratic_patch.h"

namespace tessref::cli {
namespace {

// An index option not given (any value the user types, -1 included, is checked as given).
constexpr long long kNotGiven = std::numeric_limits<long long>::min();

struct InspectArgs {
  std::string scene, coord, json, pixel;
  bool trace = false, no_fragments = false;
  std::string trace_stages = "all";
  int threads = 0;
  std::vector<std::string> sets;
  long long patch = kNotGiven, vertex = kNotGiven, draw = kNotGiven;
};

// %.9g: a float printed so that it reads back as the same bits.
std::string g9(float f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", double(f));
  return buf;
}
template <int N>
std::string vec(const glm::vec<N, float>& v) {
  std::string s = "(";
  for (int i = 0; i < N; ++i) s += (i ? ", " : "") + g9(v[i]);
  return s + ")";
}
// A draws scene's vertex input as its scalar type reads: floats, ints, uints or doubles.
std::vector<std::string> input_values(const InspectInput& in) {
  std::vector<std::string> out;
  const std::size_t step = in.scalar == shader::Scalar::F64 ? 2 : 1;
  for (std::size_t i = 0; i + step <= in.words.size(); i += step) {
    const std::uint32_t w = in.words[i];
    char buf[40];
    switch (in.scalar) {
      case shader::Scalar::I32: std::snprintf(buf, sizeof buf, "%d", int(std::int32_t(w))); break;
      case shader::Scalar::U32:
      case shader::Scalar::Bool: std::snprintf(buf, sizeof buf, "%u", w); break;
      case shader::Scalar::F64: {
        const std::uint64_t b = std::uint64_t(w) | std::uint64_t(in.words[i + 1]) << 32;
        double d;
        std::memcpy(&d, &b, sizeof d);
        std::snprintf(buf, sizeof buf, "%.17g", d);
        break;
      }
      default: {
        float f;
        std::memcpy(&f, &w, sizeof f);
        std::snprintf(buf, sizeof buf, "%.9g", double(f));
      }
    }
    out.push_back(buf);
  }
  return out;
}
const char* scalar_name(shader::Scalar s) {
  switch (s) {
    case shader::Scalar::I32: return "int";
    case shader::Scalar::U32: return "uint";
    case shader::Scalar::F64: return "double";
    case shader::Scalar::Bool: return "bool";
    default: return "float";
  }
}

// JSON numbers carry the %.9g decimal, so that any reader gets the float back by rounding.
nlohmann::json num(float f) { return std::strtod(g9(f).c_str(), nullptr); }
template <int N>
nlohmann::json jvec(const glm::vec<N, float>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < N; ++i) a.push_back(num(v[i]));
  return a;
}

// --coord U,V[,W]: two or three numbers (a missing W is completed by inspect_patch).
std::vector<float> parse_coord(const std::string& text) {
  std::vector<float> v;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t end = std::min(text.find(',', at), text.size());
    float f = 0.0f;
    const auto [ptr, ec] = std::from_chars(text.data() + at, text.data() + end, f);
    if (ec != std::errc() || ptr != text.data() + end || end == at)
      throw InputError("--coord: expected U,V[,W] (numbers, comma-separated), got '" + text + "'");
    v.push_back(f);
    at = end + 1;
  }
  if (v.size() != 2 && v.size() != 3)
    throw InputError("--coord: expected 2 or 3 components (U,V[,W]), got " + std::to_string(v.size()));
  return v;
}

// Slots up to the last one any of the vertices writes (at least one).
int used_slots(const StageVertex& v, int n = 1) {
  for (int s = 0; s < kMaxStageAttributes; ++s)
    if (v.attr[s] != glm::vec4(0.0f)) n = std::max(n, s + 1);
  return n;
}
int used_slots(const std::vector<InspectCorner>& corners) {
  int n = 1;
  for (const InspectCorner& c : corners) n = used_slots(c.vs_out, n);
  return n;
}
int used_slots(const PatchOutput& o) {
  int n = 1;
  for (int k = 0; k < o.vertex_count; ++k) n = used_slots(o.vertices[k], n);
  return n;
}
int used_patch_slots(const PatchOutput& o) {
  int n = 0;
  for (int s = 0; s < kMaxPatchAttributes; ++s)
    if (o.patch[s] != glm::vec4(0.0f)) n = s + 1;
  return n;
}

// Names of the slots: the built-in programs' (pn_triangles.h, tess_stage.h), else GLSL's I/O slots.
std::string vs_slot_name(const InspectResult& r, int s) {
  if (r.program.rfind("builtin", 0) == 0) return s == kAttrPosition ? "world position" : s == kAttrNormal ? "world normal" : "slot " + std::to_string(s);
  return s == 0 ? "gl_Position" : "location " + std::to_string(s - 1);
}
std::string tcs_slot_name(const InspectResult& r, int s) {
  if (r.builtin_quadratic) {
    switch (s) {
      case kAttrPosition: return "P_i (corner)";
      case kAttrNormal: return "N_i (unit normal)";
      case kQuadAttrEdgePoint: return "mid-edge control point b_(i,i+1)";
      case kQuadAttrMidNormal: return "mid-edge normal n_(i,i+1)";
    }
  }
  if (!r.builtin_pn) return vs_slot_name(r, s);
  switch (s) {
    case kAttrPosition: return "P_i (corner)";
    case kAttrNormal: return "N_i (unit normal)";
    case kPnAttrTangentNext: return "tangent coefficient to P_(i+1)";
    case kPnAttrTangentPrev: return "tangent coefficient to P_(i+2)";
    case kPnAttrMidNormal: return "mid-edge normal n_(i,i+1)";
  }
  return "slot " + std::to_string(s);
}
std::string patch_slot_name(const InspectResult& r, int s) {
  if (r.builtin_pn && s == kPnPatchCenter) return "b111 (centre)";
  if (r.builtin_pn && s == kPnPatchOrder) return "canonical corner order";
  if (r.builtin_quadratic && s == kQuadPatchOrder) return "canonical corner order";
  return "patch slot " + std::to_string(s);
}

int rings(const InspectResult& r) {
  if (r.layout.domain == TessDomain::Triangles) return (r.levels.inner_segments[0] + 1) / 2;
  if (r.layout.domain == TessDomain::Quads)
    return (std::min(r.levels.inner_segments[0], r.levels.inner_segments[1]) + 1) / 2;
  return 0;
}

void print_text(const Scene& scene, const InspectResult& r, const std::optional<PatchFragments>& frags, double seconds) {
  if (r.draw) {
    const InspectDrawPatch& d = *r.draw;
    std::printf("tessref inspect: %s, draws.%zu, patch %zu of %zu (0..%zu): call %zu, gl_InstanceID %d, gl_PrimitiveID "
                "%zu; patch id %u in --dump-tess and capture files; programs: %s\n\n",
                scene.source.c_str(), d.draw, r.patch, r.patch_count, r.patch_count - 1, d.call, d.instance,
                d.primitive_id, d.patch_id, r.program.c_str());
  } else {
    std::printf("tessref inspect: %s, patch %zu of %zu (0..%zu); programs: %s\n\n", scene.source.c_str(), r.patch,
                r.patch_count, r.patch_count - 1, r.program.c_str());
  }
  const bool builtin = r.program.rfind("builtin", 0) == 0;
  std::printf("1. Vertex shader: the patch's %d corners (gl_in[] of the control shader)\n", r.patch_vertices);
  const int vs_slots = used_slots(r.corners);
  for (std::size_t k = 0; k < r.corners.size(); ++k) {
    const InspectCorner& c = r.corners[k];
    if (r.draw) {
      std::printf("  gl_in[%zu] = gl_VertexID %u\n", k, c.vertex);
      for (const InspectInput& in : c.inputs) {
        std::string v;
        for (const std::string& x : input_values(in)) v += (v.empty() ? "" : ", ") + x;
        std::printf("      in location %u (%s) (%s)\n", in.location, scalar_name(in.scalar), v.c_str());
      }
    } else {
      std::printf("  gl_in[%zu] = mesh vertex %u: in position %s, in normal %s\n", k, c.vertex,
                  vec(c.in_position).c_str(), vec(c.in_normal).c_str());
    }
    if (c.gl_position) std::printf("      gl_Position %s\n", vec(*c.gl_position).c_str());
    for (int s = 0; s < vs_slots; ++s)
      std::printf("      %s %s\n", vs_slot_name(r, s).c_str(), vec(c.vs_out.attr[s]).c_str());
  }

  std::printf("\n2. Tessellation control: %d invocations, %d phase%s\n", r.tcs_vertices, r.tcs_phases,
              r.tcs_phases == 1 ? "" : "s");
  const int tcs_slots = used_slots(r.tcs_out);
  for (int k = 0; k < r.tcs_out.vertex_count; ++k)
    for (int s = 0; s < tcs_slots; ++s)
      std::printf("  gl_out[%d] %-32s %s\n", k, tcs_slot_name(r, s).c_str(), vec(r.tcs_out.vertices[k].attr[s]).c_str());
  for (int s = 0; s < used_patch_slots(r.tcs_out); ++s)
    std::printf("  patch out %-30s %s\n", patch_slot_name(r, s).c_str(), vec(r.tcs_out.patch[s]).c_str());
  const TessLevels& lv = r.tcs_out.levels;
  std::printf("  gl_TessLevelOuter %s, gl_TessLevelInner (%s, %s)\n",
              vec(glm::vec4(lv.outer[0], lv.outer[1], lv.outer[2], lv.outer[3])).c_str(), g9(lv.inner[0]).c_str(),
              g9(lv.inner[1]).c_str());

  std::printf("\n3. Primitive generator: %s, %s, %s%s; %s\n", to_string(r.layout.domain), to_string(r.layout.spacing),
              to_string(r.layout.winding), r.layout.point_mode ? ", point_mode" : "",
              r.tessellator == Tessellator::Uniform ? "uniform subdivision (levels below are the GL generator's reading)"
              : r.tessellator == Tessellator::RefinementPattern
                  ? "refinement pattern (levels below are the GL generator's reading)"
                  : "profile llvmpipe");
  const ProcessedTessLevels& p = r.levels;
  if (p.discarded) {
    std::printf("  discarded: a relevant outer level is <= 0 or NaN\n");
  } else {
    for (int e = 0; e < p.outer_count; ++e)
      std::printf("  outer[%d] %s -> clamped %s -> %d %s\n", e, g9(lv.outer[e]).c_str(), g9(p.outer[e]).c_str(),
                  p.outer_segments[e],
                  r.layout.domain == TessDomain::Isolines && e == 0 ? "lines" : "segments");
    for (int a = 0; a < p.inner_count; ++a)
      std::printf("  inner[%d] %s -> clamped %s -> %d segments\n", a, g9(lv.inner[a]).c_str(), g9(p.inner[a]).c_str(),
                  p.inner_segments[a]);
    if (p.inner_count) std::printf("  %d rings (the outer one included)\n", rings(r));
  }
  std::printf("  %zu domain points, %zu %s\n", r.domain_points, r.primitives,
              r.vertices_per_primitive == 3 ? "triangles" : r.vertices_per_primitive == 2 ? "line segments" : "points");

  std::printf("\n4. Tessellation evaluation: %d varyings; world position = varyings[%d..], normal = varyings[%d..]\n",
              r.num_varyings, r.dump_varyings[0], r.dump_varyings[1]);
  if (r.points.empty()) std::printf("  no points: the generator discarded the patch\n");
  for (const InspectPoint& pt : r.points) {
    std::printf("  %s gl_TessCoord %s\n",
                pt.index ? ("point " + std::to_string(*pt.index) + ":").c_str() : "coordinate (not a generated point):",
                vec(pt.tess_coord).c_str());
    std::printf("      gl_Position %s\n      world position %s\n      world normal %s\n", vec(pt.gl_position).c_str(),
                vec(pt.position).c_str(), vec(pt.normal).c_str());
    if (!builtin || r.num_varyings > kBuiltinVaryings) {
      std::string v;
      for (float f : pt.varyings) v += (v.empty() ? "" : ", ") + g9(f);
      std::printf("      varyings (%s)\n", v.c_str());
    }
    if (!pt.primitives.empty()) {
      std::string t;
      for (std::size_t i : pt.primitives) t += (t.empty() ? "" : ", ") + std::to_string(i);
      std::printf("      in the patch's triangles %s\n", t.c_str());
    }
  }
  if (!r.traces.empty()) {
    std::printf("\n5. Source trace%s: each executed line, as executed, with the value it produced "
                "(stores: the variable written)\n",
                r.traced_twins ? " of the built-in programs' GLSL twins" : "");
    std::fputs(format_traces(r.traces).c_str(), stdout);
  }
  if (frags) {
    std::printf("\n%d. Fragments: %zu from the patch's %zu triangles, %zu of them visible in the image", r.traces.empty() ? 5 : 6,
                frags->count, frags->per_triangle.size(), frags->visible);
    if (frags->count)
      std::printf("; pixels x %d..%d, y %d..%d (from the top row)\n", frags->min_x, frags->max_x, frags->min_y, frags->max_y);
    else
      std::printf(" (culled, clipped or between pixel centres)\n");
    if (frags->nearest) {
      const PatchFragment& f = *frags->nearest;
      std::printf("  nearest to gl_TessCoord %s: pixel (%d, %d), triangle %zu, gl_TessCoord %s, %s; tessref inspect --pixel %d,%d\n",
                  vec(r.points.size() == 1 ? r.points[0].tess_coord : glm::vec3(1.0f / 3.0f)).c_str(), f.x, f.y,
                  f.triangle, vec(f.tess_coord).c_str(), f.visible ? "visible" : "hidden", f.x, f.y);
    }
  }
  if (r.draw)
    std::printf("\n%d. Fragments: not followed for a scene of draws yet (render --dump-fragments writes every fragment)\n",
                r.traces.empty() ? 5 : 6);
  std::printf("\n(%.1f ms)\n", seconds * 1e3);
}

nlohmann::json trace_value(const shader::TraceValue& v) {
  nlohmann::json a = nlohmann::json::array();
  for (std::size_t i = 0; i < v.scalars.size(); ++i) {
    if (v.scalars[i] == shader::Scalar::Bool) a.push_back(v.bits[i] != 0);
    else a.push_back(std::strtod(v.component_text(i).c_str(), nullptr));
  }
  return a;
}

nlohmann::json traces_json(const std::vector<InspectTrace>& traces) {
  using nlohmann::json;
  json out = json::array();
  for (const InspectTrace& t : traces) {
    json lines = json::array();
    for (const shader::TraceLine& l : t.trace.lines) {
      json j{{"line", l.line}, {"source", t.source_line(l.line)}};
      if (!l.stores.empty()) {
        json stores = json::array();
        for (const shader::TraceStore& s : l.stores) stores.push_back(json{{"target", s.target}, {"value", trace_value(s.value)}});
        j["stores"] = stores;
      }
      if (l.has_result) j["result"] = trace_value(l.result);
      if (!l.joins.empty()) {
        json joins = json::array();
        for (const shader::TraceValue& v : l.joins) joins.push_back(trace_value(v));
        j["joins"] = joins;
      }
      if (l.barrier) j["barrier"] = true;
      lines.push_back(j);
    }
    out.push_back(json{{"stage", shader::stage_name(t.stage)}, {"file", t.file}, {"invocation", t.invocation},
                       {"lines", lines}, {"lines_not_kept", t.trace.dropped}});
  }
  return out;
}

nlohmann::json to_json(const Scene& scene, const InspectResult& r, const std::optional<PatchFragments>& frags) {
  using nlohmann::json;
  json corners = json::array();
  const int vs_slots = used_slots(r.corners);
  for (const InspectCorner& c : r.corners) {
    json j;
    if (r.draw) {
      j["gl_VertexID"] = c.vertex;
      json inputs = json::array();
      for (const InspectInput& in : c.inputs) {
        json v = json::array();
        for (const std::string& x : input_values(in)) v.push_back(std::strtod(x.c_str(), nullptr));
        inputs.push_back(json{{"location", in.location}, {"type", scalar_name(in.scalar)}, {"value", v}});
      }
      j["inputs"] = inputs;
    } else {
      j = json{{"mesh_vertex", c.vertex}, {"in_position", jvec(c.in_position)}, {"in_normal", jvec(c.in_normal)}};
    }
    if (c.gl_position) j["gl_Position"] = jvec(*c.gl_position);
    json out = json::array();
    for (int s = 0; s < vs_slots; ++s) out.push_back(jvec(c.vs_out.attr[s]));
    j["outputs"] = out;
    corners.push_back(j);
  }
  json gl_out = json::array();
  const int tcs_slots = used_slots(r.tcs_out);
  for (int k = 0; k < r.tcs_out.vertex_count; ++k) {
    json slots = json::array();
    for (int s = 0; s < tcs_slots; ++s) slots.push_back(jvec(r.tcs_out.vertices[k].attr[s]));
    gl_out.push_back(slots);
  }
  json patch_out = json::array();
  for (int s = 0; s < used_patch_slots(r.tcs_out); ++s) patch_out.push_back(jvec(r.tcs_out.patch[s]));
  const TessLevels& lv = r.tcs_out.levels;
  json tpg{{"domain", to_string(r.layout.domain)}, {"spacing", to_string(r.layout.spacing)},
           {"winding", to_string(r.layout.winding)}, {"point_mode", r.layout.point_mode},
           {"tessellator", to_string(r.tessellator)},
           {"discarded", r.levels.discarded}, {"domain_points", r.domain_points}, {"primitives", r.primitives},
           {"vertices_per_primitive", r.vertices_per_primitive}};
  if (!r.levels.discarded) {
    json oc = json::array(), os = json::array(), ic = json::array(), is = json::array();
    for (int e = 0; e < r.levels.outer_count; ++e) {
      oc.push_back(num(r.levels.outer[e]));
      os.push_back(r.levels.outer_segments[e]);
    }
    for (int a = 0; a < r.levels.inner_count; ++a) {
      ic.push_back(num(r.levels.inner[a]));
      is.push_back(r.levels.inner_segments[a]);
    }
    tpg["outer_clamped"] = oc;
    tpg["outer_segments"] = os;
    tpg["inner_clamped"] = ic;
    tpg["inner_segments"] = is;
    tpg["rings"] = rings(r);
  }
  json points = json::array();
  for (const InspectPoint& p : r.points) {
    json v = json::array();
    for (float f : p.varyings) v.push_back(num(f));
    points.push_back(json{{"index", p.index ? json(*p.index) : json()},
                          {"gl_TessCoord", jvec(p.tess_coord)},
                          {"gl_Position", jvec(p.gl_position)},
                          {"varyings", v},
                          {"world_position", jvec(p.position)},
                          {"world_normal", jvec(p.normal)},
                          {"primitives", p.primitives}});
  }
  json out{{"scene", scene.source},
              {"program", r.program},
              {"patch", r.patch},
              {"patch_count", r.patch_count},
              {"draw", r.draw ? json{{"draw", r.draw->draw}, {"call", r.draw->call}, {"gl_InstanceID", r.draw->instance},
                                     {"gl_PrimitiveID", r.draw->primitive_id}, {"patch_id", r.draw->patch_id}}
                              : json()},
              {"vertex_stage", {{"corners", corners}}},
              {"control_stage",
               {{"output_vertices", r.tcs_vertices},
                {"phases", r.tcs_phases},
                {"gl_out", gl_out},
                {"patch_out", patch_out},
                {"gl_TessLevelOuter", jvec(glm::vec4(lv.outer[0], lv.outer[1], lv.outer[2], lv.outer[3]))},
                {"gl_TessLevelInner", jvec(glm::vec2(lv.inner[0], lv.inner[1]))}}},
              {"primitive_generator", tpg},
              {"evaluation_stage",
               {{"num_varyings", r.num_varyings},
                {"dump_varyings", {r.dump_varyings[0], r.dump_varyings[1]}},
                {"points", points}}}};
  if (frags) {
    json f{{"count", frags->count}, {"visible", frags->visible}, {"per_triangle", frags->per_triangle}};
    if (frags->count) f["pixels"] = {{"min_x", frags->min_x}, {"max_x", frags->max_x}, {"min_y", frags->min_y}, {"max_y", frags->max_y}};
    if (frags->nearest)
      f["nearest"] = {{"x", frags->nearest->x}, {"y", frags->nearest->y}, {"triangle", frags->nearest->triangle},
                      {"gl_TessCoord", jvec(frags->nearest->tess_coord)}, {"visible", frags->nearest->visible}};
    out["fragments"] = f;
  }
  if (!r.traces.empty()) out["source_trace"] = {{"glsl_twins", r.traced_twins}, {"invocations", traces_json(r.traces)}};
  return out;
}

// --pixel X,Y: two integers (the range is checked against the image by inspect_pixel).
std::pair<int, int> parse_pixel(const std::string& text, const Scene& scene) {
  const auto integer = [&](std::size_t begin, std::size_t end, int& out) {
    const auto [ptr, ec] = std::from_chars(text.data() + begin, text.data() + end, out);
    return begin < end && ec == std::errc() && ptr == text.data() + end;
  };
  const std::size_t comma = text.find(',');
  std::pair<int, int> xy;
  if (comma == std::string::npos || !integer(0, comma, xy.first) || !integer(comma + 1, text.size(), xy.second))
    throw InputError("--pixel: expected X,Y (two integers: X from the left, Y down from the top row) on the " +
                     std::to_string(scene.width) + "x" + std::to_string(scene.height) + " image, got '" + text + "'");
  return xy;
}

// glDepthFunc's comparison as written between the fragment's depth and the stored one.
const char* depth_operator(DepthFunc f) {
  switch (f) {
    case DepthFunc::kNever: return "never";
    case DepthFunc::kLess: return "<";
    case DepthFunc::kEqual: return "==";
    case DepthFunc::kLessEqual: return "<=";
    case DepthFunc::kGreater: return ">";
    case DepthFunc::kNotEqual: return "!=";
    case DepthFunc::kGreaterEqual: return ">=";
    case DepthFunc::kAlways: return "always";
  }
  return "?";
}

std::string depth_verdict(const Scene& scene, const PixelInspectResult& r, std::size_t i) {
  const PixelFragment& f = r.fragments[i];
  const PixelFragment* next = f.hidden_by ? &r.fragments[*f.hidden_by] : nullptr;
  const bool blended_over = next && next->draw && scene.draws[*next->draw].raster.blend.enabled;
  const std::string ending = !next ? "; the winner: its colour is the pixel's"
                             : std::string(blended_over ? "; then blended over by fragment " : "; then hidden by fragment ") +
                                   std::to_string(*f.hidden_by);
  // The mesh path tests GL_LESS against depth cleared to 1; a draw its own function against the
  // initial, cleared or written depth.
  const RasterState* s = f.draw ? &scene.draws[*f.draw].raster : nullptr;
  if (s && !s->depth_test) return "none (GL_DEPTH_TEST off)" + ending;
  const char* op = s ? depth_operator(s->depth_func) : "<";
  const std::string met =
      g9(f.depth_before) + (f.depth_from ? ", fragment " + std::to_string(*f.depth_from) + "'s"
                                         : s ? ", the framebuffer's initial or cleared depth" : ", the cleared depth");
  if (!f.passed) return "failed: " + g9(f.frag_coord.z) + " " + op + " " + met + " does not hold";
  return "passed: " + g9(f.frag_coord.z) + " " + op + " " + met + ending;
}

void print_pixel_text(const Scene& scene, const PixelInspectResult& r, double seconds) {
  std::printf("tessref inspect: %s, pixel (%d, %d) of the %dx%d image (X from the left, Y down from the top row, as "
              "image files are written; GL window row %d); programs: %s\n\n",
              scene.source.c_str(), r.x, r.y, r.width, r.height, r.window_y, r.program.c_str());
  if (r.fragments.empty() && !r.pixel_outputs.empty()) {
    std::printf("no draw's fragment reached this pixel\n");
  } else if (r.fragments.empty()) {
    std::printf("nothing was drawn at this pixel: the background %s remains\n", vec(r.pixel_color).c_str());
  } else {
    if (r.fragments.size() == 1) std::printf("1 fragment at this pixel:\n");
    else std::printf("%zu fragments at this pixel, in the order the draw made them:\n", r.fragments.size());
  }
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    const PixelFragment& f = r.fragments[i];
    const char* facing = f.front_facing ? "front facing" : "back facing";
    const char* kind = f.primitive.c_str();
    if (!f.draw) std::printf("  fragment %zu: patch %zu, %s %zu, %s\n", i, f.patch, kind, f.triangle, facing);
    else if (f.from_patch) std::printf("  fragment %zu: draw %zu, patch %zu, %s %zu, %s\n", i, *f.draw, f.patch, kind, f.triangle, facing);
    else std::printf("  fragment %zu: draw %zu, %s %zu (untessellated), %s\n", i, *f.draw, kind, f.triangle, facing);
    if (f.from_patch) std::printf("      gl_TessCoord %s\n", vec(f.tess_coord).c_str());
    std::printf("      gl_FragCoord %s\n", vec(f.frag_coord).c_str());
    if (!f.draw) {  // the mesh path's convention: outputs 0 and 1 of the evaluation shader
      std::printf("      world position %s\n", vec(f.position).c_str());
      std::printf("      world normal %s\n", vec(f.normal).c_str());
    }
    if (r.program.rfind("glsl", 0) == 0) {
      std::string v;
      for (float x : f.inputs) v += (v.empty() ? "" : ", ") + g9(x);
      std::printf("      varyings (%s)\n", v.c_str());
    }
    if (f.outputs.size() > 1)
      for (std::size_t k = 0; k < f.outputs.size(); ++k)
        std::printf("      output %zu %s\n", k, vec(f.outputs[k]).c_str());
    else
      std::printf("      colour %s\n", vec(f.color).c_str());
    std::printf("      depth test: %s\n", depth_verdict(scene, r, i).c_str());
    if (f.trace) {
      std::printf("      source trace%s:\n", r.traced_twins ? " (the built-in program's GLSL twin)" : "");
      std::fputs(format_traces({*f.trace}).c_str(), stdout);
    }
  }
  if (!r.pixel_outputs.empty()) {  // a scene of draws: every draw buffer, whoever wrote it
    const std::string by = r.winner ? "colour last written by fragment " + std::to_string(*r.winner) + ", draw " +
                                          std::to_string(*r.fragments[*r.winner].draw)
                                    : "no fragment wrote it: the framebuffer's initial or cleared values";
    std::printf("\nthe pixel: colour %s, depth %s (%s)\n", vec(r.pixel_color).c_str(), g9(r.pixel_depth).c_str(),
                by.c_str());
  } else if (r.winner)
    std::printf("\nthe pixel: colour %s, depth %s (fragment %zu, patch %zu)\n", vec(r.pixel_color).c_str(),
                g9(r.pixel_depth).c_str(), *r.winner, r.fragments[*r.winner].patch);
  for (std::size_t k = 1; k < r.pixel_outputs.size(); ++k)
    std::printf("           draw buffer %zu %s\n", k, vec(r.pixel_outputs[k]).c_str());
  std::printf("\n(%.1f ms)\n", seconds * 1e3);
}

nlohmann::json pixel_json(const Scene& scene, const PixelInspectResult& r) {
  using nlohmann::json;
  const auto opt = [](const std::optional<std::size_t>& v) { return v ? json(*v) : json(); };
  json fragments = json::array();
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    const PixelFragment& f = r.fragments[i];
    fragments.push_back(json{{"patch", f.patch},
                             {"primitive", f.primitive},
                             {f.primitive, f.triangle},
                             {"gl_TessCoord", jvec(f.tess_coord)},
                             {"gl_FragCoord", jvec(f.frag_coord)},
                             {"front_facing", f.front_facing},
                             {"world_position", jvec(f.position)},
                             {"world_normal", jvec(f.normal)},
                             {"color", jvec(f.color)},
                             {"depth_test",
                              {{"passed", f.passed}, {"stored_depth", num(f.depth_before)},
                               {"stored_by", opt(f.depth_from)}}},
                             {"hidden_by", opt(f.hidden_by)}});
    json& j = fragments.back();
    if (f.draw) {
      j["draw"] = *f.draw;
      j["from_patch"] = f.from_patch;
      json outputs = json::array();
      for (const glm::vec4& o : f.outputs) outputs.push_back(jvec(o));
      j["outputs"] = outputs;
    }
    json inputs = json::array();
    for (float x : f.inputs) inputs.push_back(num(x));
    j["varyings"] = inputs;
    if (f.trace) j["source_trace"] = traces_json({*f.trace}).at(0);
  }
  return json{{"scene", scene.source},
              {"program", r.program},
              {"traced_glsl_twins", r.traced_twins},
              {"pixel", {{"x", r.x}, {"y", r.y}, {"y_axis", "down from the top row"}, {"window_y", r.window_y}}},
              {"image", {{"width", r.width}, {"height", r.height}}},
              {"fragments", fragments},
              {"winner", opt(r.winner)},
              {"pixel_color", jvec(r.pixel_color)},
              {"pixel_depth", num(r.pixel_depth)},
              {"pixel_draw_buffers", [&] {
                 json buffers = json::array();
                 for (const glm::vec4& o : r.pixel_outputs) buffers.push_back(jvec(o));
                 return buffers;
               }()}};
}

void write_json(const std::string& path, const nlohmann::json& j) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError("--json: cannot create '" + path + "'");
  out << j.dump(1) << "\n";
  if (!out.flush()) throw InputError("--json: cannot write '" + path + "'");
}

void run_inspect_pixel(const InspectArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  if (a.patch != kNotGiven || a.vertex != kNotGiven || !a.coord.empty())
    throw InputError("--pixel: give it alone (--patch, --coord and --vertex ask about a patch)");
  Scene scene = load_scene(a.scene, a.sets);
  const bool trace = a.trace && (parse_trace_stages(a.trace_stages) & kTraceFragment);
  if (!scene.draws.empty()) {
    if (a.draw != kNotGiven) throw InputError("--draw: --pixel follows every draw of the scene at the pixel; give --pixel alone");
    const auto [x, y] = parse_pixel(a.pixel, scene);
    const PixelInspectResult r = inspect_draws_pixel(scene, x, y, Parallel(a.threads), trace);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!a.json.empty()) return write_json(a.json, pixel_json(scene, r));
    return print_pixel_text(scene, r, seconds);
  }
  if (a.draw != kNotGiven) throw InputError("--draw: the scene has no draws (it draws its mesh)");
  const auto [x, y] = parse_pixel(a.pixel, scene);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
  scene.camera = fitted_camera(scene, mesh);  // as render does
  const PixelInspectResult r = inspect_pixel(scene, mesh, x, y, Parallel(a.threads), trace);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!a.json.empty()) return write_json(a.json, pixel_json(scene, r));
  print_pixel_text(scene, r, seconds);
}

void run_inspect(const InspectArgs& a) {
  if (!a.pixel.empty()) return run_inspect_pixel(a);
  const auto t0 = std::chrono::steady_clock::now();
  if (a.patch == kNotGiven) throw InputError("--patch: required: which patch of the draw to inspect (counted from 0), or --pixel X,Y");
  if (a.patch < 0) throw InputError("--patch: " + std::to_string(a.patch) + " is not a patch: patches count from 0");
  if (a.vertex != kNotGiven && a.vertex < 0) throw InputError("--vertex: must be 0 or more, got " + std::to_string(a.vertex));
  if (a.draw != kNotGiven && a.draw < 0) throw InputError("--draw: " + std::to_string(a.draw) + " is not a draw: draws count from 0");
  if (!a.coord.empty() && a.vertex != kNotGiven)
    throw InputError("--coord and --vertex: give one of them (a coordinate, or a generated point's index)");
  Scene scene = load_scene(a.scene, a.sets);
  InspectRequest request;
  if (a.draw != kNotGiven) {
    if (scene.draws.empty()) throw InputError("--draw: the scene has no draws (it draws its mesh)");
    request.draw = std::size_t(a.draw);
  } else if (scene.draws.size() > 1) {
    throw InputError("--draw: required: the scene has " + std::to_string(scene.draws.size()) +
                     " draws; say which one's patch to inspect (0.." + std::to_string(scene.draws.size() - 1) + ")");
  }
  request.patch = std::size_t(a.patch);
  if (a.vertex != kNotGiven) request.vertex = std::size_t(a.vertex);
  if (!a.coord.empty()) {
    const std::vector<float> c = parse_coord(a.coord);
    request.coord = glm::vec3(c[0], c[1], c.size() == 3 ? c[2] : 0.0f);
    request.coord_has_w = c.size() == 3;
  }
  if (a.trace) request.trace = parse_trace_stages(a.trace_stages);
  if (!scene.draws.empty()) {
    // The fragments a draw's patch became are not tagged yet: the stages only.
    const InspectResult r = inspect_draw_patch(scene, request);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!a.json.empty()) return write_json(a.json, to_json(scene, r, std::nullopt));
    return print_text(scene, r, std::nullopt, seconds);
  }
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "tessref: warning: %s\n", w.c_str());
  scene.camera = fitted_camera(scene, mesh);  // as render does
  const InspectResult r = inspect_patch(scene, mesh, request);
  std::optional<PatchFragments> frags;
  if (!a.no_fragments) {
    const std::optional<glm::vec3> near =
        r.points.size() == 1 ? std::optional<glm::vec3>(r.points[0].tess_coord) : std::nullopt;
    frags = patch_fragments(scene, mesh, r.patch, r.vertices_per_primitive == 3 ? r.primitives : 0, near, Parallel(a.threads));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!a.json.empty()) return write_json(a.json, to_json(scene, r, frags));
  print_text(scene, r, frags, seconds);
}

}  // namespace

void add_inspect_command(CLI::App& app) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* cmd = app.add_subcommand(
      "inspect", "Show one patch of the scene's draw stage by stage (vertex shader, control shader, primitive "
                 "generator, evaluation shader), or the fragments at one pixel, with the values the draw computes "
                 "(docs/inspect.md)");
  add_scene_options(cmd, args->scene, args->sets);
  cmd->add_option("--patch", args->patch,
                  "the patch (draw order, from 0) to inspect; a scene of draws: counted over --draw's calls and instances")
      ->check(kInteger);
  cmd->add_option("--draw", args->draw, "a scene of draws: the draw (from 0) whose patch to inspect (required when there are several)")
      ->check(kInteger);
  cmd->add_option("--pixel", args->pixel,
                  "instead of a patch: the fragments the draw made at pixel X,Y (X from the left, Y down from the top "
                  "row, as the image file), with their patches and the depth test's verdicts");
  cmd->add_option("--threads", args->threads, "worker threads for the draw of --pixel and of --patch's fragments (0: all hardware threads)")
      ->check(kInteger);
  cmd->add_option("--coord", args->coord, "evaluate the TES at gl_TessCoord U,V[,W] (triangles: W = (1 - U) - V if left out)");
  cmd->add_option("--vertex", args->vertex, "the patch's K-th generated domain point (from 0)")->check(kInteger);
  cmd->add_option("--json", args->json, "write the result as JSON to FILE instead of printing text");
  cmd->add_flag("--no-fragments", args->no_fragments,
                "with --patch: skip drawing the scene to find the fragments the patch became");
  cmd->add_flag("--trace", args->trace,
                "also show the source-level trace: every GLSL line each invocation executed, with its values (the "
                "built-in programs through their GLSL twins)");
  cmd->add_option("--trace-stages", args->trace_stages,
                  "the stages --trace covers: a comma-separated list of vertex, control, evaluation, fragment, all")
      ->default_val("all");
  cmd->callback([args] { run_inspect(*args); });
}

}  // namespace tessref::cli
