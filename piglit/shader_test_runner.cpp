#include "piglit/shader_test_runner.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <map>
#include <memory>
#include <new>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "render/draw_call.h"
#include "render/draw_scene.h"
#include "scene/draw_schema.h"
#include "shader/glsl_compile.h"
#include "shader/glsl_rewrite.h"
#include "stages/glsl/glsl_program.h"
#include "texture/texture.h"

namespace tessref {
namespace {

// An integer argument as the file wrote it (the parser keeps numbers as doubles).
std::string format_integer(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", v);
  return text;
}

// What tessref reports for the GL limits piglit files ask about (glGetIntegerv's names).
const std::map<std::string, long long>& limits() {
  static const std::map<std::string, long long> table = {
      {"GL_MAX_PATCH_VERTICES", kMaxPatchVertices},
      {"GL_MAX_TESS_GEN_LEVEL", 64},
      {"GL_MAX_TESS_CONTROL_INPUT_COMPONENTS", 4 * kMaxStageLocations},
      {"GL_MAX_TESS_CONTROL_OUTPUT_COMPONENTS", 4 * kMaxStageLocations},
      {"GL_MAX_TESS_EVALUATION_INPUT_COMPONENTS", 4 * kMaxStageLocations},
      {"GL_MAX_TESS_EVALUATION_OUTPUT_COMPONENTS", 4 * kMaxStageLocations},
      {"GL_MAX_TESS_PATCH_COMPONENTS", 4 * kMaxPatchAttributes},
      {"GL_MAX_VERTEX_OUTPUT_COMPONENTS", 4 * kMaxStageLocations},
      {"GL_MAX_FRAGMENT_INPUT_COMPONENTS", kMaxVaryings},
      {"GL_MAX_VARYING_COMPONENTS", kMaxVaryings},
      {"GL_MAX_CLIP_DISTANCES", 8},
      {"GL_MAX_CULL_DISTANCES", 8},
      {"GL_MAX_COMBINED_CLIP_AND_CULL_DISTANCES", 8},
      {"GL_MAX_VARYING_FLOATS", kMaxVaryings},
      {"GL_MAX_VERTEX_ATTRIBS", 16},
      // Atomic counters: any stage, any binding (counter buffers are plain arrays here).
      {"GL_MAX_VERTEX_ATOMIC_COUNTER_BUFFERS", 8},
      {"GL_MAX_TESS_CONTROL_ATOMIC_COUNTER_BUFFERS", 8},
      {"GL_MAX_TESS_EVALUATION_ATOMIC_COUNTER_BUFFERS", 8},
      {"GL_MAX_FRAGMENT_ATOMIC_COUNTER_BUFFERS", 8},
      {"GL_MAX_VERTEX_ATOMIC_COUNTERS", 1024},
      {"GL_MAX_TESS_CONTROL_ATOMIC_COUNTERS", 1024},
      {"GL_MAX_TESS_EVALUATION_ATOMIC_COUNTERS", 1024},
      {"GL_MAX_FRAGMENT_ATOMIC_COUNTERS", 1024},
  };
  return table;
}

const std::set<std::string>& extensions() {
  static const std::set<std::string> names = {
      "GL_ARB_tessellation_shader", "GL_ARB_gpu_shader_fp64", "GL_ARB_arrays_of_arrays",
      "GL_ARB_separate_shader_objects", "GL_ARB_explicit_attrib_location",
      "GL_ARB_explicit_uniform_location", "GL_ARB_gpu_shader5", "GL_ARB_shading_language_420pack",
      "GL_ARB_enhanced_layouts", "GL_ARB_texture_rectangle", "GL_ARB_uniform_buffer_object",
      "GL_ARB_shader_bit_encoding", "GL_ARB_draw_instanced", "GL_ARB_instanced_arrays",
      "GL_ARB_fragment_coord_conventions", "GL_ARB_vertex_array_object",
      "GL_ARB_shader_atomic_counters", "GL_ARB_cull_distance", "GL_EXT_shader_integer_mix",
      "GL_ARB_shader_storage_buffer_object", "GL_ARB_shader_atomic_counter_ops"};
  return names;
}

// a OP b, for integers and floats alike.
template <class T>
bool compare_as(T a, Comparison c, T b) {
  switch (c) {
    case Comparison::Equal: return a == b;
    case Comparison::NotEqual: return a != b;
    case Comparison::Less: return a < b;
    case Comparison::LessEqual: return a <= b;
    case Comparison::Greater: return a > b;
    case Comparison::GreaterEqual: return a >= b;
  }
  return false;
}
bool compare(long long a, Comparison c, long long b) { return compare_as(a, c, b); }

// One scalar of a storage buffer, stored as GL stores it (little-endian, float as IEEE single).
void write_scalar(ScalarType t, double v, std::byte* at) {
  switch (t) {
    case ScalarType::Float: { const float f = float(v); std::memcpy(at, &f, 4); return; }
    case ScalarType::Double: std::memcpy(at, &v, 8); return;
    case ScalarType::Int: { const auto i = std::int32_t(std::llround(v)); std::memcpy(at, &i, 4); return; }
    default: { const auto u = std::uint32_t(std::llround(v)); std::memcpy(at, &u, 4); return; }
  }
}

double read_scalar(ScalarType t, const std::byte* at) {
  switch (t) {
    case ScalarType::Float: { float f; std::memcpy(&f, at, 4); return f; }
    case ScalarType::Double: { double d; std::memcpy(&d, at, 8); return d; }
    case ScalarType::Int: { std::int32_t i; std::memcpy(&i, at, 4); return i; }
    default: { std::uint32_t u; std::memcpy(&u, at, 4); return u; }
  }
}

// GL_CLIP_DISTANCEi's (or GL_CLIP_PLANEi's, the same enum) i, 0 to 7; -1 for another name.
int clip_plane_index(const std::string& name) {
  for (const std::string prefix : {"GL_CLIP_DISTANCE", "GL_CLIP_PLANE"})
    if (name.size() == prefix.size() + 1 && name.compare(0, prefix.size(), prefix) == 0 && name.back() >= '0' &&
        name.back() <= '7')
      return name.back() - '0';
  return -1;
}

// shader_runner's requirement lines for separable programs: all stages in one program with
// GL_PROGRAM_SEPARABLE, or each stage a program of its own in a program pipeline.
constexpr std::string_view kSeparableProgram = "SEPARABLE PROGRAM ENABLED", kSeparatePrograms = "SSO ENABLED";

shader::Linking linking_of(const Requirements& r) {
  for (const RawLine& line : r.other) {
    if (line.text == kSeparableProgram) return shader::Linking::SeparableProgram;
    if (line.text == kSeparatePrograms) return shader::Linking::SeparatePrograms;
  }
  return shader::Linking::Program;
}

// Empty when tessref meets the file's [require] section; else the reason to skip.
std::string unmet_requirement(const ShaderTestFile& f) {
  const Requirements& r = f.requirements;
  if (r.glsl) {
    if (r.glsl->profile == Profile::Es) return "GLSL ES";
    if (!compare(460, r.glsl->comparison, r.glsl->major * 100 + r.glsl->minor))
      return "GLSL version requirement not met by 4.60";
  }
  if (r.gl) {
    if (r.gl->profile == Profile::Es) return "OpenGL ES";
    if (!compare(45, r.gl->comparison, r.gl->major * 10 + r.gl->minor)) return "GL version requirement not met by 4.5";
  }
  for (const ExtensionRequirement& e : r.extensions) {
    const bool have = extensions().count(e.name) > 0;
    if (have == e.negated) return (e.negated ? "absence of " : "") + e.name;
  }
  for (const LimitRequirement& l : r.limits) {
    auto it = limits().find(l.name);
    if (it == limits().end()) return l.name + " (not a limit tessref reports)";
    if (!compare(it->second, l.comparison, l.value))
      return l.name + " >= " + std::to_string(l.value) + " (tessref: " + std::to_string(it->second) + ")";
  }
  for (const RawLine& line : r.other)
    if (line.text != kSeparableProgram && line.text != kSeparatePrograms) return "requirement '" + line.text + "'";
  for (const ShaderSection& s : f.shaders) {
    if (s.stage == ShaderStage::Compute) return "a compute shader";
    if (s.language == ShaderLanguage::Spirv) return "SPIR-V assembly shaders";
    if (s.language == ShaderLanguage::ArbAssembly) return "ARB assembly programs";
  }
  // The compatibility profile's state beyond what the runner feeds (glsl_rewrite.h).
  for (const ShaderSection& s : f.shaders)
    for (const char* name : {"gl_BackColor", "gl_BackSecondaryColor"})
      if (s.source.find(name) != std::string::npos)
        return std::string(name) + " (compatibility profile: tessref feeds gl_Vertex, the matrices and the "
                                   "front colours only)";
  return {};
}

shader::Stage to_stage(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return shader::Stage::Vertex;
    case ShaderStage::TessControl: return shader::Stage::TessControl;
    case ShaderStage::TessEvaluation: return shader::Stage::TessEval;
    case ShaderStage::Geometry: return shader::Stage::Geometry;
    default: return shader::Stage::Fragment;
  }
}

// The fixed-function fragment stage with its defaults (no texturing, no fog, no colour sum): the
// primary colour, or, when no shader writes gl_FrontColor (GL: undefined), 0.
constexpr const char* kFixedFunctionFragment = "#version 150\nvoid main() { gl_FragColor = gl_Color; }\n";
constexpr const char* kFixedFunctionFragmentUnlit = "#version 150\nvoid main() { gl_FragColor = vec4(0.0); }\n";

// piglit's [vertex shader passthrough]: piglit_vertex (location 0) to gl_Position.
constexpr const char* kPassthrough =
    "#version 150\nin vec4 piglit_vertex;\nvoid main() { gl_Position = piglit_vertex; }\n";

std::uint32_t float_bits(float f) { return std::bit_cast<std::uint32_t>(f); }

shader::Scalar scalar_of(ScalarType t) {
  switch (t) {
    case ScalarType::Float: return shader::Scalar::F32;
    case ScalarType::Double: return shader::Scalar::F64;
    case ScalarType::Int: return shader::Scalar::I32;
    case ScalarType::Uint: return shader::Scalar::U32;
    case ScalarType::Bool: return shader::Scalar::Bool;
  }
  return shader::Scalar::F32;
}

void append_value(std::vector<std::uint32_t>& words, ScalarType t, double v) {
  switch (t) {
    case ScalarType::Float: words.push_back(float_bits(float(v))); break;
    case ScalarType::Double: {
      const std::uint64_t b = std::bit_cast<std::uint64_t>(v);
      words.push_back(std::uint32_t(b));
      words.push_back(std::uint32_t(b >> 32));
      break;
    }
    case ScalarType::Int: words.push_back(std::uint32_t(std::int32_t(std::llround(v)))); break;
    case ScalarType::Uint: words.push_back(std::uint32_t(std::llround(v))); break;
    case ScalarType::Bool: words.push_back(v != 0.0 ? 1u : 0u); break;
  }
}

struct Failure {
  std::string what;
};

class Runner {
 public:
  Runner(const ShaderTestFile& f, const Parallel& parallel, const ShaderTestOptions& options)
      : f_(f), parallel_(parallel), options_(options) {
    const int w = f.requirements.size ? (*f.requirements.size)[0] : 250;
    const int h = f.requirements.size ? (*f.requirements.size)[1] : 250;
    fb_ = Framebuffer(w, h, glm::vec4(0.0f));
    state_.depth_test = false;  // GL's default
  }

  ShaderTestResult run() {
    if (std::string why = unmet_requirement(f_); !why.empty()) return {Verdict::Skip, why};
    const bool expect_link_error = std::any_of(f_.commands.begin(), f_.commands.end(), [](const TestCommand& c) {
      return c.kind == CommandKind::LinkError;
    });
    // shader_runner's context is a compatibility-profile one unless the file asks for core.
    const bool compatibility = !(f_.requirements.gl && f_.requirements.gl->profile == Profile::Core);
    std::vector<shader::ShaderSource> sources;
    for (const ShaderSection& s : f_.shaders) {
      if (s.language == ShaderLanguage::Passthrough)
        sources.push_back({shader::Stage::Vertex, f_.file_name, 1, kPassthrough, compatibility});
      else
        sources.push_back({to_stage(s.stage), f_.file_name, s.first_line, s.source, compatibility});
    }
    // The compatibility profile's fixed-function fragment stage: the primary colour.
    const bool has_fragment = std::any_of(f_.shaders.begin(), f_.shaders.end(),
                                          [](const ShaderSection& s) { return s.stage == ShaderStage::Fragment; });
    const bool front_color = std::any_of(f_.shaders.begin(), f_.shaders.end(), [](const ShaderSection& s) {
      return s.source.find("gl_FrontColor") != std::string::npos;
    });
    // GL_CLAMP_VERTEX_COLOR, on in a compatibility context: the last stage before the rasterizer.
    if (compatibility) {
      shader::Stage last = shader::Stage::Vertex;  // the enumeration is in pipeline order
      for (const shader::ShaderSource& s : sources)
        if (s.stage != shader::Stage::Fragment) last = std::max(last, s.stage);
      for (shader::ShaderSource& s : sources) s.clamp_vertex_color = s.stage == last;
    }
    if (compatibility && !has_fragment)
      sources.push_back({shader::Stage::Fragment, f_.file_name, 1,
                         front_color ? kFixedFunctionFragment : kFixedFunctionFragmentUnlit, true});
    try {
      const shader::CompiledProgram compiled = shader::compile_program(sources, linking_of(f_.requirements));
      if (expect_link_error) return {Verdict::Fail, "the program linked, but the file expects a link error"};
      // The storage buffers' sizes size the blocks' runtime arrays: known before the program.
      shader::StorageBufferSizes storage;
      for (const TestCommand& c : f_.commands)
        if (c.kind == CommandKind::SsboSize) storage[std::uint32_t(c.numbers[0])] = std::size_t(c.numbers[1]);
      program_ = std::make_unique<glsl::GlslProgram>(compiled, options_.limits, storage);
      set_matrices();
    } catch (const shader::CompileError& e) {
      if (expect_link_error) return {Verdict::Pass, {}};
      return {Verdict::Fail, e.what()};
    } catch (const shader::SpirvError& e) {
      return {Verdict::Fail, e.what()};
    }
    try {
      load_vertex_data();
      for (const TestCommand& c : f_.commands) execute(c);
    } catch (const Failure& e) {
      return {Verdict::Fail, e.what};
    } catch (const std::bad_alloc&) {
      throw;  // the memory budget: the command says so, not a failed test
    } catch (const std::exception& e) {
      return {Verdict::Fail, e.what()};
    }
    return {Verdict::Pass, {}};
  }

 private:
  [[noreturn]] void fail(const TestCommand& c, const std::string& what) {
    throw Failure{std::to_string(c.line) + ": " + what + " [" + c.text + "]"};
  }

  // The compatibility profile's matrices, where the program reads them (glsl_rewrite.h): the
  // projection glOrtho set ('ortho'), the identity modelview.
  void set_matrices() {
    const glm::mat4 modelview(1.0f);
    const glm::mat4 values[3] = {projection_ * modelview, modelview, projection_};
    for (int i = 0; i < 3; ++i) {
      const char* name = shader::kCompatibilityMatrices[i][1];
      if (!program_->uniform_shape(name)) continue;
      glsl::UniformValue v{shader::Scalar::F32, 4, 4, {}};
      for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) v.words.push_back(float_bits(values[i][col][row]));
      program_->set_uniform(name, v);
    }
  }

  void load_vertex_data() {
    if (!f_.vertex_data) return;
    for (const VertexColumn& col : f_.vertex_data->columns) {
      const auto location =
          program_->attribute_location(col.name == "gl_Vertex" ? shader::kCompatibilityVertex : col.name);
      if (!location) continue;  // not an active input
      if (col.glsl_type.columns != 1)
        throw Failure{"[vertex data] matrix attribute '" + col.name + "' is not supported"};
      glsl::VertexAttribute a;
      a.location = *location + std::uint32_t(col.array_index);
      a.scalar = scalar_of(col.glsl_type.scalar);
      a.components = col.glsl_type.rows * shader::scalar_words(a.scalar);
      for (double v : col.values) append_value(a.words, col.glsl_type.scalar, v);
      attributes_.push_back(std::move(a));
    }
  }

  // glDrawArrays(Instanced) with a negative first, count or instance count is GL_INVALID_VALUE
  // and draws nothing; piglit's shader_runner fails the test on the error. (The parser keeps the
  // low 32 bits as piglit does, so 4294967295 arrives as -1.)
  void refuse_negative_draw_arguments(const TestCommand& c) {
    static const char* const names[] = {"first", "count", "instance count"};
    for (std::size_t i = 0; i < c.numbers.size() && i < 3; ++i)
      if (c.numbers[i] < 0)
        fail(c, "glDrawArrays: a negative " + std::string(names[i]) + " (" + format_integer(c.numbers[i]) +
                    ") is GL_INVALID_VALUE");
  }

  void draw_patches(const TestCommand& c, const std::vector<glsl::VertexAttribute>& attributes,
                    std::size_t first, std::size_t count, int instances, int patch_vertices) {
    DrawCall call;
    call.first = first;
    call.count = count;
    call.instances = instances;
    call.patch_vertices = patch_vertices;
    call.default_outer = default_outer_;
    call.default_inner = default_inner_;
    draw(c, attributes, call);
  }

  // glDrawArrays(Instanced) of points, lines or triangles (a program without tessellation).
  void draw_primitives(const TestCommand& c, const std::vector<glsl::VertexAttribute>& attributes, std::size_t first,
                       std::size_t count, int instances) {
    const std::string name = c.words.empty() ? "" : c.words[0];
    const std::optional<DrawMode> mode = draw_mode_named(name);
    if (mode == DrawMode::Patches) fail(c, "GL_PATCHES needs a tessellation evaluation shader");
    if (!mode) fail(c, "draw mode " + name + " is not drawn (quads and polygons are compatibility-profile modes)");
    std::vector<std::uint32_t> run(count);
    for (std::size_t i = 0; i < count; ++i) run[i] = std::uint32_t(first + i);
    const std::vector<std::uint32_t> indices = assemble(*mode, 3, {run});
    DrawCall call;
    call.patches = false;
    call.corners = primitive_corners(*mode);
    call.indices = indices;
    call.vertex_count = first + count;
    call.instances = instances;
    if (!indices.empty()) draw(c, attributes, call);
  }

  void draw(const TestCommand& c, const std::vector<glsl::VertexAttribute>& attributes, const DrawCall& call) {
    try {
      for (auto& [binding, bytes] : ssbos_) program_->bind_storage_buffer(binding, bytes);
      run_draw(*program_, attributes, call, state_, fb_, parallel_);
      program_->write_back_storage();
    } catch (const glsl::StageError& e) {
      fail(c, e.what());
    } catch (const std::invalid_argument& e) {  // a draw tessref refuses, at this line
      fail(c, e.what());
    }
  }

  void draw_rect(const TestCommand& c) {
    if (program_->has_tes() && !c.patch) fail(c, "draw rect without 'patch' with a tessellation program is a GL error");
    if (!program_->has_tes() && c.patch) fail(c, "draw rect patch needs a tessellation evaluation shader");
    double x = c.numbers[0], y = c.numbers[1], w = c.numbers[2], h = c.numbers[3];
    if (c.ortho) {  // window pixels to normalized device coordinates
      x = 2.0 * x / fb_.width - 1.0;
      y = 2.0 * y / fb_.height - 1.0;
      w = 2.0 * w / fb_.width;
      h = 2.0 * h / fb_.height;
    }
    const double px[4] = {x, x + w, x, x + w}, py[4] = {y, y, y + h, y + h};
    std::vector<glsl::VertexAttribute> attributes;
    // piglit_draw_rect's corners: piglit_vertex, or gl_Vertex in the compatibility profile.
    for (const char* name : {"piglit_vertex", shader::kCompatibilityVertex})
      if (auto loc = program_->attribute_location(name)) {
        glsl::VertexAttribute a;
        a.location = *loc;
        a.components = 4;
        for (int i = 0; i < 4; ++i)
          for (float v : {float(px[i]), float(py[i]), 0.0f, 1.0f}) a.words.push_back(float_bits(v));
        attributes.push_back(std::move(a));
      }
    if (auto loc = program_->attribute_location("piglit_texcoord")) {
      glsl::VertexAttribute a;
      a.location = *loc;
      a.components = 2;
      for (int i = 0; i < 4; ++i)
        for (float v : {float(i & 1), float(i >> 1)}) a.words.push_back(float_bits(v));
      attributes.push_back(std::move(a));
    }
    const int instances = c.numbers.size() > 4 ? int(c.numbers[4]) : 1;
    if (c.patch) return draw_patches(c, attributes, 0, 4, instances, 4);
    // glDrawArrays(GL_TRIANGLE_STRIP, 0, 4): its two triangles (GL 4.5, 10.1.8).
    static constexpr std::uint32_t kStrip[6] = {0, 1, 2, 2, 1, 3};
    DrawCall call;
    call.patches = false;
    call.indices = kStrip;
    call.vertex_count = 4;
    call.instances = instances;
    draw(c, attributes, call);
  }

  // What glReadPixels(GL_UNSIGNED_BYTE) returns from the RGBA8 window.
  std::array<int, 4> observed(int x, int y) const {
    const glm::vec4 c = fb_.color[fb_.index(x, y)];
    std::array<int, 4> q;
    for (int i = 0; i < 4; ++i)
      q[i] = int(std::lround(std::clamp(std::isnan(c[i]) ? 0.0f : c[i], 0.0f, 1.0f) * 255.0f));
    return q;
  }

  // piglit's probes compare in bytes: expected * 255 truncated, tolerance * 255 rounded up, and a
  // channel fails when it differs by more than the tolerance.
  void probe(const TestCommand& c, int x0, int y0, int w, int h, const double* expected, int comps) {
    int want[4], tol[4];
    for (int i = 0; i < comps; ++i) {
      want[i] = int(std::uint8_t(float(expected[i]) * 255.0f));
      tol[i] = int(std::ceil(float(tolerance_[i]) * 255.0f));
    }
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) {
        if (x < 0 || y < 0 || x >= fb_.width || y >= fb_.height) fail(c, "probe outside the window");
        const std::array<int, 4> o = observed(x, y);
        for (int i = 0; i < comps; ++i)
          if (std::abs(o[i] - want[i]) > tol[i]) {
            std::string e, g;
            for (int k = 0; k < comps; ++k) {
              e.append(k ? ", " : "").append(std::to_string(want[k]));
              g.append(k ? ", " : "").append(std::to_string(o[k]));
            }
            fail(c, "probe at (" + std::to_string(x) + ", " + std::to_string(y) + "): expected (" + e +
                        "), observed (" + g + ") in 8-bit units, tolerance " + std::to_string(tol[i]));
          }
      }
  }

  // Display lists (compatibility profile): the draws and the patch parameters between newlist and
  // endlist are compiled into the list (and run too with GL_COMPILE_AND_EXECUTE); calllist runs them.
  static bool listable(CommandKind k) {
    return k == CommandKind::DrawArrays || k == CommandKind::DrawRect || k == CommandKind::PatchVertices ||
           k == CommandKind::PatchDefaultOuterLevel || k == CommandKind::PatchDefaultInnerLevel;
  }
  void execute(const TestCommand& c) {
    if (c.kind == CommandKind::NewList) {
      if (recording_) fail(c, "newlist inside a display list is GL_INVALID_OPERATION");
      recording_ = true;
      execute_while_recording_ = !c.words.empty() && c.words[0] == "GL_COMPILE_AND_EXECUTE";
      list_.clear();
      return;
    }
    if (c.kind == CommandKind::EndList) {
      if (!recording_) fail(c, "endlist without newlist is GL_INVALID_OPERATION");
      recording_ = false;
      return;
    }
    if (c.kind == CommandKind::CallList) {
      for (const TestCommand* listed : list_) run_command(*listed);
      return;
    }
    if (c.kind == CommandKind::DeleteList) {
      list_.clear();
      return;
    }
    if (recording_ && listable(c.kind)) {
      list_.push_back(&c);
      if (!execute_while_recording_) return;
    }
    run_command(c);
  }

  void run_command(const TestCommand& c) {
    const auto& n = c.numbers;
    switch (c.kind) {
      case CommandKind::ClearColor: clear_color_ = glm::vec4(n[0], n[1], n[2], n[3]); break;
      case CommandKind::Clear: fb_.clear(clear_color_); break;
      case CommandKind::PatchVertices: patch_vertices_ = int(n[0]); break;
      case CommandKind::PatchDefaultOuterLevel: default_outer_ = glm::vec4(n[0], n[1], n[2], n[3]); break;
      case CommandKind::PatchDefaultInnerLevel: default_inner_ = glm::vec2(n[0], n[1]); break;
      case CommandKind::DrawArrays: {
        refuse_negative_draw_arguments(c);
        if (!program_->has_tes()) {
          draw_primitives(c, attributes_, std::size_t(n[0]), std::size_t(n[1]), n.size() > 2 ? int(n[2]) : 1);
          break;
        }
        if (c.words.empty() || c.words[0] != "GL_PATCHES")
          fail(c, "only GL_PATCHES draws are supported with a tessellation program");
        // Vertices past the [vertex data] read GL's default attribute values (0, 0, 0, 1).
        const std::size_t first = std::size_t(n[0]), count = std::size_t(n[1]);
        draw_patches(c, attributes_, first, count, n.size() > 2 ? int(n[2]) : 1, patch_vertices_);
        break;
      }
      case CommandKind::DrawRect: draw_rect(c); break;
      case CommandKind::Uniform: {
        glsl::UniformValue v;
        v.scalar = scalar_of(c.type.scalar);
        v.columns = c.type.columns;
        v.rows = c.type.rows;
        for (double x : n) append_value(v.words, c.type.scalar, x);
        try {
          program_->set_uniform(c.words.at(1), v);
        } catch (const std::invalid_argument& e) {
          fail(c, e.what());
        }
        break;
      }
      case CommandKind::ProbeAll: probe(c, 0, 0, fb_.width, fb_.height, n.data(), int(n.size())); break;
      case CommandKind::Probe: {
        int x = int(n[0]), y = int(n[1]);
        if (c.relative) {  // in float, as piglit computes it, and clamped into the window
          x = std::min(int(float(n[0]) * float(fb_.width)), fb_.width - 1);
          y = std::min(int(float(n[1]) * float(fb_.height)), fb_.height - 1);
        }
        probe(c, x, y, 1, 1, n.data() + 2, int(n.size()) - 2);
        break;
      }
      case CommandKind::ProbeRect: {
        int x = int(n[0]), y = int(n[1]), w = int(n[2]), h = int(n[3]);
        if (c.relative) {
          x = int(float(n[0]) * float(fb_.width));
          y = int(float(n[1]) * float(fb_.height));
          w = int(float(n[2]) * float(fb_.width));
          h = int(float(n[3]) * float(fb_.height));
        }
        probe(c, x, y, w, h, n.data() + 4, int(n.size()) - 4);
        break;
      }
      case CommandKind::Tolerance:
        for (int i = 0; i < 4; ++i) tolerance_[i] = n.size() == 1 ? n[0] : n.at(std::size_t(i));
        break;
      case CommandKind::TextureCheckerboard: {
        // piglit_checkerboard_texture: 2 x 2 squares, GL_RGBA8, level 0 only, GL_NEAREST,
        // GL_CLAMP_TO_BORDER with a red border.
        const int width = int(n[2]), height = int(n[3]);
        std::vector<float> rgba(std::size_t(width) * std::size_t(height) * 4);
        for (int j = 0; j < height; ++j)
          for (int i = 0; i < width; ++i) {
            const bool odd = ((i / std::max(1, width / 2)) + (j / std::max(1, height / 2))) & 1;
            for (int k = 0; k < 4; ++k) rgba[(std::size_t(j) * std::size_t(width) + std::size_t(i)) * 4 + std::size_t(k)] = float(n[odd ? 8 + k : 4 + k]);
          }
        auto t = std::make_unique<texture::Texture>();
        t->format = texture::TexelFormat::kRgba8;
        t->levels.push_back(texture::make_level(t->format, width, height, rgba.data()));
        t->sampler.min_filter = t->sampler.mag_filter = texture::Filter::Nearest;
        t->sampler.wrap_s = t->sampler.wrap_t = texture::Wrap::ClampToBorder;
        t->sampler.border = {1.0f, 0.0f, 0.0f, 1.0f};
        t->finalize();
        const std::uint32_t unit = std::uint32_t(n[0]);
        program_->bind_texture(unit, t.get());
        textures_[unit] = std::move(t);
        last_texture_ = textures_[unit].get();
        break;
      }
      case CommandKind::TexParameter: {
        if (!last_texture_ || c.words.size() < 3) break;
        const std::string& name = c.words[1];
        const std::string& value = c.words[2];
        using texture::Filter;
        using texture::Wrap;
        texture::SamplerState& st = last_texture_->sampler;
        if (name == "min" || name == "mag") {
          (name == "min" ? st.min_filter : st.mag_filter) = value == "linear" ? Filter::Linear : Filter::Nearest;
        } else if (name == "wrap_s" || name == "wrap_t") {
          const Wrap w = value == "repeat" ? Wrap::Repeat : value == "mirrored_repeat" ? Wrap::MirroredRepeat
                         : value == "clamp_to_edge" ? Wrap::ClampToEdge : Wrap::ClampToBorder;
          (name == "wrap_s" ? st.wrap_s : st.wrap_t) = w;
        }
        last_texture_->finalize();
        break;
      }
      case CommandKind::Enable: case CommandKind::Disable:
        if (!c.words.empty() && c.words[0] == "GL_DEPTH_TEST") {
          state_.depth_test = c.kind == CommandKind::Enable;
        } else if (const int plane = c.words.empty() ? -1 : clip_plane_index(c.words[0]); plane >= 0) {
          const auto bit = std::uint8_t(1u << plane);
          state_.clip_distances = c.kind == CommandKind::Enable ? state_.clip_distances | bit : state_.clip_distances & ~bit;
        } else {
          fail(c, "unsupported GL capability");
        }
        break;
      case CommandKind::AtomicCounters:
        program_->counter_buffer(0).assign(std::size_t(n[0]), 0u);
        break;
      case CommandKind::AtomicCounterBuffer:
        program_->counter_buffer(std::uint32_t(n[0])).assign(std::size_t(n[1]), 0u);
        break;
      case CommandKind::AtomicCounterSet: {
        auto& buffer = program_->counter_buffer(std::uint32_t(n[0]));
        if (std::size_t(n[1]) >= buffer.size()) fail(c, "counter past the buffer");
        buffer[std::size_t(n[1])] = std::uint32_t(std::llround(n[2]));
        break;
      }
      case CommandKind::ProbeAtomicCounter: case CommandKind::ProbeAtomicCounterBuffer: {
        const bool in_buffer = c.kind == CommandKind::ProbeAtomicCounterBuffer;
        const auto& buffer = program_->counter_buffer(in_buffer ? std::uint32_t(n[0]) : 0u);
        const std::size_t index = in_buffer ? std::size_t(n[1]) / 4 : std::size_t(n[0]);
        const long long want = std::llround(n[in_buffer ? 2 : 1]);
        if (index >= buffer.size()) fail(c, "counter past the buffer");
        if (!compare(buffer[index], c.comparison, want))
          fail(c, "atomic counter " + std::to_string(index) + " is " + std::to_string(buffer[index]));
        break;
      }
      case CommandKind::SsboSize:
        ssbos_[std::uint32_t(n[0])].assign(std::size_t(n[1]), std::byte{0});
        break;
      case CommandKind::SsboSubData: {
        std::vector<std::byte>& bytes = ssbo(c, std::uint32_t(n[0]));
        const std::size_t size = c.type.scalar == ScalarType::Double ? 8 : 4;
        for (std::size_t i = 2; i < n.size(); ++i) {
          const std::size_t at = std::size_t(n[1]) + (i - 2) * size;
          if (at + size > bytes.size()) fail(c, "subdata past the buffer's " + std::to_string(bytes.size()) + " bytes");
          write_scalar(c.type.scalar, n[i], bytes.data() + at);
        }
        break;
      }
      case CommandKind::ProbeSsbo: {
        const std::vector<std::byte>& bytes = ssbo(c, std::uint32_t(n[0]));
        const std::size_t at = std::size_t(n[1]), size = c.type.scalar == ScalarType::Double ? 8 : 4;
        if (at + size > bytes.size()) fail(c, "probe past the buffer's " + std::to_string(bytes.size()) + " bytes");
        const double value = read_scalar(c.type.scalar, bytes.data() + at);
        const bool ok = c.type.scalar == ScalarType::Float || c.type.scalar == ScalarType::Double
                            ? compare_as(value, c.comparison, n[2])
                            : compare(std::llround(value), c.comparison, std::llround(n[2]));
        if (!ok) fail(c, "the buffer holds " + std::to_string(value) + " at byte " + std::to_string(at));
        break;
      }
      case CommandKind::LinkSuccess: break;
      case CommandKind::ClipPlane: {  // glClipPlane: eye coordinates, the modelview being the identity
        const int i = int(n[0]);
        if (i < 0 || i > 7) fail(c, "GL_CLIP_PLANE" + std::to_string(i) + " is past GL_MAX_CLIP_PLANES (8)");
        state_.clip_planes[std::size_t(i)] = glm::vec4(n[1], n[2], n[3], n[4]);
        break;
      }
      case CommandKind::Ortho: {  // glOrtho(l, r, b, t, -1, 1); without numbers the window's pixels
        const bool pixels = c.numbers.size() < 4;
        projection_ = glm::ortho(pixels ? 0.0f : float(n[0]), pixels ? float(fb_.width) : float(n[1]),
                                 pixels ? 0.0f : float(n[2]), pixels ? float(fb_.height) : float(n[3]), -1.0f, 1.0f);
        set_matrices();
        break;
      }
      default: fail(c, "command not supported by tessref's shader-test runner");
    }
  }

  const ShaderTestFile& f_;
  const Parallel& parallel_;
  const ShaderTestOptions& options_;
  std::unique_ptr<glsl::GlslProgram> program_;
  Framebuffer fb_;
  RasterState state_;
  glm::vec4 clear_color_{0.0f};
  glm::mat4 projection_{1.0f};  // the compatibility profile's GL_PROJECTION matrix
  bool recording_ = false, execute_while_recording_ = false;  // between newlist and endlist
  std::vector<const TestCommand*> list_;                        // the display list
  glm::vec4 default_outer_{1.0f};
  glm::vec2 default_inner_{1.0f};
  int patch_vertices_ = 3;
  double tolerance_[4] = {0.01, 0.01, 0.01, 0.01};
  std::vector<glsl::VertexAttribute> attributes_;
  std::map<std::uint32_t, std::unique_ptr<texture::Texture>> textures_;
  texture::Texture* last_texture_ = nullptr;
  std::map<std::uint32_t, std::vector<std::byte>> ssbos_;  // ssbo B SIZE: bound at B for every draw

  std::vector<std::byte>& ssbo(const TestCommand& c, std::uint32_t binding) {
    const auto it = ssbos_.find(binding);
    if (it == ssbos_.end()) fail(c, "no buffer at shader storage binding " + std::to_string(binding) + " (ssbo B SIZE first)");
    return it->second;
  }
};

}  // namespace

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Pass: return "pass";
    case Verdict::Fail: return "fail";
    case Verdict::Skip: return "skip";
  }
  return "?";
}

ShaderTestResult run_shader_test(const ShaderTestFile& file, const Parallel& parallel,
                                 const ShaderTestOptions& options) {
  return Runner(file, parallel, options).run();
}

}  // namespace tessref
