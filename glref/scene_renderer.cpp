#include "glref/scene_renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <regex>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "glref/capture_wrap.h"
#include "glref/gl_context.h"
#include "glref/gl_error.h"
#include "glref/glsl_rewrite.h"
#include "glref/patch_mesh.h"
#include "glref/shader_source.h"
#include "glref/tess_capture.h"
#include "mesh/camera.h"
#include "render/initial_images.h"
#include "render/draw_scene.h"
#include "render/glsl_scene.h"
#include "mesh/vertex_tags.h"
#include "stages/programs/transform.h"
#include "stages/tess_levels_adaptive.h"

namespace tessref::glref {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

constexpr int kCaptureWords = 10;  // position 3, normal 3, tess coord 3, patch id 1

// The level settings draw_mesh gives the C++ control programs (render/draw.cpp).
TessLevelSettings level_settings(const Scene& scene, const glm::mat4& view_projection) {
  TessLevelSettings levels;
  levels.constant = scene.tessellation.levels;
  levels.adaptive = scene.tessellation.adaptive.enabled;
  levels.screen.view_proj = view_projection;
  levels.screen.viewport_pixels = glm::vec2(float(scene.width), float(scene.height));
  levels.screen.pixels_per_segment = scene.tessellation.adaptive.pixels_per_segment;
  return levels;
}

TessLayout tes_layout(const TessellationSettings& t) {
  return TessLayout{TessDomain::Triangles, t.spacing, t.winding, false};
}

// Runs the twin's main, then records gl_TessCoord and the mesh-wide patch index for capture.
std::string wrap_tes_for_capture(const std::string& tes) {
  const std::string decl = "void main()";
  const std::size_t at = tes.find(decl);
  if (at == std::string::npos || tes.find(decl, at + 1) != std::string::npos)
    throw GlError("SceneRenderer: the TES twin must have exactly one 'void main()'");
  std::string out = tes;
  out.replace(at, decl.size(), "void twin_main()");
  out = inject_after_version(
      out, "out vec3 tf_tess_coord;\nflat out int tf_patch_id;\nuniform int u_patch_base;\n");
  out += "\nvoid main() {\n  twin_main();\n  tf_tess_coord = gl_TessCoord;\n"
         "  tf_patch_id = u_patch_base + gl_PrimitiveID;\n}\n";
  return out;
}

GLenum gl_stage(shader::Stage stage) {
  switch (stage) {
    case shader::Stage::Vertex: return GL_VERTEX_SHADER;
    case shader::Stage::TessControl: return GL_TESS_CONTROL_SHADER;
    case shader::Stage::TessEval: return GL_TESS_EVALUATION_SHADER;
    case shader::Stage::Geometry: return GL_GEOMETRY_SHADER;
    default: return GL_FRAGMENT_SHADER;
  }
}

// The user's files (shaders.program custom), as tessref's executor runs them; for capture the
// evaluation shader is wrapped as the twins' is, and the geometry and fragment shaders left out.
std::vector<ShaderStage> custom_stages(const Scene& scene, const ShaderSettings& shaders, bool for_capture) {
  std::vector<ShaderStage> stages;
  for (const shader::ShaderSource& src : scene_sources(scene, shaders)) {
    // The capture records the evaluation shader's outputs by transform feedback, which a geometry
    // shader would replace with its own: the capture program ends at the evaluation shader.
    if (for_capture && (src.stage == shader::Stage::Fragment || src.stage == shader::Stage::Geometry)) continue;
    std::string text = src.text;
    if (for_capture && src.stage == shader::Stage::TessEval) text = wrap_tes_for_capture(text);
    stages.push_back({gl_stage(src.stage), text, src.file});
  }
  return stages;
}

// A draw's own stages for capture_draws_tess: the vertex and evaluation shaders wrapped
// (glref/capture_wrap.h), the geometry and fragment shaders left out.
std::vector<ShaderStage> draw_capture_stages(const Scene& scene, const ShaderSettings& shaders) {
  std::vector<ShaderStage> stages;
  for (const shader::ShaderSource& src : scene_sources(scene, shaders)) {
    if (src.stage == shader::Stage::Fragment || src.stage == shader::Stage::Geometry) continue;
    std::string text = src.text;
    if (src.stage == shader::Stage::Vertex) text = capture_vertex_shader(text);
    if (src.stage == shader::Stage::TessEval) text = capture_evaluation_shader(text);
    stages.push_back({gl_stage(src.stage), text, src.file});
  }
  return stages;
}

// The locations the driver gave a linked program's vertex inputs, to link another program with
// the same ones (the draw's vertex array object was set up for them).
AttributeLocations active_attribute_locations(unsigned program) {
  AttributeLocations out;
  GLint count = 0, longest = 0;
  glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
  glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &longest);
  std::vector<char> name(std::size_t(std::max(longest, 1)));
  for (GLint i = 0; i < count; ++i) {
    GLint size = 0;
    GLenum type = 0;
    glGetActiveAttrib(program, GLuint(i), GLsizei(name.size()), nullptr, &size, &type, name.data());
    const GLint location = glGetAttribLocation(program, name.data());
    if (location >= 0) out.push_back({name.data(), unsigned(location)});
  }
  return out;
}

// The evaluation shader's outputs at locations 0 and 1, which tessref's --dump-tess and the
// capture read as position and normal (the twins' v_world_position and v_world_normal).
std::vector<std::string> position_normal_outputs(const Scene& scene) {
  std::vector<std::string> names{"v_world_position", "v_world_normal"};
  if (scene.shaders.program != ShaderProgram::Custom) return names;
  for (const shader::ShaderSource& src : scene_sources(scene)) {
    if (src.stage != shader::Stage::TessEval) continue;
    static const std::regex out_at(R"(layout\s*\(\s*location\s*=\s*([01])\s*\)\s*out\s+\w+\s+(\w+)\s*;)");
    for (std::sregex_iterator it(src.text.begin(), src.text.end(), out_at), end; it != end; ++it)
      names[(*it)[1].str() == "0" ? 0 : 1] = (*it)[2].str();
  }
  return names;
}

// shaders.attributes: the mesh attribute each named vertex input reads (0 position, 1 normal).
AttributeLocations attribute_locations(const Scene& scene) {
  AttributeLocations out;
  for (const auto& [input, attribute] : scene.shaders.attributes)
    if (input.find_first_not_of("0123456789") != std::string::npos)
      out.push_back({input, attribute == "position" ? 0u : 1u});
  return out;
}

// tessref's GLSL twins for the scene's scheme and shading (set_uniforms gives them their values).
std::vector<ShaderStage> builtin_twin_stages(const Scene& scene, bool for_capture) {
  const TessellationSettings& t = scene.tessellation;
  // Scalar Tagged PN's control shader reads the tags the vertex stage hands on.
  const char* vs = t.enabled && t.scheme == SurfaceScheme::ScalarTaggedPN ? "tagged_transform.vert" : "transform.vert";
  std::vector<ShaderStage> stages{{GL_VERTEX_SHADER, shader_source(vs), vs}};
  if (t.enabled) {
    const SchemeTwins scheme = scheme_twins(t.scheme);
    std::string tes = set_tes_layout(shader_source(scheme.tess_evaluation), tes_layout(t));
    if (for_capture) tes = wrap_tes_for_capture(tes);
    stages.push_back({GL_TESS_CONTROL_SHADER, shader_source(scheme.tess_control), scheme.tess_control});
    stages.push_back({GL_TESS_EVALUATION_SHADER, tes, scheme.tess_evaluation});
  }
  if (!for_capture) {
    const char* fs = scene.shading == Shading::Phong ? "phong.frag" : "normals.frag";
    stages.push_back({GL_FRAGMENT_SHADER, shader_source(fs), fs});
  }
  return stages;
}

// The uniforms SceneRendererOptions::specialize compiles in, with the values set_uniforms sets.
std::vector<UniformConstant> scene_constants(const Scene& scene) {
  const TessellationSettings& t = scene.tessellation;
  auto flag = [](bool b) { return std::string(b ? "true" : "false"); };
  return {{"u_num_lights", std::to_string(scene.lights.size())},
          {"u_normal_mode", std::to_string(glsl_index(t.normal_mode))},
          {"u_adaptive", flag(t.adaptive.enabled)},
          {"u_displacement", flag(t.displacement.enabled)}};
}

// Components of one glGetTransformFeedbackVarying type (a double counts two 32-bit words);
// gl_SkipComponentsN and gl_NextBuffer report GL_NONE.
int feedback_words(GLenum type) {
  switch (type) {
    case GL_NONE: return 1;  // gl_SkipComponentsN: its size is N
    case GL_FLOAT: case GL_INT: case GL_UNSIGNED_INT: return 1;
    case GL_FLOAT_VEC2: case GL_INT_VEC2: case GL_UNSIGNED_INT_VEC2: case GL_DOUBLE: return 2;
    case GL_FLOAT_VEC3: case GL_INT_VEC3: case GL_UNSIGNED_INT_VEC3: return 3;
    case GL_FLOAT_VEC4: case GL_INT_VEC4: case GL_UNSIGNED_INT_VEC4: case GL_FLOAT_MAT2: case GL_DOUBLE_VEC2: return 4;
    case GL_FLOAT_MAT2x3: case GL_FLOAT_MAT3x2: case GL_DOUBLE_VEC3: return 6;
    case GL_FLOAT_MAT2x4: case GL_FLOAT_MAT4x2: case GL_DOUBLE_VEC4: case GL_DOUBLE_MAT2: return 8;
    case GL_FLOAT_MAT3: return 9;
    case GL_FLOAT_MAT3x4: case GL_FLOAT_MAT4x3: case GL_DOUBLE_MAT2x3: case GL_DOUBLE_MAT3x2: return 12;
    case GL_FLOAT_MAT4: case GL_DOUBLE_MAT2x4: case GL_DOUBLE_MAT4x2: return 16;
    case GL_DOUBLE_MAT3: return 18;
    case GL_DOUBLE_MAT3x4: case GL_DOUBLE_MAT4x3: return 24;
    case GL_DOUBLE_MAT4: return 32;
    default: throw GlError("transform feedback: a varying of GL type 0x" + std::to_string(type) + " the GL runner does not size");
  }
}

// Transform feedback over the draws that have it: buffers bound and the queries begun before the
// draw's calls, the bytes read back after them.
class FeedbackRecording {
 public:
  FeedbackRecording(const Scene& scene, const std::vector<Program>& programs, std::vector<FeedbackBuffers>& out)
      : scene_(scene), programs_(programs), out_(out) {
    glGenQueries(8, queries_);
  }
  ~FeedbackRecording() {
    glDeleteQueries(8, queries_);
    if (!buffers_.empty()) glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
  }
  FeedbackRecording(const FeedbackRecording&) = delete;
  FeedbackRecording& operator=(const FeedbackRecording&) = delete;

  void around(std::size_t d, bool begin) {
    const DrawSetting& draw = scene_.draws[d];
    if (!draw.transform_feedback) return;
    const GLuint program = programs_[d].id();
    if (begin) {
      const TransformFeedbackSetting& t = *draw.transform_feedback;
      buffers_.resize(t.buffers());
      glGenBuffers(GLsizei(buffers_.size()), buffers_.data());
      const std::vector<std::byte> zeros(kCapacity);  // gl_SkipComponents leaves words as they were
      for (std::size_t b = 0; b < buffers_.size(); ++b) {
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, GLuint(b), buffers_[b]);
        glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(kCapacity), zeros.data(), GL_STREAM_READ);
      }
      corners_ = primitive_corners(draw, program);
      for (GLuint s = 0; s < 4; ++s) {  // by vertex stream: a geometry shader's streams 1..3 too
        glBeginQueryIndexed(GL_PRIMITIVES_GENERATED, s, queries_[2 * s]);
        glBeginQueryIndexed(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, s, queries_[2 * s + 1]);
      }
      glBeginTransformFeedback(corners_ == 1 ? GL_POINTS : corners_ == 2 ? GL_LINES : GL_TRIANGLES);
      check_gl((draw.key + ": beginning transform feedback").c_str());
      return;
    }
    glEndTransformFeedback();
    FeedbackBuffers f;
    f.draw = d;
    std::size_t longest = 0;  // vertices, over the streams
    for (GLuint s = 0; s < 4; ++s) {
      glEndQueryIndexed(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, s);
      glEndQueryIndexed(GL_PRIMITIVES_GENERATED, s);
      GLuint generated = 0, written = 0;
      glGetQueryObjectuiv(queries_[2 * s], GL_QUERY_RESULT, &generated);
      glGetQueryObjectuiv(queries_[2 * s + 1], GL_QUERY_RESULT, &written);
      if (written != generated)
        throw GlError(draw.key + ": transform feedback wrote " + std::to_string(written) + " of " + std::to_string(generated) +
                      " primitives of stream " + std::to_string(s) + " (the GL runner's buffers hold " +
                      std::to_string(kCapacity >> 20) + " MiB each)");
      f.stream_primitives[s] = written;
      longest = std::max(longest, std::size_t(written) * std::size_t(s ? 1 : corners_));  // streams past 0: points
    }
    f.primitives = f.stream_primitives[0];
    f.corners = f.primitives ? corners_ : 0;
    // GL does not say which stream a buffer records: each is read as far as the longest stream
    // could have filled it (the rest still holds the zeros it was given).
    const std::vector<std::size_t> strides = buffer_strides(*draw.transform_feedback, program);
    for (std::size_t b = 0; b < buffers_.size(); ++b) {
      std::vector<std::byte> bytes(longest * strides[b]);
      glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers_[b]);
      if (!bytes.empty()) glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(bytes.size()), bytes.data());
      f.bytes.push_back(std::move(bytes));
    }
    check_gl((draw.key + ": reading transform feedback back").c_str());
    glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
    buffers_.clear();
    out_.push_back(std::move(f));
  }

 private:
  static constexpr std::size_t kCapacity = std::size_t(64) << 20;

  // What the draw's last vertex stage emits: the geometry shader's output type, the primitive
  // generator's, or the draw's mode.
  int primitive_corners(const DrawSetting& draw, GLuint program) const {
    if (!(draw.shaders ? *draw.shaders : scene_.shaders).geometry.empty()) {
      GLint type = 0;
      glGetProgramiv(program, GL_GEOMETRY_OUTPUT_TYPE, &type);
      return type == GL_POINTS ? 1 : type == GL_LINE_STRIP ? 2 : 3;
    }
    if (draw.mode == DrawMode::Patches) {
      GLint mode = 0, point_mode = 0;
      glGetProgramiv(program, GL_TESS_GEN_MODE, &mode);
      glGetProgramiv(program, GL_TESS_GEN_POINT_MODE, &point_mode);
      return point_mode ? 1 : mode == GL_ISOLINES ? 2 : 3;
    }
    return std::min(3, tessref::primitive_corners(draw.mode));
  }

  // Bytes a vertex takes in each buffer, from the program's varyings as GL reports them.
  static std::vector<std::size_t> buffer_strides(const TransformFeedbackSetting& t, GLuint program) {
    std::vector<std::size_t> strides(t.buffers(), 0);
    std::size_t buffer = 0;
    for (std::size_t i = 0; i < t.varyings.size(); ++i) {
      GLsizei length = 0, size = 0;
      GLenum type = GL_NONE;
      char name[256];
      glGetTransformFeedbackVarying(program, GLuint(i), sizeof name, &length, &size, &type, name);
      if (t.varyings[i] == "gl_NextBuffer") {
        ++buffer;
        continue;
      }
      strides[t.separate ? i : buffer] += 4 * std::size_t(size) * std::size_t(feedback_words(type));
    }
    return strides;
  }

  const Scene& scene_;
  const std::vector<Program>& programs_;
  std::vector<FeedbackBuffers>& out_;
  GLuint queries_[8] = {};  // generated and written, for each vertex stream
  std::vector<GLuint> buffers_;
  int corners_ = 3;
};

std::vector<ShaderStage> twin_stages(const Scene& scene, bool for_capture, bool specialize = false) {
  if (scene.shaders.program == ShaderProgram::Custom) return custom_stages(scene, scene.shaders, for_capture);
  std::vector<ShaderStage> stages = builtin_twin_stages(scene, for_capture);
  if (!specialize) return stages;
  const std::vector<UniformConstant> constants = scene_constants(scene);
  for (ShaderStage& s : stages) s.source = specialize_uniforms(s.source, constants);
  return stages;
}

}  // namespace

SceneRenderer::SceneRenderer(GlContext& context, const Scene& scene, const Mesh& mesh,
                             const SceneRendererOptions& options)
    : context_(context), scene_(scene), options_(options) {
  context_.make_current();
  model_ = model_matrix(scene.transform);
  view_projection_ =
      projection_matrix(scene.camera, scene.width, scene.height) * view_matrix(scene.camera);

  bool shared_program = scene_.draws.empty();
  for (const DrawSetting& d : scene_.draws) shared_program = shared_program || !d.shaders;
  if (shared_program) {
    // A scene's draws name their inputs themselves: no glBindAttribLocation from shaders.attributes.
    program_ = link_program(twin_stages(scene_, false, options_.specialize), {},
                            scene_.draws.empty() ? attribute_locations(scene_) : AttributeLocations{});
    set_uniforms(program_, scene_.shaders);
    textures_ = std::make_unique<GlTextures>(scene_, scene_.shaders);
    textures_->set_samplers(program_.id());
  }

  if (!scene_.draws.empty()) {
    // Each draw's program: its own (draws[].shaders) or the scene's.
    std::vector<unsigned> programs;
    std::vector<const GlTextures*> textures;
    draw_programs_.resize(scene_.draws.size());
    draw_textures_.resize(scene_.draws.size());
    for (std::size_t i = 0; i < scene_.draws.size(); ++i) {
      const DrawSetting& d = scene_.draws[i];
      // A draw with transform feedback links its program with the varyings (its own program).
      const bool own = d.shaders || d.transform_feedback;
      if (own) {
        const ShaderSettings& shaders = d.shaders ? *d.shaders : scene_.shaders;
        FeedbackVaryings varyings;
        if (d.transform_feedback) varyings = {d.transform_feedback->varyings, !d.transform_feedback->separate};
        draw_programs_[i] = link_program(custom_stages(scene_, shaders, false), varyings);
        set_uniforms(draw_programs_[i], shaders);
        draw_textures_[i] = std::make_unique<GlTextures>(scene_, shaders);
        draw_textures_[i]->set_samplers(draw_programs_[i].id());
      }
      programs.push_back(own ? draw_programs_[i].id() : program_.id());
      textures.push_back(own ? draw_textures_[i].get() : textures_.get());
    }
    draws_ = std::make_unique<GlDraws>(scene_, load_buffers(scene_), programs, textures);
  } else if (const TessellationSettings& t = scene_.tessellation; t.enabled) {
    const bool custom = scene_.shaders.program == ShaderProgram::Custom;
    PatchMeshData data{mesh.positions, mesh.normals, mesh.indices, custom ? scene_.shaders.patch_vertices : 3, {}, {}};
    if (!custom && t.scheme == SurfaceScheme::ScalarTaggedPN)
      for (const VertexTags& v : load_vertex_tags(t, mesh)) {
        data.tags.emplace_back(v.tension, v.sharpness, v.bias, 0.0f);
        data.creases.push_back(v.crease);
      }
    patches_ = std::make_unique<PatchMesh>(context_, data);
    // Constant levels: the exact bound of every patch. Adaptive: the TCS clamps to max_level. A
    // user's control shader: any level up to the largest.
    TessLevels worst = t.levels;
    if (t.adaptive.enabled || custom) {
      const float m = custom ? 64.0f : level_settings(scene_, view_projection_).screen.max_level;
      worst.outer = {m, m, m, m};
      worst.inner = {m, m};
    }
    point_bounds_.assign(patches_->patch_count(), domain_point_bound(tes_layout(t), worst));
  } else {
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(3, buffers_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.positions.size() * sizeof(glm::vec3)),
                 mesh.positions.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[1]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.normals.size() * sizeof(glm::vec3)),
                 mesh.normals.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    index_count_ = mesh.indices.size();
    check_gl("SceneRenderer: uploading the mesh");
  }

  RenderTargetDesc desc;
  desc.width = scene_.width;
  desc.height = scene_.height;
  desc.colors = {options_.color};
  desc.depth24 = options_.depth24;
  if (options_.normals_attachment) desc.colors.push_back(ColorFormat::kRgba32F);
  if (!scene_.draws.empty()) {  // the scene's own attachments
    desc.colors.clear();
    for (const ColorAttachmentSetting& c : scene_.framebuffer.color) desc.colors.push_back(c.format);
    desc.depth24 = scene_.framebuffer.depth_format == DepthFormat::k24;
  }
  target_ = std::make_unique<RenderTarget>(context_, desc);
}

SceneRenderer::~SceneRenderer() {
  context_.make_current();
  target_.reset();
  patches_.reset();
  draws_.reset();
  if (buffers_[0]) glDeleteBuffers(3, buffers_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

// Every uniform the twins read, with the values render_scene/draw_mesh give the C++ programs.
// Uniforms the driver optimized away (e.g. the lights in normals.frag) are skipped.
void SceneRenderer::set_uniforms(const Program& program, const ShaderSettings& shaders) const {
  program.use();
  if (!shaders.scene_uniforms) {
    for (const UniformSetting& u : shaders.uniforms) set_user_uniform(program, u);
    return;
  }
  auto loc = [&](const char* name) { return glGetUniformLocation(program.id(), name); };
  const auto vs = programs::TransformVertexShader::from(model_, view_projection_);
  const TessLevelSettings lv = level_settings(scene_, view_projection_);
  const TessellationSettings& t = scene_.tessellation;
  int l;
  if ((l = loc("u_model")) >= 0) glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(vs.u_model));
  if ((l = loc("u_view_projection")) >= 0)
    glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(vs.u_view_projection));
  if ((l = loc("u_normal_matrix")) >= 0)
    glUniformMatrix3fv(l, 1, GL_FALSE, glm::value_ptr(vs.u_normal_matrix));
  // One name in TCS and TES: the adaptive levels' matrix and gl_Position's, both the camera's.
  if ((l = loc("u_view_proj")) >= 0) glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(vs.u_view_projection));
  if ((l = loc("u_normal_mode")) >= 0) glUniform1i(l, glsl_index(t.normal_mode));
  if ((l = loc("u_phong_alpha")) >= 0) glUniform1f(l, t.phong_alpha);
  if ((l = loc("u_nagata_eps")) >= 0) glUniform1f(l, t.nagata_eps);
  if ((l = loc("u_displacement")) >= 0) glUniform1i(l, t.displacement.enabled ? 1 : 0);
  if ((l = loc("u_displacement_amplitude")) >= 0) glUniform1f(l, t.displacement.amplitude);
  if ((l = loc("u_displacement_frequency")) >= 0) glUniform1f(l, t.displacement.frequency);
  if ((l = loc("u_adaptive")) >= 0) glUniform1i(l, lv.adaptive ? 1 : 0);
  if ((l = loc("u_outer")) >= 0) glUniform4fv(l, 1, lv.constant.outer.data());
  if ((l = loc("u_inner")) >= 0) glUniform2fv(l, 1, lv.constant.inner.data());
  if ((l = loc("u_viewport")) >= 0)
    glUniform2f(l, lv.screen.viewport_pixels.x, lv.screen.viewport_pixels.y);
  if ((l = loc("u_pixels_per_segment")) >= 0) glUniform1f(l, lv.screen.pixels_per_segment);
  if ((l = loc("u_min_level")) >= 0) glUniform1f(l, lv.screen.min_level);
  if ((l = loc("u_max_level")) >= 0) glUniform1f(l, lv.screen.max_level);
  if ((l = loc("u_inner_rule")) >= 0)
    glUniform1i(l, lv.screen.inner_rule == InnerLevelRule::Max ? 0 : 1);

  // phong.frag, as render.cpp's phong_shader().
  if ((l = loc("u_eye")) >= 0) glUniform3fv(l, 1, glm::value_ptr(scene_.camera.eye));
  if ((l = loc("u_num_lights")) >= 0) glUniform1i(l, int(scene_.lights.size()));
  for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
    std::string at = "[";
    at.append(std::to_string(i)).append("]");
    if ((l = loc(("u_light_position" + at).c_str())) >= 0)
      glUniform3fv(l, 1, glm::value_ptr(scene_.lights[i].position));
    if ((l = loc(("u_light_intensity" + at).c_str())) >= 0)
      glUniform3fv(l, 1, glm::value_ptr(scene_.lights[i].intensity));
  }
  if ((l = loc("u_ka")) >= 0) glUniform1f(l, scene_.material.ka);
  if ((l = loc("u_kd")) >= 0) glUniform1f(l, scene_.material.kd);
  if ((l = loc("u_ks")) >= 0) glUniform1f(l, scene_.material.ks);
  if ((l = loc("u_shininess")) >= 0) glUniform1f(l, scene_.material.shininess);
  if ((l = loc("u_color")) >= 0) glUniform3fv(l, 1, glm::value_ptr(scene_.material.color));
  check_gl("SceneRenderer: setting uniforms");
  for (const UniformSetting& u : shaders.uniforms) set_user_uniform(program, u);
}

// shaders.uniforms, by the type GL reports (tessref's executor has checked the values against
// the GLSL types already; a uniform GL optimized away is skipped, as the scene uniforms are).
void SceneRenderer::set_user_uniform(const Program& program, const UniformSetting& u) const {
  const GLint location = glGetUniformLocation(program.id(), u.name.c_str());
  if (location < 0) return;
  const char* name = u.name.c_str();
  GLuint index = GL_INVALID_INDEX;
  glGetUniformIndices(program.id(), 1, &name, &index);
  GLint type = 0;
  if (index == GL_INVALID_INDEX && u.name.back() == ']') {  // "u[3]": GL lists the array as "u[0]"
    const std::string base = u.name.substr(0, u.name.rfind('[')) + "[0]";
    const char* b = base.c_str();
    glGetUniformIndices(program.id(), 1, &b, &index);
  }
  if (index != GL_INVALID_INDEX) glGetActiveUniformsiv(program.id(), 1, &index, GL_UNIFORM_TYPE, &type);
  // Components per element of each GL type, and glUniform*v with as many elements as were given
  // (several in a row set an array from this one on).
  const std::vector<float> f(u.values.begin(), u.values.end());
  const std::vector<double> d(u.values.begin(), u.values.end());
  std::vector<GLint> i;
  std::vector<GLuint> ui;
  for (double x : u.values) {
    i.push_back(GLint(x));
    ui.push_back(x < 0.0 ? GLuint(GLint(x)) : GLuint(x));
  }
  auto count = [&](std::size_t components) { return GLsizei(u.values.size() / components); };
  switch (type) {
    case GL_FLOAT: glUniform1fv(location, count(1), f.data()); break;
    case GL_FLOAT_VEC2: glUniform2fv(location, count(2), f.data()); break;
    case GL_FLOAT_VEC3: glUniform3fv(location, count(3), f.data()); break;
    case GL_FLOAT_VEC4: glUniform4fv(location, count(4), f.data()); break;
    case GL_DOUBLE: glUniform1dv(location, count(1), d.data()); break;
    case GL_DOUBLE_VEC2: glUniform2dv(location, count(2), d.data()); break;
    case GL_DOUBLE_VEC3: glUniform3dv(location, count(3), d.data()); break;
    case GL_DOUBLE_VEC4: glUniform4dv(location, count(4), d.data()); break;
    case GL_INT: case GL_BOOL: case GL_SAMPLER_2D: glUniform1iv(location, count(1), i.data()); break;
    case GL_INT_VEC2: case GL_BOOL_VEC2: glUniform2iv(location, count(2), i.data()); break;
    case GL_INT_VEC3: case GL_BOOL_VEC3: glUniform3iv(location, count(3), i.data()); break;
    case GL_INT_VEC4: case GL_BOOL_VEC4: glUniform4iv(location, count(4), i.data()); break;
    case GL_UNSIGNED_INT: glUniform1uiv(location, count(1), ui.data()); break;
    case GL_UNSIGNED_INT_VEC2: glUniform2uiv(location, count(2), ui.data()); break;
    case GL_UNSIGNED_INT_VEC3: glUniform3uiv(location, count(3), ui.data()); break;
    case GL_UNSIGNED_INT_VEC4: glUniform4uiv(location, count(4), ui.data()); break;
    case GL_FLOAT_MAT2: glUniformMatrix2fv(location, count(4), GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT3: glUniformMatrix3fv(location, count(9), GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT4: glUniformMatrix4fv(location, count(16), GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT2x3: glUniformMatrix2x3fv(location, count(6), GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT2x4: glUniformMatrix2x4fv(location, count(8), GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT3x2: glUniformMatrix3x2fv(location, count(6), GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT3x4: glUniformMatrix3x4fv(location, count(12), GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT4x2: glUniformMatrix4x2fv(location, count(8), GL_FALSE, f.data()); break;
    case GL_FLOAT_MAT4x3: glUniformMatrix4x3fv(location, count(12), GL_FALSE, f.data()); break;
    case GL_DOUBLE_MAT2: glUniformMatrix2dv(location, count(4), GL_FALSE, d.data()); break;
    case GL_DOUBLE_MAT3: glUniformMatrix3dv(location, count(9), GL_FALSE, d.data()); break;
    case GL_DOUBLE_MAT4: glUniformMatrix4dv(location, count(16), GL_FALSE, d.data()); break;
    case GL_DOUBLE_MAT2x3: glUniformMatrix2x3dv(location, count(6), GL_FALSE, d.data()); break;
    case GL_DOUBLE_MAT2x4: glUniformMatrix2x4dv(location, count(8), GL_FALSE, d.data()); break;
    case GL_DOUBLE_MAT3x2: glUniformMatrix3x2dv(location, count(6), GL_FALSE, d.data()); break;
    case GL_DOUBLE_MAT3x4: glUniformMatrix3x4dv(location, count(12), GL_FALSE, d.data()); break;
    case GL_DOUBLE_MAT4x2: glUniformMatrix4x2dv(location, count(8), GL_FALSE, d.data()); break;
    case GL_DOUBLE_MAT4x3: glUniformMatrix4x3dv(location, count(12), GL_FALSE, d.data()); break;
    default: throw GlError("SceneRenderer: uniform " + u.name + " has a type the GL runner does not set yet");
  }
  check_gl(("SceneRenderer: setting uniform " + u.name).c_str());
}

void SceneRenderer::draw() {
  context_.make_current();
  const auto t0 = Clock::now();
  target_->clear(scene_.background, 1.0f);  // binds the target, viewport = image size
  if (draws_) {  // the framebuffer a scene of draws starts from, as tessref reads it
    const InitialPixels initial = load_initial_images(scene_);
    for (std::size_t k = 0; k < initial.color.size(); ++k) {
      const ColorFormat f = scene_.framebuffer.color[k].format;
      if (initial.color[k]) target_->upload_color(*initial.color[k], int(k));
      else if (f != ColorFormat::kRgba32F)  // the background as the format holds it, as tessref starts
        target_->upload_color(std::vector<glm::vec4>(std::size_t(scene_.width) * std::size_t(scene_.height),
                                                     stored_color(f, false, scene_.background)), int(k));
    }
    if (initial.depth) target_->upload_depth(*initial.depth);
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  if (scene_.cull_back_faces) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
  }
  glPolygonMode(GL_FRONT_AND_BACK, scene_.polygon_mode == PolygonMode::kLine    ? GL_LINE
                                   : scene_.polygon_mode == PolygonMode::kPoint ? GL_POINT
                                                                                : GL_FILL);
  if (draws_) {
    glDisable(GL_DEPTH_TEST);  // each draw sets its own state and program
    if (feedback_) {
      FeedbackRecording recording(scene_, draw_programs_, *feedback_);
      draws_->draw([&recording](std::size_t d, bool begin) { recording.around(d, begin); });
    } else {
      draws_->draw();
    }
    stats_.draws = scene_.draws.size();
  } else if (patches_) {
    program_.use();
    textures_->bind();
    stats_.draws = patches_->draw(program_, point_bounds_, options_.max_points_per_draw);
  } else {
    program_.use();
    textures_->bind();
    glBindVertexArray(vao_);
    glDrawElements(GL_TRIANGLES, GLsizei(index_count_), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    stats_.draws = 1;
  }
  glFinish();
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  check_gl("SceneRenderer::draw");
  stats_.draw_seconds = seconds_since(t0);
}

Framebuffer SceneRenderer::read_back() {
  context_.make_current();
  const auto t0 = Clock::now();
  Framebuffer fb = target_->to_framebuffer();
  stats_.readback_seconds = seconds_since(t0);
  return fb;
}

std::vector<glm::u8vec4> SceneRenderer::read_back_rgba8() {
  context_.make_current();
  const auto t0 = Clock::now();
  std::vector<glm::u8vec4> color = target_->read_rgba8(0);
  stats_.readback_seconds = seconds_since(t0);
  return color;
}

Framebuffer SceneRenderer::render() {
  draw();
  return read_back();
}

std::vector<TessOutputVertex> SceneRenderer::capture_tess() {
  if (!patches_) throw GlError("SceneRenderer::capture_tess: the scene does not tessellate");
  context_.make_current();
  if (!capture_program_) {
    const std::vector<std::string> outputs = position_normal_outputs(scene_);
    capture_program_ = link_program(twin_stages(scene_, true),
                                    FeedbackVaryings{{outputs[0], outputs[1], "tf_tess_coord", "tf_patch_id"}, true},
                                    attribute_locations(scene_));
    set_uniforms(capture_program_, scene_.shaders);
    textures_->set_samplers(capture_program_.id());
  }
  textures_->bind();
  const std::vector<std::uint32_t> words =
      patches_->capture(capture_program_, kCaptureWords, GL_TRIANGLES, point_bounds_,
                        options_.max_points_per_draw);
  std::vector<TessOutputVertex> out(words.size() / kCaptureWords);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::uint32_t* w = &words[i * kCaptureWords];
    std::memcpy(&out[i].position, w, 3 * sizeof(float));
    std::memcpy(&out[i].normal, w + 3, 3 * sizeof(float));
    std::memcpy(&out[i].tess_coord, w + 6, 3 * sizeof(float));
    out[i].patch = w[9];
    // Patches come back in order; anything else is the 16-bit trap (or a driver bug).
    if (out[i].patch >= patches_->patch_count() || (i > 0 && out[i].patch < out[i - 1].patch))
      throw GlError("SceneRenderer::capture_tess: vertex " + std::to_string(i) + " tagged with patch " +
                    std::to_string(out[i].patch) + " out of order");
  }
  return out;
}

std::vector<TessDumpRecord> SceneRenderer::capture_draws_tess() {
  if (!draws_) throw GlError("SceneRenderer::capture_draws_tess: the scene has no draws");
  context_.make_current();
  const std::vector<std::vector<CallPatches>> numbering = patch_numbering(scene_, load_buffers(scene_));
  std::vector<TessDumpRecord> out;
  constexpr int kWords = 8;  // gl_Position 4, gl_TessCoord 3, gl_PrimitiveID 1
  GLuint feedback = 0, queries[2] = {0, 0};
  glGenBuffers(1, &feedback);
  glGenQueries(2, queries);
  std::size_t capacity = 0;
  glEnable(GL_RASTERIZER_DISCARD);
  try {
    for (std::size_t d = 0; d < scene_.draws.size(); ++d) {
      const DrawSetting& draw = scene_.draws[d];
      if (draw.mode != DrawMode::Patches) continue;
      const ShaderSettings& shaders = draw.shaders ? *draw.shaders : scene_.shaders;
      const unsigned own = draw.shaders ? draw_programs_[d].id() : program_.id();
      Program program = link_program(draw_capture_stages(scene_, shaders),
                                     FeedbackVaryings{{"gl_Position", kCaptureTessCoord, kCapturePrimitive}, true},
                                     active_attribute_locations(own));
      set_uniforms(program, shaders);
      const GlTextures* textures = draw.shaders ? draw_textures_[d].get() : textures_.get();
      if (textures) textures->set_samplers(program.id());
      GLint mode = 0, point_mode = 0;
      glGetProgramiv(program.id(), GL_TESS_GEN_MODE, &mode);
      glGetProgramiv(program.id(), GL_TESS_GEN_POINT_MODE, &point_mode);
      const GLenum primitive = point_mode ? GL_POINTS : mode == GL_ISOLINES ? GL_LINES : GL_TRIANGLES;
      const std::size_t per_primitive = primitive == GL_POINTS ? 1 : primitive == GL_LINES ? 2 : 3;
      const GLint offset = glGetUniformLocation(program.id(), kCaptureInstanceOffset);
      draws_->bind(d, program.id());
      glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedback);
      for (std::size_t c = 0; c < draw.calls.size(); ++c) {
        const CallPatches& patches = numbering[d][c];
        for (std::uint32_t i = 0; i < patches.instances; ++i) {
          GLuint generated = 0, written = 0;
          // The stream's size is known only afterwards: an overflow is drawn again, larger.
          for (std::size_t words = std::max<std::size_t>(capacity, 1 << 16);; words = std::size_t(generated) * per_primitive * kWords) {
            if (words > capacity) {
              glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(words * 4), nullptr, GL_STREAM_READ);
              capacity = words;
            }
            if (offset >= 0) glUniform1i(offset, GLint(i));
            glBeginQuery(GL_PRIMITIVES_GENERATED, queries[0]);
            glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, queries[1]);
            glBeginTransformFeedback(primitive);
            draws_->draw_instance(d, c, i);
            glEndTransformFeedback();
            glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
            glEndQuery(GL_PRIMITIVES_GENERATED);
            glGetQueryObjectuiv(queries[0], GL_QUERY_RESULT, &generated);
            glGetQueryObjectuiv(queries[1], GL_QUERY_RESULT, &written);
            if (written == generated) break;
          }
          std::vector<std::uint32_t> words(std::size_t(written) * per_primitive * kWords);
          if (!words.empty())
            glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(words.size() * 4), words.data());
          check_gl((draw.key + ": capturing the evaluation shader's outputs").c_str());
          // Patches come out in order, each contiguous: gl_PrimitiveID only grows within an
          // instance. Anything else cannot be numbered as tessref numbers patches.
          std::int64_t last = -1;
          for (std::size_t v = 0; v < words.size() / kWords; ++v) {
            const std::uint32_t* w = &words[v * kWords];
            TessDumpRecord r;
            std::memcpy(&r.clip, w, 16);
            std::memcpy(&r.tess_coord, w + 4, 12);
            const auto id = std::int32_t(w[7]);
            if (id < last || id < 0 || std::uint32_t(id) >= patches.per_instance)
              throw GlError(draw.key + ".calls[" + std::to_string(c) + "]: the driver's vertex " + std::to_string(v) +
                            " of instance " + std::to_string(i) + " has gl_PrimitiveID " + std::to_string(id) +
                            (id < last ? " after " + std::to_string(last) : std::string()) + " (the call has " +
                            std::to_string(patches.per_instance) +
                            " patches an instance; Mesa's draw module restarts gl_PrimitiveID every 1,023 indices, "
                            "so draw at most " + std::to_string(max_patches_per_draw(draw.patch_vertices)) +
                            " patches a call to capture it)");
            last = id;
            r.patch_id = patches.first_patch + i * patches.per_instance + std::uint32_t(id);
            out.push_back(r);
          }
        }
      }
      draws_->unbind();
    }
  } catch (...) {
    glDisable(GL_RASTERIZER_DISCARD);
    glDeleteQueries(2, queries);
    glDeleteBuffers(1, &feedback);
    throw;
  }
  glDisable(GL_RASTERIZER_DISCARD);
  glDeleteQueries(2, queries);
  glDeleteBuffers(1, &feedback);
  return out;
}

Rgb8Image rgb8_top_first(const std::vector<glm::u8vec4>& bottom_first, int width, int height) {
  Rgb8Image out{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 3)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::u8vec4 c = bottom_first[std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)];
      std::uint8_t* p = &out.pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
    }
  return out;
}

std::vector<FeedbackBuffers> SceneRenderer::transform_feedback() {
  if (!draws_) throw GlError("SceneRenderer::transform_feedback: the scene has no draws");
  std::vector<FeedbackBuffers> out;
  feedback_ = &out;
  try {
    draw();
  } catch (...) {
    feedback_ = nullptr;
    throw;
  }
  feedback_ = nullptr;
  return out;
}

}  // namespace tessref::glref
