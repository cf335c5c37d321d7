#pragma once
// A scene drawn with GLSL on tessref's executor (scene key `shaders`): the built-in programs' GLSL
// twins, or the user's files. The scene's matrices, lights, material and tessellation settings
// reach the program as the uniforms the twins declare (the "scene uniforms", README), set whenever
// the program has one of that name; `shaders.uniforms` sets any other (or overrides them).
#include <memory>

#include "render/draw.h"
#include "render/draw_call.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "shader/glsl_compile.h"
#include "stages/glsl/glsl_program.h"

namespace tessref {

// The scene's program and the textures bound to it.
struct SceneProgram {
  std::unique_ptr<glsl::GlslProgram> program;
  std::vector<std::unique_ptr<texture::Texture>> textures;
  // The textures bound as images, by their uniform's name: what image stores change.
  std::vector<std::pair<std::string, texture::Texture*>> images;
  std::vector<std::string> warnings;  // incomplete textures
};

// The GLSL of the scene's program, stage by stage: the twins, or the user's files (`twin:NAME`
// resolved). InputError when a file cannot be read. The real-GL runner draws the same sources.
std::vector<shader::ShaderSource> scene_sources(const Scene& scene);
// The same for one draw's own program (Scene::draws[].shaders), with the scene's uniforms.
std::vector<shader::ShaderSource> scene_sources(const Scene& scene, const ShaderSettings& shaders);

// Compiles the scene's program (InputError: a file that cannot be read, compile and link errors
// with file and line, a uniform value whose type does not fit, an unreadable texture) with its
// uniforms set and its textures bound.
SceneProgram build_scene_program(const Scene& scene);
// storage: the bytes bound at each shader storage binding when it draws (they size runtime arrays).
SceneProgram build_scene_program(const Scene& scene, const ShaderSettings& shaders,
                                 const shader::StorageBufferSizes& storage = {});

// The draw's vertex attribute arrays (shaders.attributes: the mesh's positions and normals by input
// name or location) and the draw call (indices, GL_PATCH_VERTICES) draw_glsl_scene makes; also
// what tessref inspect reruns.
std::vector<glsl::VertexAttribute> scene_attributes(const Scene& scene, const glsl::GlslProgram& program,
                                                   const Mesh& mesh);
DrawCall scene_draw_call(const Scene& scene, const Mesh& mesh);

// Draws the mesh with the scene's GLSL program into fb (already cleared).
DrawStats draw_glsl_scene(const Scene& scene, const glsl::GlslProgram& program, const Mesh& mesh,
                          Framebuffer& fb, const Parallel& parallel, const DrawOptions& options);

}  // namespace tessref
