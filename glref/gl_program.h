#pragma once
// Compiling and linking GLSL programs; failures throw GlError with the driver's info log.
#include <string>
#include <vector>

namespace tessref::glref {

struct ShaderStage {
  unsigned type;       // GL_VERTEX_SHADER, GL_TESS_CONTROL_SHADER, ...
  std::string source;  // full GLSL text
  std::string name;    // for messages, e.g. "tpg_capture.tese"
};

// Transform feedback: the varyings to capture, set before linking (glTransformFeedbackVaryings).
struct FeedbackVaryings {
  std::vector<std::string> names;
  bool interleaved = true;  // GL_INTERLEAVED_ATTRIBS, else GL_SEPARATE_ATTRIBS
};

// Vertex shader inputs bound to attribute locations before linking (glBindAttribLocation); an
// input with its own layout(location) keeps it.
using AttributeLocations = std::vector<std::pair<std::string, unsigned>>;

// A linked program object (move-only; deletes the program when destroyed).
class Program {
 public:
  Program() = default;
  explicit Program(unsigned id) : id_(id) {}
  ~Program();
  Program(Program&& o) noexcept : id_(o.id_) { o.id_ = 0; }
  Program& operator=(Program&& o) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  unsigned id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void use() const;
  // Location of a uniform; throws GlError if it is not active (a typo or optimised away).
  int uniform(const char* name) const;

 private:
  unsigned id_ = 0;
};

// Compiles one stage; returns the shader object. Throws GlError with the stage name and info log.
unsigned compile_shader(const ShaderStage& stage);
// Compiles and links; the shader objects are deleted after linking.
Program link_program(const std::vector<ShaderStage>& stages, const FeedbackVaryings& feedback = {},
                     const AttributeLocations& attributes = {});

const char* stage_name(unsigned type);  // "vertex", "tessellation control", ...

}  // namespace tessref::glref
