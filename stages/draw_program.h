#pragma once
// What a draw call runs: a program object as glUseProgram binds it. A user's GLSL program
// (stages/glsl/glsl_program.h) and the built-in C++ programs (render/builtin_program.h) both are
// one, so that every draw takes the same path (render/draw_call.h).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "raster/rasterizer.h"
#include "shader/spirv_module.h"
#include "stages/geometry_stage.h"
#include "stages/tess_stage.h"

namespace tessref {

// A vertex attribute array as the vertex shader reads it, by location: `components` words per
// vertex.
struct VertexAttribute {
  std::uint32_t location = 0;
  int components = 4;
  shader::Scalar scalar = shader::Scalar::F32;
  std::vector<std::uint32_t> words;  // vertex v's component k at v * components + k (doubles: 2 words)
  // Every vertex reads the first element: an instanced array's element for this instance, or a
  // disabled array's current value (glVertexAttrib*).
  bool constant = false;
};

// One vertex shader output the draw's --check tests: `components` floats of StageVertex slot `slot`.
struct CheckedOutput {
  int slot = 0;
  std::string name;
  int components = 4;
};

// How a draw's tessellation is cut into work: patches per chunk (tessellated, drawn, dropped) and
// per parallel task. Neither shows in the image.
struct TessGrain {
  std::size_t chunk_patches = 64;
  std::size_t task_patches = 4;
  // Whether the next chunk is tessellated while this one is drawn (tessellate_chunks). It pays for
  // the C++ programs on heavy frames (Wuson at level 64, 2 threads: 275 -> 233 ms); with the
  // SPIR-V executor on both sides it cost 5 to 10% (the GLSL twins, the textured frame), so
  // programs opt in.
  bool overlap_chunks = false;
};

class DrawProgram {
 public:
  virtual ~DrawProgram() = default;

  // Whether the program has a tessellation evaluation stage (it then draws GL_PATCHES only).
  virtual bool has_tes() const = 0;
  // Runs the vertex shader for vertices [first, first + count) of the attribute arrays of instance
  // `instance` (gl_InstanceID); gl_VertexID is vertex_ids[i] when given, else first + i. out
  // receives the outputs as the control stage reads them (gl_in[]).
  virtual void run_vertices(const std::vector<VertexAttribute>& attributes, std::size_t first,
                            std::size_t count, int instance, StageVertex* out, const Parallel& parallel,
                            const std::uint32_t* vertex_ids = nullptr) const = 0;
  // The rasterizer's vertex (vertex_records(varyings()) records) for a shaded vertex of an
  // untessellated draw. The default: slot 0 is gl_Position and location L sits at varying 4L.
  virtual void rasterizer_vertex(const StageVertex& shaded, ClipVertex* records) const;
  // The vertex shader outputs --check tests, in the order it tests them.
  virtual std::vector<CheckedOutput> checked_outputs() const;

  // Stage programs for tessellate() and draw_triangles(). default_outer/inner: the levels used
  // when there is no control stage (glPatchParameterfv); patch_vertices: GL_PATCH_VERTICES.
  virtual std::shared_ptr<const TessControlProgram> control(int patch_vertices, const glm::vec4& default_outer,
                                                            const glm::vec2& default_inner) const = 0;
  virtual std::shared_ptr<const TessEvalProgram> evaluation() const = 0;
  virtual std::shared_ptr<const FragmentProgram> fragment() const = 0;
  // The geometry shader, if any: it takes the vertex or evaluation stage's primitives, and its
  // output is what the rasterizer draws.
  virtual std::shared_ptr<const GeometryProgram> geometry() const { return nullptr; }
  // The untessellated vertex's varyings and which are flat.
  virtual int varyings() const = 0;
  virtual VaryingMask flat_varyings() const { return {}; }
  // Where the rasterizer's vertices carry gl_ClipDistance and gl_CullDistance (none by default).
  virtual DistanceVaryings distance_varyings() const { return {}; }

  // The primitive generator or uniform subdivision, and the work grain.
  virtual Tessellator tessellator() const { return Tessellator::PrimitiveGenerator; }
  virtual TessGrain tess_grain() const { return {}; }
  // A program whose invocations share state across the draw (atomic counters) runs on one thread,
  // so that the values each invocation sees do not depend on the thread count.
  virtual bool draws_serially() const { return false; }
  // Why GL would not draw with the program as bound ("" if it would).
  virtual std::string draw_refusal() const { return {}; }
};

}  // namespace tessref
