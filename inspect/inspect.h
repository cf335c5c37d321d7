#pragma once
// tessref inspect: the life of one patch of a scene's draw, stage by stage, as the draw computes it.
// Nothing here re-derives a value: the scene's own program objects (builtin_program.h, or the GLSL
// program on the executor) run on the patch through the same executor (tessellate() over
// [patch, patch + 1)), and what each stage handed to the next is recorded on the way.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "inspect/inspect_trace.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "shader/spirv_module.h"
#include "stages/tess_stage.h"
#include "stages/tpg_levels.h"

namespace tessref {

struct InspectRequest {
  std::optional<std::size_t> draw;  // a scene of draws: which (Scene::draws index; none: draw 0)
  std::size_t patch = 0;  // a scene of draws: counted over the draw's calls and instances in order
  std::optional<glm::vec3> coord;      // evaluate the TES here (need not be a generated point)
  bool coord_has_w = true;             // false: z is filled in, (1 - u) - v for triangles (as the
                                       // generator computes it), 0 for quads and isolines
  std::optional<std::size_t> vertex;   // the patch's K-th generated domain point
  // Neither: every generated point.
  unsigned trace = 0;  // the stages to trace at source level (inspect_trace.h's TraceStages)
};

// A vertex shader input of a scene of draws, as fetched and converted (its words by scalar type).
struct InspectInput {
  std::uint32_t location = 0;
  shader::Scalar scalar = shader::Scalar::F32;
  std::vector<std::uint32_t> words;
};

// One corner of the patch (gl_in[k] of the TCS).
struct InspectCorner {
  std::uint32_t vertex = 0;   // the mesh path: index into the mesh's vertex arrays; draws: gl_VertexID
  glm::vec3 in_position{0.0f}, in_normal{0.0f};  // the mesh path: the mesh's attributes
  std::vector<InspectInput> inputs;              // draws: the vertex shader's inputs
  StageVertex vs_out;              // the vertex stage's output as the TCS received it
  std::optional<glm::vec4> gl_position;  // built-in vertex shader: its gl_Position (not passed on)
};

// One TES invocation.
struct InspectPoint {
  std::optional<std::size_t> index;  // generation order within the patch; none: a --coord off the pattern
  glm::vec3 tess_coord{0.0f};
  glm::vec4 gl_position{0.0f};
  std::vector<float> varyings;      // the TES's num_varyings outputs
  glm::vec3 position{0.0f}, normal{0.0f};  // world position and normal, as --dump-tess records them
  std::vector<std::size_t> primitives;     // the patch's triangles (emission order) using this point
};

// Where a scene of draws' patch lies: gl_PrimitiveID within one instance of one call.
struct InspectDrawPatch {
  std::size_t draw = 0, call = 0;
  int instance = 0;          // gl_InstanceID
  std::size_t primitive_id = 0;
  std::uint32_t patch_id = 0;  // its number in --dump-tess and capture files (draw_scene.h patch_numbering)
};

struct InspectResult {
  std::string program;           // "builtin pn (quadratic normals)", "glsl twins", "glsl custom"
  bool builtin_pn = false;       // the TCS output follows pn_triangles.h's layout
  bool builtin_quadratic = false;  // ... quadratic_patch.h's (phong, nlsa, nagata)
  std::size_t patch = 0, patch_count = 0;
  std::optional<InspectDrawPatch> draw;    // a scene of draws
  std::string vertex_name = "mesh vertex";  // what InspectCorner::vertex counts
  int patch_vertices = 3;
  std::vector<InspectCorner> corners;
  int tcs_vertices = 0, tcs_phases = 1;
  PatchOutput tcs_out;           // gl_out[], patch out, levels: what the executor handed the TES
  TessLayout layout;
  Tessellator tessellator = Tessellator::PrimitiveGenerator;
  ProcessedTessLevels levels;    // the generator's reading of tcs_out.levels
  std::size_t domain_points = 0, primitives = 0;
  int vertices_per_primitive = 3;
  bool discarded = false;
  int num_varyings = 0;
  std::array<int, 2> dump_varyings{kVaryingPosition, kVaryingNormal};
  std::vector<InspectPoint> points;  // the requested ones
  // Source-level traces (request.trace): the vertex shader at each corner, each control shader
  // invocation, the evaluation shader at the one requested point (none when all points are).
  std::vector<InspectTrace> traces;
  bool traced_twins = false;  // the built-in programs, traced through their GLSL twins
};

// Runs the scene's draw on one patch. The scene's camera must already be fitted (as render does).
// InputError for a patch past the draw (message names --patch and the patch count), a --vertex past
// the patch's domain points, a --coord off the domain, or a scene that does not tessellate.
InspectResult inspect_patch(const Scene& scene, const Mesh& mesh, const InspectRequest& request);
// The same for patch request.patch of draw request.draw of a scene of draws, with its own buffers,
// program and GL state (the uniform buffers the earlier draws bound included). InputError for a
// draw past the scene or one that is not GL_PATCHES, and as inspect_patch.
InspectResult inspect_draw_patch(const Scene& scene, const InspectRequest& request);

}  // namespace tessref
