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

// shaders.textures: each image on its own texture unit (its index), the sampler uniform set to
// that unit.
void bind_textures(const Scene& scene, const ShaderSettings& shaders, glsl::GlslProgram& program, SceneProgram& out) {
  std::uint32_t unit = 0;
  for (const TextureSetting& t : shaders.textures) {
    const std::string key = scene.source + ": " + shaders.key + ".textures." + t.sampler;
    const auto shape = program.uniform_shape(t.sampler);
    if (!shape || shape->glsl_name.find("sampler") == std::string::npos)
      throw InputError(key + ": the program has no active sampler uniform of that name" +
                       (shape ? " (it is a " + shape->glsl_name + ")" : std::string()));
    const std::string& type = shape->glsl_name;
    // The sampler's dimensions and shadow suffix without the i or u of its sampled type.
    const std::string dims = type.substr(type[0] == 's' ? 0 : 1);
    const bool shadow = dims.ends_with("Shadow"), array = dims.starts_with("sampler2DArray");
    if (dims != "sampler2D" && dims != "sampler2DShadow" && dims != "sampler2DArray" && dims != "sampler2DArrayShadow")
      throw InputError(key + ": the uniform is " + with_article(type) + ", but textures are 2D images (GL_TEXTURE_2D) "
                       "or 2D arrays (GL_TEXTURE_2D_ARRAY); GL draws nothing from a sampler whose unit holds a texture "
                       "of another target");
    auto tex = std::make_unique<texture::Texture>(load_texture(t, key));
    if (tex->array != array)
      throw InputError(key + ".target: the uniform is " + with_article(type) + ", which reads a " +
                       (array ? "GL_TEXTURE_2D_ARRAY" : "GL_TEXTURE_2D") + " texture, and this one is " +
                       (tex->array ? "GL_TEXTURE_2D_ARRAY" : "GL_TEXTURE_2D") +
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
  set_scene_uniforms(scene, *program);
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

namespace {

const char* channels_name(int channels) {
  switch (channels) {
    case 1: return "gray (1 channel)";
    case 2: return "gray and alpha (2 channels)";
    case 3: return "RGB (3 channels)";
    default: return "RGBA (4 channels)";
  }
}

// An image's pixels as RGBA rows from the bottom (GL's order): gray repeated in R, G and B
// (GL_RGBA32F from a gray file) or kept in R (an R format), alpha 1 where the file has none.
std::vector<float> rgba_rows(const FloatImage& image, bool gray_to_rgb) {
  std::vector<float> out(std::size_t(image.width) * std::size_t(image.height) * 4);
  const int ch = image.channels;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* src = image.pixels.data() + (std::size_t(image.height - 1 - y) * std::size_t(image.width) + std::size_t(x)) * std::size_t(ch);
      float* dst = out.data() + (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
      if (ch <= 2) {
        dst[0] = src[0];
        dst[1] = gray_to_rgb ? src[0] : ch == 2 ? src[1] : 0.0f;
        dst[2] = gray_to_rgb ? src[0] : 0.0f;
        dst[3] = ch == 2 && gray_to_rgb ? src[1] : 1.0f;
      } else {
        for (int c = 0; c < 4; ++c) dst[c] = c < ch ? src[c] : 1.0f;
      }
    }
  return out;
}

// An integer format's texels from an image file (GL uploads them as integers, GL 4.6 8.4.4.2):
// an 8- or 16-bit file's stored integers k (read as k / (2^b - 1)), a float file's values, which
// must be whole numbers; each within the format's range.
std::vector<std::int64_t> integer_texels(const FloatImage& image, const std::vector<float>& rgba,
                                         const texture::TexelFormatInfo& format, const std::filesystem::path& file,
                                         const std::string& at) {
  const double scale = image.stored_float ? 1.0 : std::ldexp(1.0, image.stored_bits) - 1.0;
  std::vector<std::int64_t> out(rgba.size());
  for (std::size_t k = 0; k < rgba.size(); ++k) {
    const double v = double(rgba[k]) * scale;
    const int c = int(k % 4);
    if (c >= format.channels) {  // not stored: alpha 1 and 0 for the others, as decoded
      out[k] = c == 3 ? 1 : 0;
      continue;
    }
    const double whole = std::nearbyint(v);
    if (!(std::fabs(v - whole) <= (image.stored_float ? 0.0 : 1e-3)) || whole < double(format.integer_min(c)) ||
        whole > double(format.integer_max(c))) {
      const std::size_t texel = k / 4;
      const std::size_t x = texel % std::size_t(image.width), y = std::size_t(image.height) - 1 - texel / std::size_t(image.width);
      char value[64];
      std::snprintf(value, sizeof value, "%.9g", v);
      throw InputError(at + ": " + file.string() + " pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                       ") channel " + std::to_string(c) + " is " + value + ", and " + format.gl_name +
                       " holds whole numbers from " + std::to_string(format.integer_min(c)) + " to " +
                       std::to_string(format.integer_max(c)) + " (internalformat; give a float file of whole "
                       "numbers, an 8/16-bit file's integers, or raw bytes with raw_size)");
    }
    out[k] = std::int64_t(whole);
  }
  return out;
}

// Level k of a texture whose level 0 is w x h with `layers` layers, from a file of raw texel
// bytes in format f.
texture::Level read_raw_level(const std::filesystem::path& file, texture::TexelFormat f, std::array<int, 3> size0, int k,
                              const std::string& at) {
  const texture::TexelFormatInfo& fi = texture::info(f);
  const int w = size0[0], h = size0[1];
  if (k > 0 && std::max(w, h) >> k == 0)
    throw InputError(at + ": a " + std::to_string(w) + "x" + std::to_string(h) + " texture has no level " + std::to_string(k));
  const int width = std::max(1, w >> k), height = std::max(1, h >> k), layers = size0[2];
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(at + ": cannot open " + file.string());
  std::vector<std::uint8_t> stored{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::size_t want = std::size_t(width) * std::size_t(height) * std::size_t(layers) * std::size_t(fi.bytes_per_texel());
  if (stored.size() != want)
    throw InputError(at + ": " + file.string() + " has " + std::to_string(stored.size()) + " bytes, and level " +
                     std::to_string(k) + " of " + fi.gl_name + " is " + std::to_string(width) + "x" + std::to_string(height) +
                     (layers > 1 ? "x" + std::to_string(layers) : "") + " texels of " + std::to_string(fi.bytes_per_texel()) +
                     " bytes: " + std::to_string(want) + " (raw_size)");
  // GL_DEPTH_COMPONENT24 words as GL_UNSIGNED_INT: the top 24 bits are the depth; the low byte is
  // made to repeat them, so the driver's conversion cannot round differently.
  if (f == texture::TexelFormat::kDepth24)
    for (std::size_t i = 0; i + 4 <= stored.size(); i += 4) {
      std::uint32_t word;
      std::memcpy(&word, &stored[i], 4);
      word = (word & 0xffffff00u) | (word >> 24);
      std::memcpy(&stored[i], &word, 4);
    }
  return texture::level_from_stored(f, width, height, layers, std::move(stored));
}

// One image file's texels for a texture of `format` (declared when `declared`), RGBA rows from the
// bottom: floats, or for an integer format integers (and no floats).
struct ImageTexels {
  int width = 0, height = 0;
  std::vector<float> rgba;
  std::vector<std::int64_t> integers;
};
ImageTexels read_image_texels(const std::filesystem::path& file, const texture::TexelFormatInfo& format, bool declared,
                              const std::string& at) {
  FloatImage image;
  try {
    image = read_float_image(file);
  } catch (const InputError& e) {
    throw InputError(at + ": " + e.what());
  }
  if (declared && image.channels != format.channels)
    throw InputError(at + ": " + file.string() + " is " + channels_name(image.channels) + ", and " + format.gl_name +
                     " has " + std::to_string(format.channels) + " channel" + (format.channels > 1 ? "s" : "") +
                     " (internalformat)");
  using texture::kMaxTextureSize;
  if (image.width > kMaxTextureSize || image.height > kMaxTextureSize)
    throw InputError(at + ": " + file.string() + " is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                     ", more than GL_MAX_TEXTURE_SIZE (" + std::to_string(kMaxTextureSize) + ")");
  ImageTexels out;
  out.width = image.width;
  out.height = image.height;
  out.rgba = rgba_rows(image, !declared);
  if (format.integer()) {
    out.integers = integer_texels(image, out.rgba, format, file, at);
    out.rgba = {};
  }
  return out;
}

// Layers of one level, each width x height, as a level of format f (one layer is not copied).
texture::Level level_of_layers(texture::TexelFormat f, std::vector<ImageTexels> layers) {
  const int w = layers[0].width, h = layers[0].height, n = int(layers.size());
  auto joined = [&](auto member) {
    auto all = std::move(layers[0].*member);
    for (std::size_t k = 1; k < layers.size(); ++k) all.insert(all.end(), (layers[k].*member).begin(), (layers[k].*member).end());
    return all;
  };
  if (texture::info(f).integer()) return texture::make_integer_level(f, w, h, joined(&ImageTexels::integers).data(), n);
  return texture::make_level(f, w, h, joined(&ImageTexels::rgba).data(), n);
}

}  // namespace

texture::Texture load_texture(const TextureSetting& t, const std::string& key) {
  texture::Texture tex;
  tex.array = t.array;
  tex.format = t.format.value_or(texture::TexelFormat::kRgba32F);
  const texture::TexelFormatInfo& format = texture::info(tex.format);
  if (!t.layers.empty()) {  // an array's level 0, one file per layer
    std::vector<ImageTexels> layers;
    for (std::size_t k = 0; k < t.layers.size(); ++k) {
      const std::string at = key + ".layers." + std::to_string(k);
      layers.push_back(read_image_texels(t.layers[k], format, t.format.has_value(), at));
      if (layers[k].width != layers[0].width || layers[k].height != layers[0].height)
        throw InputError(at + ": " + t.layers[k].string() + " is " + std::to_string(layers[k].width) + "x" +
                         std::to_string(layers[k].height) + ", and layer 0 is " + std::to_string(layers[0].width) + "x" +
                         std::to_string(layers[0].height) + " (an array's layers are one size)");
    }
    tex.levels.push_back(level_of_layers(tex.format, std::move(layers)));
  }
  int width0 = 0, height0 = 0;
  for (std::size_t k = 0; k < t.levels.size(); ++k) {
    const std::string at = t.levels.size() > 1 ? key + ".levels." + std::to_string(k) : key;
    if (t.raw_size) {
      tex.levels.push_back(read_raw_level(t.levels[k], tex.format, *t.raw_size, int(k), at));
      continue;
    }
    std::vector<ImageTexels> level;  // one layer
    level.push_back(read_image_texels(t.levels[k], format, t.format.has_value(), at));
    const ImageTexels& image = level[0];
    if (k == 0) {
      width0 = image.width;
      height0 = image.height;
    }
    // glTexStorage2D fixes level k's size from level 0's (GL 4.6 8.19).
    const int w = std::max(1, width0 >> k), h = std::max(1, height0 >> k);
    if (image.width != w || image.height != h || (k > 0 && std::max(width0, height0) >> k == 0))
      throw InputError(at + ": level " + std::to_string(k) + " is " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + ", and a level " + std::to_string(k) + " of a " +
                       std::to_string(width0) + "x" + std::to_string(height0) + " texture is " +
                       (std::max(width0, height0) >> k == 0 ? std::string("past its last level")
                                                            : std::to_string(w) + "x" + std::to_string(h)));
    tex.levels.push_back(level_of_layers(tex.format, std::move(level)));
  }
  // glGenerateMipmap right after level 0 is uploaded, before any glTexParameter: every level.
  if (t.generate_mipmaps) texture::generate_mipmaps(tex);
  tex.sampler = t.sampler_object.value_or(t.sampler_state);
  tex.base_level = t.base_level;
  tex.max_level = t.max_level;
  tex.swizzle = t.swizzle;
  tex.finalize();
  return tex;
}

}  // namespace tessref
