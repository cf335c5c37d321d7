#include "scene/scene_schema.h"

#include <cmath>
#include <functional>
#include <limits>

#include "scene/draw_schema.h"
#include "scene/texture_schema.h"
#include "shader/executor.h"

namespace tessref {
namespace {

using nlohmann::json;
constexpr float kInf = std::numeric_limits<float>::infinity();

bool parse(const std::string& s, MeshType& out) {
  static const std::pair<const char*, MeshType> kNames[] = {{"icosphere", MeshType::Icosphere},
                                                            {"torus", MeshType::Torus},
                                                            {"cube", MeshType::Cube},
                                                            {"file", MeshType::File},
                                                            {"seed004_torus", MeshType::Seed004Torus},
                                                            {"rounded_cube", MeshType::RoundedCube},
                                                            {"vase", MeshType::Vase}};
  for (const auto& [name, type] : kNames)
    if (s == name) return out = type, true;
  return false;
}

bool parse(const std::string& s, Shading& out) {
  if (s == "phong") return out = Shading::Phong, true;
  if (s == "normals") return out = Shading::Normals, true;
  return false;
}

bool parse(const std::string& s, PolygonMode& out) {
  if (s == "GL_FILL") return out = PolygonMode::kFill, true;
  if (s == "GL_LINE") return out = PolygonMode::kLine, true;
  if (s == "GL_POINT") return out = PolygonMode::kPoint, true;
  return false;
}

template <typename Enum>
Enum enum_value(JsonObject& o, const std::string& key, const char* choices) {
  std::string s = o.string(key);
  o.describe(key, "one of " + std::string(choices));
  Enum e{};
  if (!parse(s, e)) o.fail(key, "expected one of " + std::string(choices) + ", got \"" + s + "\"");
  return e;
}

// A procedural mesh's size: positive, and small enough that its triangles' edge cross products
// (about size^2) stay within single precision.
constexpr float kMaxExtent = 1e18f;
float extent(JsonObject& o, const std::string& key) {
  const float v = o.number_in(key, 0.0f, kInf, true, true);
  o.describe(key, "a number in (0, 1e18]");
  if (v > kMaxExtent)
    o.fail(key, format_float(v) + " is too large: the mesh's triangle areas (about its square) "
                "would overflow single precision; use at most 1e18");
  return v;
}

MeshSettings read_mesh(JsonObject o, const std::filesystem::path& base_dir) {
  MeshSettings m;
  m.type = enum_value<MeshType>(o, "type", "icosphere, torus, cube, file, seed004_torus, rounded_cube, vase");
  o.describe("path", "a mesh file (OBJ, PLY, STL, ... through assimp), relative to the scene file");
  if (o.has("path")) {
    std::filesystem::path p = o.string("path");
    m.path = p.is_relative() ? base_dir / p : p;
  }
  const std::string normals = o.string("normals");
  o.describe("normals", "one of shared, split (a file's normals per face, as stored: cracks where they differ)");
  if (normals != "shared" && normals != "split")
    o.fail("normals", "expected one of shared, split, got \"" + normals + "\"");
  m.split_normals = normals == "split";
  if (m.type == MeshType::File && m.path.empty())
    o.fail("path", "required when mesh.type is \"file\" (a path relative to the scene file)");
  JsonObject ico = o.object("icosphere");
  m.icosphere_refinements = ico.integer("refinements", 0, 8);
  m.icosphere_radius = extent(ico, "radius");
  ico.finish();
  JsonObject torus = o.object("torus");
  m.torus_major_radius = extent(torus, "major_radius");
  m.torus_minor_radius = extent(torus, "minor_radius");
  torus.describe("minor_radius", "a number in (0, 1e18], less than major_radius");
  if (!(m.torus_minor_radius < m.torus_major_radius))
    torus.fail("minor_radius", "must be less than mesh.torus.major_radius (" +
                                   format_float(m.torus_major_radius) + "), got " +
                                   format_float(m.torus_minor_radius),
               {"major_radius"});
  m.torus_major_segments = torus.integer("major_segments", 3, 4096);
  m.torus_minor_segments = torus.integer("minor_segments", 3, 4096);
  torus.finish();
  JsonObject cube = o.object("cube");
  m.cube_size = extent(cube, "size");
  cube.finish();
  // Seed 004's meshes (mesh/reference_meshes.h): optional, as the default scene has none.
  o.describe("seed004_torus", "an object: grid (3..4096), normals (face_average, analytic)");
  o.describe("rounded_cube", "an object: cut (0..1), half_size (> 0)");
  if (o.has("seed004_torus")) {
    JsonObject t = o.object("seed004_torus");
    if (t.has("grid")) m.seed004_torus_grid = t.integer("grid", 3, 4096);
    if (t.has("normals")) {
      const std::string n = t.string("normals");
      t.describe("normals", "one of face_average (seed 004's), analytic");
      if (n != "face_average" && n != "analytic")
        t.fail("normals", "expected one of face_average, analytic, got \"" + n + "\"");
      m.seed004_torus_analytic_normals = n == "analytic";
    }
    t.finish();
  }
  if (o.has("rounded_cube")) {
    JsonObject c = o.object("rounded_cube");
    if (c.has("cut")) {
      m.rounded_cube_cut = c.number_in("cut", 0.0f, 1.0f, true, true);
      c.describe("cut", "a number in (0, 1): where the corners are cut along each edge");
    }
    if (c.has("half_size")) m.rounded_cube_half_size = extent(c, "half_size");
    c.finish();
  }
  o.finish();
  return m;
}

Transform read_transform(JsonObject o) {
  Transform t;
  t.translate = o.vec3("translate");
  t.rotate_deg = o.vec3("rotate_deg");
  t.scale = o.vec3_or_scalar("scale");
  if (t.scale.x == 0.0f || t.scale.y == 0.0f || t.scale.z == 0.0f)
    o.fail("scale", "must not be zero (the model would be flat and its normals undefined)");
  o.finish();
  return t;
}

Camera read_camera(JsonObject o) {
  Camera c;
  c.eye = o.vec3("eye");
  c.target = o.vec3("target");
  c.up = o.vec3("up");
  c.fov_y_deg = o.number_in("fov_y_deg", 0.0f, 180.0f, true, true);
  c.near = o.number_in("near", 0.0f, kInf, true, true);
  c.far = o.number_in("far", 0.0f, kInf, true, true);
  o.describe("far", "a number greater than camera.near");
  if (!(c.far > c.near))
    o.fail("far", "must be greater than camera.near (" + format_float(c.near) + "), got " +
                      format_float(c.far), {"near"});
  c.fit = o.boolean("fit");
  glm::vec3 forward = c.target - c.eye;
  // lookAt normalizes target - eye and up in single precision: their squared lengths must fit.
  const float forward2 = glm::dot(forward, forward), up2 = glm::dot(c.up, c.up);
  if (!std::isfinite(forward2))
    o.fail("eye", "the distance from camera.eye to camera.target overflows single precision when "
                  "squared (keep it below 1e19)", {"target"});
  if (!std::isfinite(up2))
    o.fail("up", "its length overflows single precision when squared (keep it below 1e19)");
  if (forward2 == 0.0f) o.fail("target", "must differ from camera.eye", {"eye"});
  // In double: the test must not overflow where lookAt itself would not.
  const glm::dvec3 side = glm::cross(glm::dvec3(forward), glm::dvec3(c.up));
  if (!(glm::dot(side, side) > 1e-12 * double(forward2) * double(up2)))
    o.fail("up", "must not be zero or parallel to the view direction (target - eye)", {"eye", "target"});
  o.finish();
  return c;
}

std::vector<Light> read_lights(JsonObject& root, const JsonSource& source) {
  root.describe("lights", "an array of at most " + std::to_string(kMaxLights) + " lights");
  const json& arr = root.value("lights");
  if (!arr.is_array() || arr.size() > kMaxLights)
    root.fail("lights", "expected an array of at most " + std::to_string(kMaxLights) +
                            " lights, got " + describe_json(arr));
  std::vector<Light> lights;
  for (std::size_t i = 0; i < arr.size(); ++i) {
    JsonObject o(arr[i], "lights." + std::to_string(i), source);
    Light l;
    l.position = o.vec3("position");
    if (o.has("intensity")) l.intensity = o.vec3("intensity");
    if (l.intensity.x < 0.0f || l.intensity.y < 0.0f || l.intensity.z < 0.0f)
      o.fail("intensity", "must not be negative");
    o.finish();
    lights.push_back(l);
  }
  return lights;
}

Material read_material(JsonObject o) {
  Material m;
  m.ka = o.number_in("ka", 0.0f, kInf, false, true);
  m.kd = o.number_in("kd", 0.0f, kInf, false, true);
  m.ks = o.number_in("ks", 0.0f, kInf, false, true);
  // > 0: GLSL leaves pow(0, 0) undefined.
  m.shininess = o.number_in("shininess", 0.0f, kInf, true, true);
  m.color = o.vec3("color");
  o.finish();
  return m;
}

TessellationSettings read_tessellation(JsonObject o) {
  TessellationSettings t;
  t.enabled = o.boolean("enabled");
  t.scheme = enum_value<SurfaceScheme>(o, "scheme", "flat, pn, phong, nlsa, nagata, scalar_tagged_pn");
  t.normal_mode =
      enum_value<NormalMode>(o, "normal_mode", "linear, quadratic, quadratic_corrected, analytic");
  t.spacing = enum_value<TessSpacing>(o, "spacing", "equal, fractional_odd, fractional_even");
  t.winding = enum_value<TessWinding>(o, "winding", "ccw, cw");
  t.tessellator = enum_value<Tessellator>(o, "tessellator", "primitive_generator, uniform, refinement_pattern");
  // Every level is allowed, as a control shader may write any (docs/tpg.md: NaN or <= 0 outer
  // levels discard the patch; inner levels clamp, NaN to the lower bound).
  std::vector<float> inner = o.levels("inner", 1, 2);
  for (std::size_t i = 0; i < inner.size(); ++i) t.levels.inner[i] = inner[i];
  if (inner.size() == 1) t.levels.inner[1] = inner[0];
  std::vector<float> outer = o.levels("outer", 3, 4);
  for (std::size_t i = 0; i < outer.size(); ++i) t.levels.outer[i] = outer[i];
  if (outer.size() == 3) t.levels.outer[3] = outer[2];
  JsonObject a = o.object("adaptive");
  t.adaptive.enabled = a.boolean("enabled");
  t.adaptive.pixels_per_segment = a.number_in("pixels_per_segment", 0.0f, kInf, true, true);
  a.finish();
  // The quadratic schemes' parameters (docs/schemes.md), checked whatever the scheme.
  t.phong_alpha = o.number("phong_alpha");
  o.describe("phong_alpha", "a finite number >= 0: Phong tessellation's shape factor (0 flat, 0.75 the paper's)");
  if (!(t.phong_alpha >= 0.0f))
    o.fail("phong_alpha", "must not be negative (0 is the flat triangle, 1 the full tangent-plane "
                          "projection, 0.75 Boubekeur & Alexa's choice), got " + format_float(t.phong_alpha));
  t.nagata_eps = o.number("nagata_eps");
  o.describe("nagata_eps", "a number in [0, 0.5]: Nagata's threshold on (1 - n0.n1)/2");
  if (!(t.nagata_eps >= 0.0f && t.nagata_eps <= 0.5f))
    o.fail("nagata_eps", "must be in [0, 0.5] (an edge is left straight where (1 - n0.n1)/2 <= eps or "
                         "(1 + n0.n1)/2 <= eps: 0 only for exactly parallel normals, 0.5 for every edge), got " +
                             format_float(t.nagata_eps));
  o.describe("displacement", "an object {amplitude, frequency}: P + amplitude sin(frequency |P|) N");
  if (o.has("displacement")) {
    JsonObject d = o.object("displacement");
    t.displacement.enabled = true;
    t.displacement.amplitude = d.number("amplitude");
    t.displacement.frequency = d.number("frequency");
    d.describe("frequency", "a finite number >= 0 (radians per world unit of |P|)");
    if (!(t.displacement.frequency >= 0.0f))
      d.fail("frequency", "must not be negative (sin(-f r) = -sin(f r): use a negative amplitude), got " +
                              format_float(t.displacement.frequency));
    d.finish();
  }
  // Scalar Tagged PN's tags (mesh/vertex_tags.h checks the file against the mesh at draw time).
  o.describe("tags", "a JSON file of per-vertex tags, relative to the scene file (docs/scalar-tagged-pn.md)");
  if (o.has("tags")) t.tags = o.string("tags");
  o.describe("tension", "a number in [-1, 1]: every vertex's tension where tessellation.tags gives none");
  if (o.has("tension")) t.tension = o.number_in("tension", -1.0f, 1.0f, false, false);
  if ((!t.tags.empty() || t.tension != 0.0f) && t.scheme != SurfaceScheme::ScalarTaggedPN)
    o.fail(t.tags.empty() ? "tension" : "tags", "applies to scheme \"scalar_tagged_pn\" only (the scheme is \"" +
                                                   std::string(to_string(t.scheme)) + "\")", {"scheme"});
  // One n per patch from its own levels: adaptive levels would differ across a shared edge and
  // open T-junction cracks, so uniform subdivision takes fixed levels only.
  if (t.enabled && t.tessellator != Tessellator::PrimitiveGenerator && t.adaptive.enabled)
    o.fail("tessellator", "\"" + std::string(to_string(t.tessellator)) +
                              "\" needs fixed levels; it cannot be used with adaptive.enabled",
           {"adaptive.enabled", "enabled"});
  o.finish();
  return t;
}

}  // namespace

ShaderSettings read_shaders(JsonObject o, const JsonSource& source, const std::filesystem::path& base_dir) {
  ShaderSettings s;
  s.key = o.path();
  const std::string program = o.string("program");
  o.describe("program", "one of builtin, twins, custom");
  if (program == "builtin") s.program = ShaderProgram::Builtin;
  else if (program == "twins") s.program = ShaderProgram::Twins;
  else if (program == "custom") s.program = ShaderProgram::Custom;
  else o.fail("program", "expected one of builtin, twins, custom, got \"" + program + "\"");
  auto path = [&](const char* key) -> std::filesystem::path {
    o.describe(key, "a GLSL file relative to the scene file, or \"twin:NAME\"");
    if (!o.has(key)) return {};
    const std::string s = o.string(key);
    if (s.rfind("twin:", 0) == 0) return s;  // a built-in program's GLSL twin (stages/glsl/twins.h)
    std::filesystem::path p = s;
    return p.is_relative() ? base_dir / p : p;
  };
  s.vertex = path("vertex");
  s.tess_control = path("tess_control");
  s.tess_evaluation = path("tess_evaluation");
  s.geometry = path("geometry");
  s.fragment = path("fragment");
  if (s.program == ShaderProgram::Custom)
    for (const char* key : {"vertex", "fragment"})
      if (path(key).empty())
        o.fail(key, "required when shaders.program is \"custom\" (a GLSL file relative to the scene file)");
  o.describe("uniforms", "an object of uniform name (a GL name: \"u\", \"u[2]\", \"lights[1].color\"): number, boolean, "
                         "array, or for a struct an object of its members (an array of such objects for an array of structs)");
  const nlohmann::json& uniforms = o.value("uniforms");
  if (!uniforms.is_object()) o.fail("uniforms", "expected an object of name: value, got " + describe_json(uniforms));
  // Structs and arrays of structs are given as JSON objects (and arrays of them): each leaf becomes
  // the uniform of its GL name, "name.member" or "name[i].member", as an application sets them.
  std::function<void(const std::string&, const nlohmann::json&)> read_uniform = [&](const std::string& name,
                                                                                    const nlohmann::json& value) {
    if (value.is_object()) {
      if (value.empty()) o.fail("uniforms." + name, "has no value (an empty struct)");
      for (const auto& [member, v] : value.items()) read_uniform(name + "." + member, v);
      return;
    }
    if (value.is_array() && !value.empty() && value[0].is_object()) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        if (!value[i].is_object())
          o.fail("uniforms." + name, "an array of structs takes an object per element; element " + std::to_string(i) +
                                     " is " + describe_json(value[i]));
        read_uniform(name + "[" + std::to_string(i) + "]", value[i]);
      }
      return;
    }
    UniformSetting u{name, {}, false};
    auto add = [&](const nlohmann::json& v) {
      if (v.is_boolean()) {
        u.boolean = true;
        u.values.push_back(v.get<bool>() ? 1.0 : 0.0);
      } else if (v.is_number() && std::isfinite(v.get<double>())) {
        u.values.push_back(v.get<double>());
      } else {
        o.fail("uniforms." + u.name, "expected numbers or booleans (a vector as an array, a matrix as an "
                                   "array of columns, a struct as an object), got " + describe_json(v));
      }
    };
    if (value.is_array()) {
      for (const auto& e : value) {
        if (e.is_array()) for (const auto& x : e) add(x);
        else add(e);
      }
    } else {
      add(value);
    }
    if (u.values.empty()) o.fail("uniforms." + name, "has no value");
    s.uniforms.push_back(std::move(u));
  };
  for (const auto& [name, value] : uniforms.items()) read_uniform(name, value);
  o.describe("attributes", "an object of vertex input name: \"position\" or \"normal\"");
  const nlohmann::json& attributes = o.value("attributes");
  if (!attributes.is_object()) o.fail("attributes", "expected an object of input name: attribute, got " + describe_json(attributes));
  for (const auto& [name, value] : attributes.items()) {
    if (!value.is_string() || (value != "position" && value != "normal"))
      o.fail("attributes." + name, "expected \"position\" or \"normal\", got " + describe_json(value));
    s.attributes.push_back({name, value.get<std::string>()});
  }
  o.describe("textures", "an object of sampler name: image file or {target, path, levels or layers, internalformat, "
                         "raw_size, generate_mipmap, filter, min_filter, mag_filter, wrap, wrap_s, wrap_t, border_color, "
                         "min_lod, max_lod, lod_bias, base_level, max_level, swizzle, compare_mode, compare_func, sampler}, "
                         "or {target: GL_TEXTURE_BUFFER, buffer, internalformat, offset, size}");
  if (o.has("textures")) {
    const nlohmann::json& textures = o.value("textures");
    if (!textures.is_object())
      o.fail("textures", "expected an object of sampler name: image file, got " + describe_json(textures));
    for (const auto& [name, value] : textures.items())
      s.textures.push_back(read_texture_setting(name, value, o.path_of("textures") + "." + name, source, base_dir));
  }
  s.patch_vertices = o.integer("patch_vertices", 1, 32);
  // Optional, not in the default scene: captures' manifests hold the whole resolved scene, and a
  // key added to the default would make every earlier capture's scene differ.
  o.describe("scene_uniforms", "a boolean (default true): the camera, lights and material set the uniforms of the twins' names");
  s.scene_uniforms = o.has("scene_uniforms") ? o.boolean("scene_uniforms") : true;
  s.batch_lanes = o.integer("batch_lanes", 1, shader::kMaxLanes);
  s.max_instructions = std::uint64_t(o.integer("max_instructions", 1, std::numeric_limits<int>::max()));
  o.finish();
  return s;
}

Scene scene_from_json(const json& root_json, const JsonSource& source,
                      const std::filesystem::path& mesh_base_dir) {
  JsonObject root(root_json, "", source);
  Scene s;
  s.source = source.name;
  if (root.has("description")) root.string("description");
  root.describe("description", "a string (ignored)");
  s.mesh = read_mesh(root.object("mesh"), mesh_base_dir);
  s.transform = read_transform(root.object("transform"));
  s.camera = read_camera(root.object("camera"));
  s.lights = read_lights(root, source);
  s.material = read_material(root.object("material"));
  JsonObject image = root.object("image");
  s.width = image.integer("width", 1, kMaxImageSide);
  s.height = image.integer("height", 1, kMaxImageSide);
  if (static_cast<long long>(s.width) * s.height > kMaxImagePixels)
    image.fail("height", std::to_string(s.width) + " x " + std::to_string(s.height) +
                             " pixels is more than the limit of " +
                             std::to_string(kMaxImagePixels) + " (8192 x 8192)");
  image.finish();
  s.background = root.rgba("background");
  s.shading = enum_value<Shading>(root, "shading", "phong, normals");
  s.cull_back_faces = root.boolean("cull_back_faces");
  s.polygon_mode = enum_value<PolygonMode>(root, "polygon_mode", "GL_FILL, GL_LINE, GL_POINT");
  s.tessellation = read_tessellation(root.object("tessellation"));
  s.shaders = read_shaders(root.object("shaders"), source, mesh_base_dir);
  const bool has_framebuffer = root.has("framebuffer");
  read_draw_keys(root, source, mesh_base_dir, s.shaders, s.buffers, s.draws, s.framebuffer);
  if (has_framebuffer && s.draws.empty())
    source.fail("framebuffer", "takes a scene of draws (the mesh path draws into RGBA32F colour and float depth)",
                {"framebuffer", "draws"});
  for (const DrawSetting& d : s.draws)
    if (!d.shaders && s.shaders.program != ShaderProgram::Custom)
      source.fail(d.key, "has no shaders of its own, so the scene's GLSL program draws it: set shaders.program to \"custom\" or give the draw its own shaders",
                  {d.key, "shaders.program"});
  if (s.tessellation.tags.is_relative() && !s.tessellation.tags.empty())
    s.tessellation.tags = mesh_base_dir / s.tessellation.tags;
  // The GLSL path's TES may declare any domain; uniform subdivision is plumbed for the built-in
  // programs only.
  if (s.tessellation.enabled && s.tessellation.tessellator != Tessellator::PrimitiveGenerator &&
      s.shaders.program != ShaderProgram::Builtin)
    source.fail("tessellation.tessellator",
                "\"" + std::string(to_string(s.tessellation.tessellator)) +
                    "\" works with shaders.program \"builtin\" only",
                {"tessellation.tessellator", "shaders.program", "tessellation.enabled"});
  // The displacement is a block of the built-in evaluation programs and of their twins; a custom
  // TES displaces in its own code (scenes/displacement.json).
  if (s.tessellation.displacement.enabled &&
      (!s.tessellation.enabled || s.shaders.program == ShaderProgram::Custom))
    source.fail("tessellation.displacement",
                "needs tessellation.enabled and shaders.program \"builtin\" or \"twins\"",
                {"tessellation.displacement", "tessellation.enabled", "shaders.program"});
  root.finish();
  return s;
}

}  // namespace tessref
