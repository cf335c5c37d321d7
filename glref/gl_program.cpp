#include "glref/gl_program.h"

#include <epoxy/gl.h>

#include "glref/gl_error.h"

namespace tessref::glref {
namespace {

std::string shader_log(GLuint shader) {
  GLint len = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
  std::string log(len > 0 ? len : 0, '\0');
  if (len > 0) glGetShaderInfoLog(shader, len, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

std::string program_log(GLuint program) {
  GLint len = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
  std::string log(len > 0 ? len : 0, '\0');
  if (len > 0) glGetProgramInfoLog(program, len, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

}  // namespace

const char* stage_name(unsigned type) {
  switch (type) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_TESS_CONTROL_SHADER: return "tessellation control";
    case GL_TESS_EVALUATION_SHADER: return "tessellation evaluation";
    case GL_GEOMETRY_SHADER: return "geometry";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_COMPUTE_SHADER: return "compute";
  }
  return "unknown";
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

Program& Program::operator=(Program&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteProgram(id_);
    id_ = o.id_;
    o.id_ = 0;
  }
  return *this;
}

void Program::use() const { glUseProgram(id_); }

int Program::uniform(const char* name) const {
  GLint loc = glGetUniformLocation(id_, name);
  if (loc < 0) throw GlError(std::string("uniform ") + name + " is not active in program " + std::to_string(id_));
  return loc;
}

unsigned compile_shader(const ShaderStage& stage) {
  GLuint s = glCreateShader(stage.type);
  if (!s) throw GlError(std::string("glCreateShader(") + stage_name(stage.type) + ") failed for " + stage.name);
  const char* src = stage.source.c_str();
  const GLint len = static_cast<GLint>(stage.source.size());
  glShaderSource(s, 1, &src, &len);
  glCompileShader(s);
  GLint ok = GL_FALSE;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::string log = shader_log(s);
    glDeleteShader(s);
    throw GlError("compiling " + std::string(stage_name(stage.type)) + " shader " + stage.name +
                  " failed:\n" + log);
  }
  return s;
}

Program link_program(const std::vector<ShaderStage>& stages, const FeedbackVaryings& feedback,
                     const AttributeLocations& attributes) {
  Program program(glCreateProgram());
  if (!program) throw GlError("glCreateProgram failed");
  std::vector<GLuint> shaders;
  std::string names;
  try {
    for (const ShaderStage& st : stages) {
      shaders.push_back(compile_shader(st));
      glAttachShader(program.id(), shaders.back());
      names += (names.empty() ? "" : ", ") + st.name;
    }
  } catch (...) {
    for (GLuint s : shaders) glDeleteShader(s);
    throw;
  }
  if (!feedback.names.empty()) {
    std::vector<const char*> ptrs;
    for (const std::string& n : feedback.names) ptrs.push_back(n.c_str());
    glTransformFeedbackVaryings(program.id(), static_cast<GLsizei>(ptrs.size()), ptrs.data(),
                                feedback.interleaved ? GL_INTERLEAVED_ATTRIBS : GL_SEPARATE_ATTRIBS);
  }
  for (const auto& [name, location] : attributes) glBindAttribLocation(program.id(), location, name.c_str());
  glLinkProgram(program.id());
  for (GLuint s : shaders) {
    glDetachShader(program.id(), s);
    glDeleteShader(s);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) throw GlError("linking program (" + names + ") failed:\n" + program_log(program.id()));
  check_gl(("linking program (" + names + ")").c_str());
  return program;
}

}  // namespace tessref::glref
