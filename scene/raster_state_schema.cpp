#include "scene/raster_state_schema.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <utility>

#include "common/fixed_point.h"

namespace tessref {
namespace {

using nlohmann::json;

// One of a list of GL enum names, or a failure naming them.
template <class E, std::size_t N>
E gl_enum(JsonObject& o, const std::string& key, const std::pair<const char*, E> (&names)[N], const nlohmann::json& v) {
  std::string all;
  for (const auto& [name, e] : names) {
    if (v.is_string() && v.get<std::string>() == name) return e;
    all += (all.empty() ? "" : ", ") + std::string(name);
  }
  o.fail(key, "expected one of " + all + ", got " + describe_json(v));
}

constexpr std::pair<const char*, DepthFunc> kDepthFuncs[] = {
    {"GL_NEVER", DepthFunc::kNever},   {"GL_LESS", DepthFunc::kLess},         {"GL_EQUAL", DepthFunc::kEqual},
    {"GL_LEQUAL", DepthFunc::kLessEqual}, {"GL_GREATER", DepthFunc::kGreater}, {"GL_NOTEQUAL", DepthFunc::kNotEqual},
    {"GL_GEQUAL", DepthFunc::kGreaterEqual}, {"GL_ALWAYS", DepthFunc::kAlways}};
constexpr std::pair<const char*, BlendEquation> kEquations[] = {
    {"GL_FUNC_ADD", BlendEquation::kAdd}, {"GL_FUNC_SUBTRACT", BlendEquation::kSubtract},
    {"GL_FUNC_REVERSE_SUBTRACT", BlendEquation::kReverseSubtract}, {"GL_MIN", BlendEquation::kMin},
    {"GL_MAX", BlendEquation::kMax}};
constexpr std::pair<const char*, BlendFactor> kFactors[] = {
    {"GL_ZERO", BlendFactor::kZero},
    {"GL_ONE", BlendFactor::kOne},
    {"GL_SRC_COLOR", BlendFactor::kSrcColor},
    {"GL_ONE_MINUS_SRC_COLOR", BlendFactor::kOneMinusSrcColor},
    {"GL_DST_COLOR", BlendFactor::kDstColor},
    {"GL_ONE_MINUS_DST_COLOR", BlendFactor::kOneMinusDstColor},
    {"GL_SRC_ALPHA", BlendFactor::kSrcAlpha},
    {"GL_ONE_MINUS_SRC_ALPHA", BlendFactor::kOneMinusSrcAlpha},
    {"GL_DST_ALPHA", BlendFactor::kDstAlpha},
    {"GL_ONE_MINUS_DST_ALPHA", BlendFactor::kOneMinusDstAlpha},
    {"GL_CONSTANT_COLOR", BlendFactor::kConstantColor},
    {"GL_ONE_MINUS_CONSTANT_COLOR", BlendFactor::kOneMinusConstantColor},
    {"GL_CONSTANT_ALPHA", BlendFactor::kConstantAlpha},
    {"GL_ONE_MINUS_CONSTANT_ALPHA", BlendFactor::kOneMinusConstantAlpha},
    {"GL_SRC_ALPHA_SATURATE", BlendFactor::kSrcAlphaSaturate}};

enum class Face { kBack, kFront, kBoth };
constexpr std::pair<const char*, Face> kFaces[] = {
    {"GL_BACK", Face::kBack}, {"GL_FRONT", Face::kFront}, {"GL_FRONT_AND_BACK", Face::kBoth}};
constexpr std::pair<const char*, bool> kWindings[] = {{"GL_CCW", false}, {"GL_CW", true}};  // true: cw front
constexpr std::pair<const char*, PolygonMode> kPolygonModes[] = {
    {"GL_FILL", PolygonMode::kFill}, {"GL_LINE", PolygonMode::kLine}, {"GL_POINT", PolygonMode::kPoint}};

BlendState read_blend(JsonObject& b) {
  BlendState s;
  b.describe("equation", "glBlendEquation for colour and alpha: GL_FUNC_ADD (default), GL_FUNC_SUBTRACT, "
                         "GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX");
  if (b.has("equation")) s.equation_rgb = s.equation_alpha = gl_enum(b, "equation", kEquations, b.value("equation"));
  b.describe("equation_alpha", "glBlendEquationSeparate's alpha equation (default: equation)");
  if (b.has("equation_alpha")) s.equation_alpha = gl_enum(b, "equation_alpha", kEquations, b.value("equation_alpha"));
  b.describe("src", "glBlendFunc's source factor for colour and alpha: GL_ONE (default), GL_SRC_ALPHA, ...");
  if (b.has("src")) s.src_rgb = s.src_alpha = gl_enum(b, "src", kFactors, b.value("src"));
  b.describe("dst", "glBlendFunc's destination factor: GL_ZERO (default), GL_ONE_MINUS_SRC_ALPHA, ...");
  if (b.has("dst")) s.dst_rgb = s.dst_alpha = gl_enum(b, "dst", kFactors, b.value("dst"));
  b.describe("src_alpha", "glBlendFuncSeparate's alpha source factor (default: src)");
  if (b.has("src_alpha")) s.src_alpha = gl_enum(b, "src_alpha", kFactors, b.value("src_alpha"));
  b.describe("dst_alpha", "glBlendFuncSeparate's alpha destination factor (default: dst)");
  if (b.has("dst_alpha")) s.dst_alpha = gl_enum(b, "dst_alpha", kFactors, b.value("dst_alpha"));
  b.describe("color", "glBlendColor: [r, g, b, a] (default 0)");
  if (b.has("color")) s.constant = b.rgba("color");
  b.finish();
  return s;
}

}  // namespace

// GL_CLIP_DISTANCEi's i (0 to 7), or -1.
int clip_distance_index(const json& cap) {
  if (!cap.is_string()) return -1;
  const std::string& name = cap.get_ref<const std::string&>();
  const std::string prefix = "GL_CLIP_DISTANCE";
  if (name.size() != prefix.size() + 1 || name.compare(0, prefix.size(), prefix) != 0) return -1;
  const char c = name.back();
  return c >= '0' && c <= '7' ? c - '0' : -1;
}

RasterState read_raster_state(JsonObject& o) {
  RasterState r = gl_initial_state();
  bool cull = false, scissor = false, blend = false;
  o.describe("enable", "an array of GL capabilities glEnable turns on: GL_DEPTH_TEST, GL_CULL_FACE, GL_SCISSOR_TEST, GL_BLEND, GL_FRAMEBUFFER_SRGB, GL_DEPTH_CLAMP, GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_CLIP_DISTANCE0 to GL_CLIP_DISTANCE7");
  if (o.has("enable")) {
    const json& e = o.value("enable");
    if (!e.is_array()) o.fail("enable", "expected an array of GL_DEPTH_TEST, GL_CULL_FACE, GL_SCISSOR_TEST, GL_BLEND, GL_FRAMEBUFFER_SRGB, GL_DEPTH_CLAMP, GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_CLIP_DISTANCE0 to GL_CLIP_DISTANCE7, got " + describe_json(e));
    for (const json& cap : e) {
      if (cap == "GL_DEPTH_TEST") r.depth_test = true;
      else if (cap == "GL_CULL_FACE") cull = true;
      else if (cap == "GL_SCISSOR_TEST") scissor = true;
      else if (cap == "GL_BLEND") blend = true;
      else if (cap == "GL_FRAMEBUFFER_SRGB") r.framebuffer_srgb = true;
      else if (cap == "GL_DEPTH_CLAMP") r.depth_clamp = true;
      else if (cap == "GL_TEXTURE_CUBE_MAP_SEAMLESS") r.cube_map_seamless = true;
      else if (const int plane = clip_distance_index(cap); plane >= 0) r.clip_distances |= std::uint8_t(1u << plane);
      else if (cap == "GL_PRIMITIVE_RESTART" || cap == "GL_PRIMITIVE_RESTART_FIXED_INDEX")
        o.fail("enable", "primitive restart is the key primitive_restart (with its index)");
      else o.fail("enable", "expected GL_DEPTH_TEST, GL_CULL_FACE, GL_SCISSOR_TEST, GL_BLEND, GL_FRAMEBUFFER_SRGB, GL_DEPTH_CLAMP, GL_TEXTURE_CUBE_MAP_SEAMLESS or GL_CLIP_DISTANCE0 to GL_CLIP_DISTANCE7, got " + describe_json(cap));
    }
  }
  o.describe("depth_func", "glDepthFunc: GL_LESS (default), GL_LEQUAL, GL_EQUAL, GL_GREATER, GL_GEQUAL, GL_NOTEQUAL, GL_ALWAYS, GL_NEVER");
  if (o.has("depth_func")) r.depth_func = gl_enum(o, "depth_func", kDepthFuncs, o.value("depth_func"));
  o.describe("depth_mask", "glDepthMask: true (default) writes depth");
  if (o.has("depth_mask")) r.depth_write = o.boolean("depth_mask");
  o.describe("cull_face", "glCullFace: GL_BACK (default), GL_FRONT, GL_FRONT_AND_BACK (with GL_CULL_FACE enabled)");
  Face face = Face::kBack;
  if (o.has("cull_face")) face = gl_enum(o, "cull_face", kFaces, o.value("cull_face"));
  r.cull_back_faces = cull && face != Face::kFront;
  r.cull_front_faces = cull && face != Face::kBack;
  o.describe("front_face", "glFrontFace: GL_CCW (default) or GL_CW");
  if (o.has("front_face")) r.front_face_cw = gl_enum(o, "front_face", kWindings, o.value("front_face"));
  o.describe("polygon_mode", "glPolygonMode(GL_FRONT_AND_BACK, ...): GL_FILL (default), GL_LINE or GL_POINT");
  if (o.has("polygon_mode")) r.polygon_mode = gl_enum(o, "polygon_mode", kPolygonModes, o.value("polygon_mode"));
  o.describe("scissor", "glScissor: [x, y, width, height] in pixels (with GL_SCISSOR_TEST enabled)");
  if (o.has("scissor")) {
    const json& s = o.value("scissor");
    if (!s.is_array() || s.size() != 4 || !std::all_of(s.begin(), s.end(), [](const json& x) { return x.is_number_integer(); }))
      o.fail("scissor", "expected [x, y, width, height] as 4 integers, got " + describe_json(s));
    r.scissor = {scissor, s[0].get<int>(), s[1].get<int>(), s[2].get<int>(), s[3].get<int>()};
    if (r.scissor.width < 0 || r.scissor.height < 0)
      o.fail("scissor", "glScissor refuses a negative width or height (GL_INVALID_VALUE)");
  } else if (scissor) {
    o.fail("enable", "GL_SCISSOR_TEST without a scissor box: give scissor [x, y, width, height]", {"scissor"});
  }
  o.describe("viewport", "glViewport: [x, y, width, height] in pixels, y up from the bottom row (default: the whole image)");
  if (o.has("viewport")) {
    const json& v = o.value("viewport");
    if (!v.is_array() || v.size() != 4 || !std::all_of(v.begin(), v.end(), [](const json& x) { return x.is_number_integer(); }))
      o.fail("viewport", "expected [x, y, width, height] as 4 integers, got " + describe_json(v));
    const ViewportRect rect{v[0].get<int>(), v[1].get<int>(), v[2].get<int>(), v[3].get<int>()};
    if (rect.width < 0 || rect.height < 0)
      o.fail("viewport", "glViewport refuses a negative width or height (GL_INVALID_VALUE)");
    // GL clamps a larger viewport to GL_MAX_VIEWPORT_DIMS and its origin to GL_VIEWPORT_BOUNDS_RANGE;
    // tessref's fixed-point bounds (fixed_point.h) take origins within one maximal viewport of the image.
    if (rect.width > fixed::kMaxViewportPixels || rect.height > fixed::kMaxViewportPixels)
      o.fail("viewport", "width and height must be at most " + std::to_string(fixed::kMaxViewportPixels) + " (GL_MAX_VIEWPORT_DIMS)");
    if (std::abs(rect.x) > fixed::kMaxViewportPixels || std::abs(rect.y) > fixed::kMaxViewportPixels)
      o.fail("viewport", "x and y must lie within -" + std::to_string(fixed::kMaxViewportPixels) + ".." + std::to_string(fixed::kMaxViewportPixels));
    if (rect.width == 0 || rect.height == 0)
      o.fail("viewport", "a viewport without area draws nothing; leave the draw out");
    r.viewport = rect;
  }
  o.describe("depth_range", "glDepthRange: [near, far] (default [0, 1]; GL clamps each to [0, 1])");
  if (o.has("depth_range")) {
    const json& d = o.value("depth_range");
    if (!d.is_array() || d.size() != 2 || !std::all_of(d.begin(), d.end(), [](const json& x) { return x.is_number(); }))
      o.fail("depth_range", "expected [near, far] as 2 numbers, got " + describe_json(d));
    r.depth_range_near = std::clamp(d[0].get<double>(), 0.0, 1.0);
    r.depth_range_far = std::clamp(d[1].get<double>(), 0.0, 1.0);
  }
  o.describe("color_mask", "glColorMask: [r, g, b, a] booleans (default all true)");
  if (o.has("color_mask")) {
    const json& m = o.value("color_mask");
    if (!m.is_array() || m.size() != 4 || !std::all_of(m.begin(), m.end(), [](const json& x) { return x.is_boolean(); }))
      o.fail("color_mask", "expected [r, g, b, a] as 4 booleans, got " + describe_json(m));
    r.color_mask = {m[0].get<bool>(), m[1].get<bool>(), m[2].get<bool>(), m[3].get<bool>()};
  }
  o.describe("blend", "an object {equation, equation_alpha, src, dst, src_alpha, dst_alpha, color}: glBlendEquationSeparate, "
                      "glBlendFuncSeparate and glBlendColor (with GL_BLEND enabled)");
  if (o.has("blend")) {
    JsonObject b = o.object("blend");
    r.blend = read_blend(b);
  }
  r.blend.enabled = blend;
  return r;
}

}  // namespace tessref
