#include "render/glsl_scene.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>

#include "common/error.h"
#include "mesh/camera.h"
#include "render/draw_call.h"
#include "render/texture_load.h"
#include "io/image_output.h"
#include "mesh/vertex_tags.h"
#include "shader/glsl_compile.h"
#include "stages/glsl/twins.h"
#include "stages/programs/transform.h"
#include "stages/tess_levels_adaptive.h"
#include "texture/mipmap.h"

namespace tessref {
namespace {

using shader::Scalar;
using shader::Stage;

std::string read_file(const Scene& scene, const ShaderSettings& s, const char* key, const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (!in || !(text << in.rdbuf()))
    throw InputError(scene.source + ": " + s.key + "." + key + ": cannot read '" + path.string() + "'");
  return text.str();
}

glsl::UniformValue floats(std::initializer_list<float> v, int columns = 1, int rows = 0) {
  glsl::UniformValue u;
  u.scalar = Scalar::F32;
  u.columns = columns;
  u.rows = rows ? rows : int(v.size()) / columns;
  for (float x : v) u.words.push_back(std::bit_cast<std::uint32_t>(x));
  return u;
}
glsl::UniformValue vec(const float* p, int n) {
  glsl::UniformValue u;
  u.rows = n;
  for (int i = 0; i < n; ++i) u.words.push_back(std::bit_cast<std::uint32_t>(p[i]));
  return u;
}
glsl::UniformValue mat(const float* p, int columns, int rows) {
  glsl::UniformValue u = vec(p, columns * rows);
  u.columns = columns;
  u.rows = rows;
  return u;
}
glsl::UniformValue integer(int v, Scalar s = Scalar::I32) {
  glsl::UniformValue u;
  u.scalar = s;
  u.words.push_back(std::uint32_t(v));
  return u;
}

// The scene uniforms: every uniform the GLSL twins read, with the values render_scene gives the
// C++ programs (as the real-GL runner sets them, glref/scene_renderer.cpp).
void set_scene_uniforms(const Scene& scene, glsl::GlslProgram& program) {
  const std::vector<std::string> names = program.uniform_names();
  auto set = [&](const std::string& name, const glsl::UniformValue& v) {
    const std::string base = name.substr(0, name.find('['));
    if (std::binary_search(names.begin(), names.end(), base)) program.set_uniform(name, v);
  };
  const glm::mat4 view_proj =
      projection_matrix(scene.camera, scene.width, scene.height) * view_matrix(scene.camera);
  const auto vs = programs::TransformVertexShader::from(model_matrix(scene.transform), view_proj);
  set("u_model", mat(&vs.u_model[0][0], 4, 4));
  set("u_view_projection", mat(&vs.u_view_projection[0][0], 4, 4));
  set("u_normal_matrix", mat(&vs.u_normal_matrix[0][0], 3, 3));
  set("u_view_proj", mat(&vs.u_view_projection[0][0], 4, 4));
  const TessellationSettings& t = scene.tessellation;
  const AdaptiveLevelSettings screen;
  set("u_normal_mode", integer(glsl_index(t.normal_mode)));
  set("u_phong_alpha", floats({t.phong_alpha}));
  set("u_nagata_eps", floats({t.nagata_eps}));
  set("u_adaptive", integer(t.adaptive.enabled ? 1 : 0, Scalar::Bool));
  set("u_outer", vec(t.levels.outer.data(), 4));
  set("u_inner", vec(t.levels.inner.data(), 2));
  set("u_viewport", floats({float(scene.width), float(scene.height)}));
  set("u_pixels_per_segment", floats({t.adaptive.pixels_per_segment}));
  set("u_min_level", floats({screen.min_level}));
  set("u_max_level", floats({screen.max_level}));
  set("u_inner_rule", integer(screen.inner_rule == InnerLevelRule::Max ? 0 : 1));
  set("u_displacement", integer(t.displacement.enabled ? 1 : 0, Scalar::Bool));
  set("u_displacement_amplitude", floats({t.displacement.amplitude}));
  set("u_displacement_frequency", floats({t.displacement.frequency}));
  set("u_eye", vec(&scene.camera.eye.x, 3));
  set("u_num_lights", integer(int(scene.lights.size())));
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    set("u_light_position[" + std::to_string(i) + "]", vec(&scene.lights[i].position.x, 3));
    set("u_light_intensity[" + std::to_string(i) + "]", vec(&scene.lights[i].intensity.x, 3));
  }
  set("u_ka", floats({scene.material.ka}));
  set("u_kd", floats({scene.material.kd}));
  set("u_ks", floats({scene.material.ks}));
  set("u_shininess", floats({scene.material.shininess}));
  set("u_color", vec(&scene.material.color.x, 3));
}

// shaders.uniforms: the scene's numbers in the uniform's own GLSL type.
void set_user_uniforms(const Scene& scene, const ShaderSettings& shaders, glsl::GlslProgram& program) {
  for (const UniformSetting& u : shaders.uniforms) {
    const std::string key = scene.source + ": " + shaders.key + ".uniforms." + u.name;
    const auto shape = program.uniform_shape(u.name);
    if (!shape) {
      std::string active;
      for (const std::string& n : program.uniform_names()) active += (active.empty() ? "" : ", ") + n;
      throw InputError(key + ": the program has no active uniform of that name (active: " +
                       (active.empty() ? "none" : active) + ")");
    }
    if (shape->is_struct) {
      std::string members;
      for (const std::string& m : shape->members) members += (members.empty() ? "" : ", ") + m;
      throw InputError(key + ": the uniform is a " + shape->glsl_name + ": give an object of its members (" + members +
                       ")" + (shape->elements > 1 ? ", one per element" : ""));
    }
    glsl::UniformValue v;
    v.scalar = shape->scalar;
    v.columns = shape->columns;
    v.rows = shape->rows;
    const std::size_t want = std::size_t(shape->columns * shape->rows * shape->elements);
    const std::size_t one = std::size_t(shape->columns * shape->rows);
    if (u.values.size() != want && u.values.size() != one) {
      const bool element = u.name.back() == ']';
      throw InputError(key + ": the uniform is a " + shape->glsl_name + ", which takes " +
                       (element && want != one ? std::to_string(one) + " values (this element) or " + std::to_string(want) +
                                                     " (the elements from it to the end of the array)"
                                               : std::to_string(want) + " values") +
                       ", got " + std::to_string(u.values.size()));
    }
    if (u.boolean != (shape->scalar == Scalar::Bool))
      throw InputError(key + ": the uniform is a " + shape->glsl_name + (u.boolean ? ", not a bool" : ", give true or false"));
    for (double x : u.values) {
      switch (shape->scalar) {
        case Scalar::F32: v.words.push_back(std::bit_cast<std::uint32_t>(float(x))); break;
        case Scalar::F64: {
          const auto b = std::bit_cast<std::uint64_t>(x);
          v.words.push_back(std::uint32_t(b));
          v.words.push_back(std::uint32_t(b >> 32));
          break;
        }
        case Scalar::Bool: v.words.push_back(x != 0.0 ? 1u : 0u); break;
        default: {
          const bool is_unsigned = shape->scalar == Scalar::U32;
          if (x != std::floor(x) || x < (is_unsigned ? 0.0 : -2147483648.0) || x > (is_unsigned ? 4294967295.0 : 2147483647.0))
            throw InputError(key + ": the uniform is a " + shape->glsl_name + "; " + std::to_string(x) +
                             " is not a 32-bit " + (is_unsigned ? "unsigned " : "") + "integer");
          v.words.push_back(is_unsigned ? std::uint32_t(x) : std::uint32_t(std::int32_t(x)));
        }
      }
    }
    program.set_uniform(u.name, v);
  }
}

// "an isampler2D", "a usampler2D", "a sampler2D": a GLSL type named in a sentence.
std::string with_article(const std::string& type) { return (type[0] == 'i' ? "an " : "a ") + type; }

// The target a sampler type (without its i or u prefix and Shadow suffix) reads.
std::optional<texture::Target> sampler_target(const std::string& dims) {
  if (dims == "sampler1D") return texture::Target::k1D;
  if (dims == "sampler2D") return texture::Target::k2D;
  if (dims == "sampler1DArray") return texture::Target::k1DArray;
  if (dims == "sampler2DArray") return texture::Target::k2DArray;
  if (dims == "sampler3D") return texture::Target::k3D;
  if (dims == "sampler2DRect") return texture::Target::kRectangle;
  if (dims == "samplerBuffer") return texture::Target::kBuffer;
  if (dims == "samplerCube") return texture::Target::kCube;
  if (dims == "samplerCubeArray") return texture::Target::kCubeArray;
  return std::nullopt;
}

// A texture named for an image uniform (image2D ...): its level 0 bound to the next image unit, as
// glBindImageTexture(unit, texture, 0, GL_TRUE, 0, GL_READ_WRITE, format) with the format the image
// declares, which must be the texture's own (GL also takes formats of the same size; tessref
// refuses them by name).
void bind_image(const Scene& scene, const TextureSetting& t, const std::string& key, const std::string& type,
                std::uint32_t unit, glsl::GlslProgram& program, SceneProgram& out) {
  const std::string dims = "sampler" + type.substr(type.find("image") + 5);
  const std::optional<texture::Target> target = sampler_target(dims);
  if (!target || texture::is_cube(*target))
    throw InputError(key + ": the uniform is " + with_article(type) + "; tessref's images are the 1D, 2D, 3D, "
                     "rectangle, buffer and array forms (not cube maps or multisample images)");
  auto tex = std::make_unique<texture::Texture>(load_texture(t, key, scene));
  if (tex->target != *target)
    throw InputError(key + ".target: the uniform is " + with_article(type) + ", which reads a " +
                     texture::gl_name(*target) + " texture, and this one is " + texture::gl_name(tex->target));
  const std::optional<texture::TexelFormat> declared = program.image_format(t.sampler);
  if (!declared)
    throw InputError(key + ": the image's format qualifier is one tessref's textures do not have");
  if (*declared != tex->format)
    throw InputError(key + ".internalformat: the image is declared " + texture::info(*declared).gl_name +
                     " and the texture is " + texture::info(tex->format).gl_name +
                     "; tessref binds an image of its texture's own format");
  program.bind_image(unit, tex.get());
  program.set_uniform(t.sampler, integer(int(unit)));
  out.images.emplace_back(t.sampler, tex.get());
  out.textures.push_back(std::move(tex));
}

// shaders.textures: each image on its own texture unit (its index), the sampler uniform set to
// that unit; images (image2D ...) on image units of their own (bind_image).
void bind_textures(const Scene& scene, const ShaderSettings& shaders, glsl::GlslProgram& program, SceneProgram& out) {
  std::uint32_t unit = 0, image_unit = 0;
  for (const TextureSetting& t : shaders.textures) {
    const std::string key = scene.source + ": " + shaders.key + ".textures." + t.sampler;
    const auto shape = program.uniform_shape(t.sampler);
    if (shape && shape->glsl_name.find("image") != std::string::npos) {
      bind_image(scene, t, key, shape->glsl_name, image_unit++, program, out);
      continue;
    }
    if (!shape || shape->glsl_name.find("sampler") == std::string::npos)
      throw InputError(key + ": the program has no active sampler uniform of that name" +
                       (shape ? " (it is a " + shape->glsl_name + ")" : std::string()));
    const std::string& type = shape->glsl_name;
    // The sampler's dimensions and shadow suffix without the i or u of its sampled type.
    const std::string dims = type.substr(type[0] == 's' ? 0 : 1);
    const bool shadow = dims.ends_with("Shadow");
    const std::optional<texture::Target> target = sampler_target(shadow ? dims.substr(0, dims.size() - 6) : dims);
    if (!target)
      throw InputError(key + ": the uniform is " + with_article(type) + ", and tessref's textures are GL_TEXTURE_1D, "
                       "GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, their arrays, GL_TEXTURE_3D, GL_TEXTURE_RECTANGLE and "
                       "GL_TEXTURE_BUFFER; GL draws "
                       "nothing from a sampler whose unit holds a texture of another target");
    auto tex = std::make_unique<texture::Texture>(load_texture(t, key, scene));
    if (tex->target != *target)
      throw InputError(key + ".target: the uniform is " + with_article(type) + ", which reads a " +
                       texture::gl_name(*target) + " texture, and this one is " + texture::gl_name(tex->target) +
                       "; GL draws nothing from a sampler whose unit holds a texture of another target");
    // GLSL 4.60 8.9 and GL 4.6 8.23.1 leave these lookups undefined: refused, not guessed.
    const texture::TexelFormatInfo& format = texture::info(tex->format);
    const std::string wanted = format.signed_integer() ? "i" + dims : format.unsigned_integer() ? "u" + dims : "";
    if (!wanted.empty() && type != wanted)
      throw InputError(key + ".internalformat: " + format.gl_name + " is an integer format, read by " + with_article(wanted) +
                       ", and the uniform is " + with_article(type) + " (GL leaves the result undefined)");
    if (wanted.empty() && type[0] != 's')
      throw InputError(key + ".internalformat: the uniform is " + with_article(type) + ", which reads " +
                       (type[0] == 'i' ? "signed" : "unsigned") + " integer formats (GL_R8I .. GL_RGBA32" +
                       (type[0] == 'i' ? "I" : "UI") + "), not " + format.gl_name + " (GL leaves the result undefined)");
    if (shadow && !format.depth)
      throw InputError(key + ".internalformat: the uniform is " + with_article(type) + ", which needs a depth format "
                       "(GL_DEPTH_COMPONENT16, 24, 32F or GL_DEPTH24_STENCIL8), not " + std::string(format.gl_name) +
                       " (GL leaves the result undefined)");
    if (shadow && !tex->sampler.compare)
      throw InputError(key + ".compare_mode: the uniform is " + with_article(type) + ", so give \"compare_ref_to_texture\" "
                       "(with GL_NONE GL leaves a shadow lookup's result undefined)");
    if (!shadow && tex->sampler.compare)
      throw InputError(key + ".compare_mode: the uniform is " + with_article(type) + ", which GL leaves undefined with "
                       "GL_COMPARE_REF_TO_TEXTURE: use a " + type + "Shadow, or \"none\"");
    // GL 4.6 11.1.3.5: an incomplete texture reads (0, 0, 0, 1); the draw goes on, as on a driver.
    if (!tex->complete)
      out.warnings.push_back(key + ": the texture is incomplete, so it reads (0, 0, 0, 1): " + tex->incomplete_reason);
    program.bind_texture(unit, tex.get());
    program.set_uniform(t.sampler, integer(int(unit)));
    out.textures.push_back(std::move(tex));
    ++unit;
  }
}

// The last program compiled, by its sources: repeated frames (--repeat, benchmarks) of one scene
// compile once.
shader::CompiledProgram compile_cached(const std::vector<shader::ShaderSource>& sources) {
  static std::mutex mutex;
  static std::string last_key;
  static shader::CompiledProgram last;
  std::string key;
  for (const shader::ShaderSource& s : sources)
    key += std::to_string(int(s.stage)) + '\0' + s.file + '\0' + std::to_string(s.first_line) + '\0' + s.text + '\0';
  const std::lock_guard<std::mutex> lock(mutex);
  if (key != last_key) {
    last = shader::compile_program(sources);
    last_key = std::move(key);
  }
  return last;
}

}  // namespace

std::vector<shader::ShaderSource> scene_sources(const Scene& scene) { return scene_sources(scene, scene.shaders); }

std::vector<shader::ShaderSource> scene_sources(const Scene& scene, const ShaderSettings& s) {
  std::vector<shader::ShaderSource> out;
  if (s.program == ShaderProgram::Twins) {
    auto twin = [&](Stage stage, const std::string& name) {
      out.push_back({stage, name, 1, glsl::twin_source(name)});
    };
    const SchemeTwins scheme = scheme_twins(scene.tessellation.scheme);
    // Scalar Tagged PN's control shader reads the tags the vertex stage hands on.
    const bool tagged = scene.tessellation.enabled && scene.tessellation.scheme == SurfaceScheme::ScalarTaggedPN;
    twin(Stage::Vertex, tagged ? "tagged_transform.vert" : "transform.vert");
    if (scene.tessellation.enabled) {
      twin(Stage::TessControl, scheme.tess_control);
      twin(Stage::TessEval, scheme.tess_evaluation);
    }
    twin(Stage::Fragment, scene.shading == Shading::Phong ? "phong.frag" : "normals.frag");
    return out;
  }
  auto file = [&](Stage stage, const char* key, const std::filesystem::path& path) {
    if (path.empty()) return;
    const std::string name = path.string();
    if (name.rfind("twin:", 0) == 0) {
      try {
        out.push_back({stage, name.substr(5), 1, glsl::twin_source(name.substr(5))});
      } catch (const std::invalid_argument& e) {
        throw InputError(scene.source + ": " + s.key + "." + key + ": " + e.what());
      }
      return;
    }
    out.push_back({stage, name, 1, read_file(scene, s, key, path)});
  };
  file(Stage::Vertex, "vertex", s.vertex);
  file(Stage::TessControl, "tess_control", s.tess_control);
  file(Stage::TessEval, "tess_evaluation", s.tess_evaluation);
  file(Stage::Geometry, "geometry", s.geometry);
  file(Stage::Fragment, "fragment", s.fragment);
  return out;
}

SceneProgram build_scene_program(const Scene& scene) { return build_scene_program(scene, scene.shaders); }

SceneProgram build_scene_program(const Scene& scene, const ShaderSettings& shaders,
                                 const shader::StorageBufferSizes& storage) {
  const std::vector<shader::ShaderSource> sources = scene_sources(scene, shaders);
  shader::ExecLimits limits;
  limits.batch_lanes = shaders.batch_lanes;
  limits.max_instructions = shaders.max_instructions;
  std::unique_ptr<glsl::GlslProgram> program;
  try {
    program = std::make_unique<glsl::GlslProgram>(compile_cached(sources), limits, storage);
  } catch (const shader::SpirvError& e) {
    throw InputError(scene.source + ": " + shaders.key + ": " + e.what());
  }
  // A scene's draws name their modes (GL_PATCHES needs a tessellation evaluation shader, checked
  // per draw); the mesh path takes its mode from tessellation.enabled.
  if (scene.draws.empty() && scene.tessellation.enabled != program->has_tes())
    throw InputError(scene.source + (program->has_tes()
                                         ? ": shaders: the program has tessellation shaders but tessellation.enabled is false"
                                         : ": shaders: tessellation.enabled is true but the program has no tessellation evaluation shader"));
  // The twins' TES layout line names one spacing and winding; the scene chooses them (the
  // real-GL runner rewrites the line the same way).
  if (shaders.program == ShaderProgram::Twins && program->has_tes())
    program->override_tes_layout(TessLayout{TessDomain::Triangles, scene.tessellation.spacing,
                                            scene.tessellation.winding, false});
  if (shaders.scene_uniforms) set_scene_uniforms(scene, *program);
  set_user_uniforms(scene, shaders, *program);
  SceneProgram out;
  bind_textures(scene, shaders, *program, out);
  out.program = std::move(program);
  return out;
}

std::vector<glsl::VertexAttribute> scene_attributes(const Scene& scene, const glsl::GlslProgram& program,
                                                   const Mesh& mesh) {
  std::vector<glsl::VertexAttribute> attributes;
  for (const auto& [input, source] : scene.shaders.attributes) {
    const bool by_location = !input.empty() && input.find_first_not_of("0123456789") == std::string::npos;
    const auto location = by_location ? std::optional<std::uint32_t>(std::stoul(input)) : program.attribute_location(input);
    if (!location) continue;  // an input this program does not have (or does not use)
    const std::vector<glm::vec3>& data = source == "position" ? mesh.positions : mesh.normals;
    glsl::VertexAttribute a;
    a.location = *location;
    a.components = 3;
    for (const glm::vec3& v : data)
      for (int c = 0; c < 3; ++c) a.words.push_back(std::bit_cast<std::uint32_t>(v[c]));
    attributes.push_back(std::move(a));
  }
  // tagged_transform.vert's in_tags (location 2) and in_crease (location 3).
  if (scene.shaders.program == ShaderProgram::Twins && scene.tessellation.enabled &&
      scene.tessellation.scheme == SurfaceScheme::ScalarTaggedPN) {
    const std::vector<VertexTags> tags = load_vertex_tags(scene.tessellation, mesh);
    glsl::VertexAttribute t, c;
    t.location = 2;
    t.components = 4;
    c.location = 3;
    c.components = 3;
    for (const VertexTags& v : tags) {
      for (float x : {v.tension, v.sharpness, v.bias, 0.0f}) t.words.push_back(std::bit_cast<std::uint32_t>(x));
      for (int k = 0; k < 3; ++k) c.words.push_back(std::bit_cast<std::uint32_t>(v.crease[k]));
    }
    attributes.push_back(std::move(t));
    attributes.push_back(std::move(c));
  }
  return attributes;
}

DrawCall scene_draw_call(const Scene& scene, const Mesh& mesh) {
  DrawCall call;
  call.indices = mesh.indices;
  call.vertex_count = mesh.vertex_count();
  call.patches = scene.tessellation.enabled;
  call.patch_vertices = scene.shaders.program == ShaderProgram::Twins ? 3 : scene.shaders.patch_vertices;
  return call;
}

DrawStats draw_glsl_scene(const Scene& scene, const glsl::GlslProgram& program, const Mesh& mesh,
                          Framebuffer& fb, const Parallel& parallel, const DrawOptions& options) {
  const std::vector<glsl::VertexAttribute> attributes = scene_attributes(scene, program, mesh);
  const DrawCall call = scene_draw_call(scene, mesh);
  RasterState state;
  state.cull_back_faces = scene.cull_back_faces;
  state.polygon_mode = scene.polygon_mode;
  try {
    return run_draw(program, attributes, call, state, fb, parallel, options);
  } catch (const glsl::StageError& e) {
    throw InputError(scene.source + ": " + e.what());
  }
}

}  // namespace tessref
