#pragma once
// One scene, one image: the scene's programs and matrices set up around the draw call.
#include <cstdint>
#include <optional>

#include "common/parallel.h"
#include "render/draw.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "raster/framebuffer.h"
#include "stages/programs/normals.h"
#include "stages/programs/phong.h"

namespace tessref {

struct FeedbackBuffers;  // render/transform_feedback.h
struct DrawnMemory;      // render/draw_scene.h

struct RenderResult {
  Framebuffer framebuffer;
  DrawStats stats;
};

RenderResult render_scene(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                          const DrawOptions& options = {});
// The same frame into fb, whose memory is reused when its size matches the scene's (repeated
// frames: --repeat, benchmarks). The bytes of fb are those render_scene would return. With
// `feedback`, a scene of draws appends what its draws' transform feedback records; with
// `memory`, it receives the buffers and images as the draws left them (render/draw_scene.h).
DrawStats render_scene(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                       Framebuffer& fb, const DrawOptions& options = {},
                       std::vector<FeedbackBuffers>* feedback = nullptr, DrawnMemory* memory = nullptr);

// The built-in fragment program the scene's shading names, with the scene's uniforms: the object
// render_scene draws with (shaders.program builtin), for tools that run it themselves.
struct BuiltinFragmentProgram {
  programs::PhongShader phong;
  programs::NormalsShader normals;
  bool use_phong = true;
  const FragmentProgram& get() const {
    return use_phong ? static_cast<const FragmentProgram&>(phong) : normals;
  }
};
BuiltinFragmentProgram builtin_fragment_program(const Scene& scene);

// The number of TES invocations the draw will run, where it is known before drawing: built-in
// programs with the scene's fixed levels (every patch then has the same domain). Empty for
// adaptive levels and GLSL programs, whose control shaders decide per patch.
std::optional<std::uint64_t> predicted_tes_invocations(const Scene& scene, const Mesh& mesh);

}  // namespace tessref
