#include "shader/glsl_rewrite.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <string_view>

namespace tessref::shader {
namespace {

// #extension names whose features are core in GLSL 4.50: the line goes (glslang's SPIR-V path
// refuses some of them, e.g. GL_ARB_arrays_of_arrays, as "not supported").
constexpr std::array kCoreExtensions = {
    "GL_ARB_texture_rectangle",         "GL_ARB_uniform_buffer_object",
    "GL_ARB_texture_buffer_object",     "GL_ARB_fragment_coord_conventions",
    "GL_ARB_texture_multisample",       "GL_ARB_explicit_attrib_location",
    "GL_ARB_shader_bit_encoding",       "GL_ARB_tessellation_shader",
    "GL_ARB_gpu_shader5",               "GL_ARB_gpu_shader_fp64",
    "GL_ARB_texture_cube_map_array",    "GL_ARB_texture_gather",
    "GL_ARB_texture_query_lod",         "GL_ARB_sample_shading",
    "GL_ARB_shader_subroutine",         "GL_ARB_separate_shader_objects",
    "GL_ARB_vertex_attrib_64bit",       "GL_ARB_viewport_array",
    "GL_ARB_shader_precision",          "GL_ARB_shading_language_420pack",
    "GL_ARB_shader_atomic_counters",    "GL_ARB_shader_image_load_store",
    "GL_ARB_conservative_depth",        "GL_ARB_shading_language_packing",
    "GL_ARB_arrays_of_arrays",          "GL_ARB_compute_shader",
    "GL_ARB_explicit_uniform_location", "GL_ARB_fragment_layer_viewport",
    "GL_ARB_shader_image_size",         "GL_ARB_shader_storage_buffer_object",
    "GL_ARB_texture_query_levels",      "GL_ARB_enhanced_layouts",
    "GL_ARB_derivative_control",        "GL_ARB_shader_texture_image_samples",
    "GL_ARB_cull_distance",             "GL_EXT_shader_integer_mix",
};

// Texture lookups removed from core GLSL, and the overloaded names that replace them.
const std::map<std::string_view, std::string_view> kOldTextureFunctions = {
    {"texture1D", "texture"},           {"texture2D", "texture"},
    {"texture3D", "texture"},           {"textureCube", "texture"},
    {"texture2DRect", "texture"},       {"texture1DProj", "textureProj"},
    {"texture2DProj", "textureProj"},   {"texture3DProj", "textureProj"},
    {"texture2DRectProj", "textureProj"}, {"texture1DLod", "textureLod"},
    {"texture2DLod", "textureLod"},     {"texture3DLod", "textureLod"},
    {"textureCubeLod", "textureLod"},   {"texture1DProjLod", "textureProjLod"},
    {"texture2DProjLod", "textureProjLod"}, {"texture3DProjLod", "textureProjLod"},
};

// Compatibility-profile fixed-function state and what to write instead.
const char* compatibility_hint(std::string_view name) {
  static const std::map<std::string_view, const char*> kNames = {
      {"gl_Vertex", "declare an input attribute"},
      {"gl_Normal", "declare an input attribute"},
      {"gl_Color", "declare an input"},
      {"gl_SecondaryColor", "declare an input"},
      {"gl_FogCoord", "declare an input attribute"},
      {"gl_ClipVertex", "write gl_ClipDistance"},
      {"gl_FrontColor", "declare an output"},
      {"gl_BackColor", "declare an output"},
      {"gl_FrontSecondaryColor", "declare an output"},
      {"gl_BackSecondaryColor", "declare an output"},
      {"gl_TexCoord", "declare an output or input"},
      {"gl_FogFragCoord", "declare an output or input"},
      {"gl_ClipPlane", "pass the plane as a uniform"},
      {"gl_Point", "pass it as a uniform"},
      {"gl_Fog", "pass it as a uniform"},
      {"gl_FrontMaterial", "pass it as a uniform"},
      {"gl_BackMaterial", "pass it as a uniform"},
      {"gl_LightSource", "pass it as a uniform"},
      {"gl_LightModel", "pass it as a uniform"},
      {"gl_FrontLightModelProduct", "pass it as a uniform"},
      {"gl_BackLightModelProduct", "pass it as a uniform"},
      {"gl_FrontLightProduct", "pass it as a uniform"},
      {"gl_BackLightProduct", "pass it as a uniform"},
      {"gl_TextureEnvColor", "pass it as a uniform"},
      {"ftransform", "multiply by your own matrix uniform"},
  };
  if (auto it = kNames.find(name); it != kNames.end()) return it->second;
  if (name.starts_with("gl_MultiTexCoord")) return "declare an input attribute";
  if (name.starts_with("gl_EyePlane") || name.starts_with("gl_ObjectPlane"))
    return "pass the plane as a uniform";
  for (std::string_view matrix : {"gl_ModelViewProjectionMatrix", "gl_ModelViewMatrix",
                                  "gl_ProjectionMatrix", "gl_TextureMatrix", "gl_NormalMatrix"}) {
    if (!name.starts_with(matrix)) continue;
    std::string_view rest = name.substr(matrix.size());
    if (rest.empty() || rest == "Inverse" || rest == "Transpose" || rest == "InverseTranspose")
      return "pass the matrix as a uniform";
  }
  return nullptr;
}

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The text with comments replaced by spaces (newlines kept): directives and identifiers are
// looked for in it, at the offsets they have in the original.
std::string blank_comments(const std::string& text) {
  std::string code = text;
  std::size_t i = 0;
  while (i < code.size()) {
    std::size_t end;
    if (code.compare(i, 2, "//") == 0) {
      end = std::min(code.find('\n', i), code.size());
    } else if (code.compare(i, 2, "/*") == 0) {
      end = code.find("*/", i + 2);
      end = end == std::string::npos ? code.size() : end + 2;
    } else {
      ++i;
      continue;
    }
    for (; i < end; ++i)
      if (code[i] != '\n') code[i] = ' ';
  }
  return code;
}

struct Word {
  std::size_t pos;
  std::string_view text;
};

// A preprocessor directive: its extent (without a trailing comment) and its words, split at
// white space and ':' ("#extension X : require" -> extension, X, require).
struct Directive {
  std::size_t begin, end;
  std::vector<std::string_view> words;
};

class Rewriter {
 public:
  explicit Rewriter(const ShaderSource& source)
      : source_(source), code_(blank_comments(source.text)) {
    scan();
  }

  RewrittenSource run() {
    if (source_.compatibility) rewrite_compatibility_state();
    refuse_compatibility_state();
    const int version = rewrite_version();
    remove_core_extensions();
    if (source_.stage == Stage::Fragment) rewrite_fragment_outputs();
    rewrite_storage_keywords();
    rewrite_texture_functions();
    return build(version);
  }

 private:
  void scan() {
    std::size_t line_begin = 0;
    while (line_begin <= code_.size()) {
      line_starts_.push_back(line_begin);
      std::size_t line_end = std::min(code_.find('\n', line_begin), code_.size());
      std::string_view line(code_.data() + line_begin, line_end - line_begin);
      std::size_t hash = line.find_first_not_of(" \t\r\f\v");
      if (hash != std::string_view::npos && line[hash] == '#') {
        Directive d{line_begin + hash, line_begin + line.find_last_not_of(" \t\r\f\v") + 1, {}};
        std::string_view rest = line.substr(hash + 1, d.end - d.begin - 1);
        for (std::size_t i = 0; i < rest.size();) {
          std::size_t n = rest.find_first_of(" \t:", i);
          if (n == std::string_view::npos) n = rest.size();
          if (n > i) d.words.push_back(rest.substr(i, n - i));
          i = n + 1;
        }
        directives_.push_back(d);
      }
      for (std::size_t i = line_begin; i < line_end;) {
        if (is_ident_start(code_[i]) && (i == 0 || !is_ident_char(code_[i - 1]))) {
          std::size_t n = i;
          while (n < line_end && is_ident_char(code_[n])) ++n;
          words_.push_back({i, std::string_view(code_.data() + i, n - i)});
          i = n;
        } else {
          ++i;
        }
      }
      line_begin = line_end + 1;
    }
  }

  // "FILE:LINE" of an offset in the text.
  std::string where(std::size_t pos) const {
    auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), pos);
    int line = static_cast<int>(it - line_starts_.begin()) + source_.first_line - 1;
    return source_.file + ":" + std::to_string(line);
  }
  [[noreturn]] void fail(std::size_t pos, const std::string& message) const {
    throw CompileError(where(pos) + ": error: " + message);
  }
  void note(std::size_t pos, const std::string& what) { notes_.push_back({pos, what}); }
  void replace(std::size_t pos, std::size_t length, std::string with) {
    edits_.push_back({pos, length, std::move(with)});
  }

  // The compatibility-profile state piglit's shader_runner feeds, as declared variables.
  void rewrite_compatibility_state() {
    const auto declare = [&](std::string_view from, const char* to, const std::string& declaration) {
      const Word* first = find_word(from);
      if (!first) return;
      rename_all(from, to);
      declarations_.push_back(declaration);
      std::string what(from);  // appended piecewise, as rename_noted does
      what.append(" read as '").append(declaration).append("' (compatibility profile)");
      note(first->pos, what);
      fed_.push_back(from);
    };
    for (const auto& [from, to] : kCompatibilityMatrices)
      declare(from, to, std::string("uniform mat4 ") + to + ";");
    if (source_.stage == Stage::Vertex)
      declare("gl_Vertex", kCompatibilityVertex, std::string("in vec4 ") + kCompatibilityVertex + ";");
    if (source_.stage == Stage::Fragment) {
      declare("gl_Color", "tessref_Color", "in vec4 tessref_Color;");
      declare("gl_SecondaryColor", "tessref_SecondaryColor", "in vec4 tessref_SecondaryColor;");
    } else {
      if (source_.stage != Stage::TessControl) {
        declare("gl_FrontColor", "tessref_Color", "out vec4 tessref_Color;");
        declare("gl_FrontSecondaryColor", "tessref_SecondaryColor", "out vec4 tessref_SecondaryColor;");
        if (source_.clamp_vertex_color) clamp_vertex_colors();
      }
      rewrite_clip_vertex();
    }
  }

  // GL_CLAMP_VERTEX_COLOR: the colours this stage writes are clamped to [0, 1] per vertex, before
  // they are interpolated: when main() returns, or at each EmitVertex() of a geometry shader.
  void clamp_vertex_colors() {
    std::string clamps;
    for (const auto& [from, to] : {std::pair{"gl_FrontColor", "tessref_Color"},
                                   std::pair{"gl_FrontSecondaryColor", "tessref_SecondaryColor"}})
      if (find_word(from)) clamps.append(" ").append(to).append(" = clamp(").append(to).append(", 0.0, 1.0);");
    if (clamps.empty()) return;
    const bool geometry = source_.stage == Stage::Geometry;
    const char* entry = geometry ? "EmitVertex" : "main";
    const Word* first = find_word(entry);
    if (!first) return;
    rename_all(entry, geometry ? "tessref_EmitVertex" : "tessref_main");
    if (geometry)
      declarations_.push_back("void tessref_EmitVertex() {" + clamps + " EmitVertex(); }");
    else
      appendix_ = "\nvoid main() { tessref_main();" + clamps + " }\n";
    note(first->pos, std::string("vertex colours clamped to [0, 1] ") +
                         (geometry ? "at each EmitVertex()" : "when main() returns") +
                         " (compatibility profile: GL_CLAMP_VERTEX_COLOR)");
  }

  // gl_ClipVertex: the stage's output tessref_ClipVertex, gl_in[i].gl_ClipVertex the input array
  // tessref_ClipVertexIn[i], both at location 31 (the last), so that they meet across stages.
  void rewrite_clip_vertex() {
    const std::string out_name = kCompatibilityClipVertex, in_name = out_name + "In";
    bool written = false, read = false, arrayed_out = false;
    const Word* first = nullptr;
    for (const Word& w : words_) {
      if (w.text != "gl_ClipVertex") continue;
      first = first ? first : &w;
      const std::size_t dot = w.pos > 0 ? code_.find_last_not_of(" \t\r\n", w.pos - 1) : std::string::npos;
      if (dot == std::string::npos || code_[dot] != '.') {  // the stage's own output
        replace(w.pos, w.text.size(), out_name);
        written = true;
        continue;
      }
      // X[index].gl_ClipVertex, X being gl_in or gl_out: X becomes the array, ".gl_ClipVertex" goes.
      const std::size_t close = dot > 0 ? code_.find_last_not_of(" \t\r\n", dot - 1) : std::string::npos;
      std::size_t open = close;
      for (int depth = 0; open != std::string::npos && open > 0; --open) {
        if (code_[open] == ']') ++depth;
        if (code_[open] == '[' && --depth == 0) break;
      }
      const std::size_t name_end = open == std::string::npos || open == 0
                                       ? std::string::npos : code_.find_last_not_of(" \t\r\n", open - 1);
      const auto member_of = [&](std::string_view block) {
        return name_end != std::string::npos && name_end + 1 >= block.size() &&
               code_.compare(name_end + 1 - block.size(), block.size(), block) == 0;
      };
      const bool in = member_of("gl_in");
      if (close == std::string::npos || code_[close] != ']' || (!in && !member_of("gl_out")))
        fail(w.pos, "gl_ClipVertex as a member of something other than gl_in[i] or gl_out[i]");
      const std::size_t name = name_end + 1 - (in ? 5 : 6);
      replace(name, in ? 5 : 6, in ? in_name : out_name);
      replace(close + 1, w.pos + w.text.size() - (close + 1), "");
      (in ? read : arrayed_out) = true;
    }
    if (!first) return;
    if (read) declarations_.push_back("layout(location = 31) in vec4 " + in_name + "[];");
    if (written || arrayed_out)
      declarations_.push_back("layout(location = 31) out vec4 " + out_name + (arrayed_out ? "[];" : ";"));
    note(first->pos, "gl_ClipVertex read as '" + out_name + "' at location 31 (compatibility profile)");
    fed_.push_back("gl_ClipVertex");
  }

  void refuse_compatibility_state() const {
    for (const Word& w : words_)
      if (std::find(fed_.begin(), fed_.end(), w.text) != fed_.end()) continue;
      else if (const char* hint = compatibility_hint(w.text))
        fail(w.pos, "'" + std::string(w.text) +
                        "' is compatibility-profile fixed-function state, which tessref does not "
                        "support; " + hint + " instead");
  }

  // Every shader compiles as #version 450 core (460 stays 460): glslang's OpenGL SPIR-V path
  // needs 330 or later and refuses the compatibility profile.
  int rewrite_version() {
    auto it = std::find_if(directives_.begin(), directives_.end(), [](const Directive& d) {
      return !d.words.empty() && d.words[0] == "version";
    });
    if (it == directives_.end()) {
      note(0, "no #version (GLSL 1.10): compiled as #version 450 core");
      return 450;
    }
    const Directive& d = *it;
    if (code_.find_first_not_of(" \t\r\n\f\v") < d.begin)
      fail(d.begin, "#version must come before anything else but comments");
    const std::string_view number = d.words.size() > 1 ? d.words[1] : "";
    const std::string_view profile = d.words.size() > 2 ? d.words[2] : "";
    user_version_ = std::atoi(std::string(number).c_str());
    if (profile == "es" || number == "100")
      fail(d.begin, "OpenGL ES shaders are not supported (#version " + std::string(number) + " " +
                        std::string(profile) + "); tessref runs desktop GLSL 1.10 to 4.60");
    static constexpr std::array kKnown = {"110", "120", "130", "140", "150", "330", "400",
                                          "410", "420", "430", "440", "450", "460"};
    if (std::find(kKnown.begin(), kKnown.end(), number) == kKnown.end() || d.words.size() > 3 ||
        !(profile.empty() || profile == "core" || profile == "compatibility"))
      fail(d.begin, "unsupported #version line; tessref runs desktop GLSL 1.10 to 4.60");
    const int version = number == "460" ? 460 : 450;
    if (number != std::to_string(version) || profile == "compatibility")
      note(d.begin, "#version " + std::string(number) + (profile.empty() ? "" : " ") +
                        std::string(profile) + " compiled as #version " + std::to_string(version) +
                        " core");
    replace(d.begin, d.end - d.begin, "");
    return version;
  }

  void remove_core_extensions() {
    for (const Directive& d : directives_) {
      if (d.words.size() < 2 || d.words[0] != "extension") continue;
      if (std::find(kCoreExtensions.begin(), kCoreExtensions.end(), d.words[1]) ==
          kCoreExtensions.end())
        continue;
      std::string line = "#extension " + std::string(d.words[1]);
      if (d.words.size() > 2) line += " : " + std::string(d.words[2]);
      note(d.begin, "removed '" + line + "' (core in GLSL 4.50)");
      replace(d.begin, d.end - d.begin, "");
    }
  }

  // gl_FragColor and gl_FragData are not in 4.50 core: each becomes a declared output at
  // location 0 (gl_FragData: 8 draw buffers, GL's minimum and llvmpipe's count).
  void rewrite_fragment_outputs() {
    const Word* color = find_word("gl_FragColor");
    const Word* data = find_word("gl_FragData");
    if (color && data)
      fail(data->pos, "a fragment shader writes gl_FragColor or gl_FragData, not both");
    if (color) {
      rename_all("gl_FragColor", "tessref_FragColor");
      declarations_.push_back("layout(location = 0) out vec4 tessref_FragColor;");
      note(color->pos, "gl_FragColor written as 'layout(location = 0) out vec4 tessref_FragColor'");
    }
    if (data) {
      rename_all("gl_FragData", "tessref_FragData");
      declarations_.push_back("layout(location = 0) out vec4 tessref_FragData[8];");
      note(data->pos, "gl_FragData written as 'layout(location = 0) out vec4 tessref_FragData[8]'");
    }
  }

  // Pre-1.30 storage qualifiers: attribute (vertex inputs), varying (vertex outputs, fragment
  // inputs). Elsewhere they are errors, which glslang reports.
  void rewrite_storage_keywords() {
    if (source_.stage == Stage::Vertex) {
      rename_noted("attribute", "in");
      rename_noted("varying", "out");
    } else if (source_.stage == Stage::Fragment) {
      rename_noted("varying", "in");
    }
  }

  void rewrite_texture_functions() {
    for (const auto& [old_name, new_name] : kOldTextureFunctions)
      rename_noted(old_name, new_name);
  }

  // Whether the text redeclares the built-in block `storage gl_PerVertex` (GLSL 4.50, 7.1).
  bool redeclares(std::string_view storage) const {
    for (std::size_t i = 0; i + 1 < words_.size(); ++i)
      if (words_[i].text == storage && words_[i + 1].text == "gl_PerVertex") return true;
    return false;
  }

  const Word* find_word(std::string_view text) const {
    auto it = std::find_if(words_.begin(), words_.end(),
                           [&](const Word& w) { return w.text == text; });
    return it == words_.end() ? nullptr : &*it;
  }
  int rename_all(std::string_view from, std::string_view to) {
    int count = 0;
    for (const Word& w : words_)
      if (w.text == from) {
        replace(w.pos, w.text.size(), std::string(to));
        ++count;
      }
    return count;
  }
  // Renames every `from`, with one note at the first: "'varying' read as 'out' (3 times)".
  void rename_noted(std::string_view from, std::string_view to) {
    const Word* first = find_word(from);
    if (!first) return;
    const int count = rename_all(from, to);
    std::string what = "'";  // appended piecewise: GCC 12 warns (-Wrestrict) on "..." + string
    what.append(from).append("' read as '").append(to).append("'");
    if (count > 1) what.append(" (").append(std::to_string(count)).append(" times)");
    note(first->pos, what);
  }

  // "#version V core", the declarations, then "#line first_line" so that the user's text keeps
  // its line numbers (GLSL 3.30+: #line N numbers the next line N).
  RewrittenSource build(int version) {
    std::string text = source_.text;
    std::sort(edits_.begin(), edits_.end(),
              [](const Edit& a, const Edit& b) { return a.pos > b.pos; });
    for (const Edit& e : edits_) text.replace(e.pos, e.length, e.with);
    std::string header = "#version " + std::to_string(version) + " core\n";
    for (const std::string& d : declarations_) header += d + "\n";
    header += "#line " + std::to_string(source_.first_line) + "\n";
    std::stable_sort(notes_.begin(), notes_.end(),
                     [](const Note& a, const Note& b) { return a.pos < b.pos; });
    RewrittenSource out{header + text + appendix_, {}, user_version_, redeclares("in"), redeclares("out")};
    for (const Note& n : notes_) out.notes.push_back(where(n.pos) + ": " + n.what);
    return out;
  }

  struct Edit {
    std::size_t pos, length;
    std::string with;
  };
  struct Note {
    std::size_t pos;
    std::string what;
  };

  const ShaderSource& source_;
  std::vector<std::string_view> fed_;  // compatibility state rewritten, not refused
  std::string code_;
  std::vector<std::size_t> line_starts_;
  std::vector<Directive> directives_;
  std::vector<Word> words_;
  std::vector<Edit> edits_;
  std::vector<std::string> declarations_;
  std::string appendix_;  // after the user's text
  std::vector<Note> notes_;
  int user_version_ = 110;
};

}  // namespace

RewrittenSource rewrite_glsl(const ShaderSource& source) { return Rewriter(source).run(); }

}  // namespace tessref::shader
