#pragma once
// Source rewrites that let glslang's OpenGL SPIR-V path (#version 450 core) take the GLSL that
// tessellation users write: other #version lines, #extension lines for features core in 4.50,
// gl_FragColor/gl_FragData, attribute/varying, texture2D() and its kin. Each rewrite applied is
// recorded as a note. Line numbers stay those of the user's file: the rewrites stay within their
// lines and a #line directive follows the inserted header. docs/glsl.md lists them all.
#include <string>
#include <vector>

#include "shader/glsl_compile.h"

namespace tessref::shader {

struct RewrittenSource {
  std::string text;                // for glslang: "#version 450 core" (or 460), header, #line
  std::vector<std::string> notes;  // "FILE:LINE: what was rewritten", one per rewrite
  int version = 110;               // the user's #version (110 without one)
  // The text redeclares `in gl_PerVertex` / `out gl_PerVertex` (a separable program must).
  bool redeclares_per_vertex_in = false, redeclares_per_vertex_out = false;
};

// Throws CompileError for what tessref refuses: an unknown or OpenGL ES #version, and
// compatibility-profile fixed-function state (gl_ModelViewProjectionMatrix, gl_ClipVertex, ...).
// With source.compatibility, the state a caller can feed becomes declared variables instead:
// gl_ModelViewProjectionMatrix, gl_ModelViewMatrix and gl_ProjectionMatrix the uniforms
// kCompatibilityMatrices name, gl_Vertex the vertex input kCompatibilityVertex, gl_FrontColor and
// the fragment shader's gl_Color the varying tessref_Color (gl_FrontSecondaryColor and
// gl_SecondaryColor tessref_SecondaryColor; source.clamp_vertex_color clamps both), a vertex,
// evaluation or geometry shader's gl_ClipVertex the output kCompatibilityClipVertex.
RewrittenSource rewrite_glsl(const ShaderSource& source);

inline constexpr const char* kCompatibilityVertex = "tessref_Vertex";
inline constexpr const char* kCompatibilityClipVertex = "tessref_ClipVertex";
inline constexpr const char* kCompatibilityMatrices[3][2] = {
    {"gl_ModelViewProjectionMatrix", "tessref_ModelViewProjectionMatrix"},
    {"gl_ModelViewMatrix", "tessref_ModelViewMatrix"},
    {"gl_ProjectionMatrix", "tessref_ProjectionMatrix"}};

}  // namespace tessref::shader
