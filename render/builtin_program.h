#pragma once
// The built-in programs a scene is drawn with (shaders.program builtin) as one program object, built
// in one place so that the draw (render/draw.cpp, render/render.cpp) and tools that rerun part of it
// (tessref inspect) construct the very same program objects with the same uniforms.
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/mesh.h"
#include "scene/scene.h"
#include "scene/tessellation_settings.h"
#include "stages/programs/transform.h"
#include "stages/schemes/displacement.h"
#include "stages/schemes/flat.h"
#include "stages/schemes/nagata.h"
#include "stages/schemes/nlsa.h"
#include "stages/schemes/phong.h"
#include "stages/schemes/pn_triangles.h"
#include "stages/schemes/quadratic_patch.h"
#include "stages/schemes/scalar_tagged_pn.h"
#include "stages/draw_program.h"
#include "stages/tess_stage.h"

namespace tessref {

// The scene's vertex shader: model matrix from scene.transform, view-projection from its camera
// (already fitted, if camera.fit) and image size.
programs::TransformVertexShader scene_vertex_shader(const Scene& scene);

// The control and evaluation programs of the scheme the settings name. Holds every pair;
// tcs()/tes() pick the one the draw runs. viewport: the framebuffer's size in pixels
// (adaptive levels).
struct BuiltinTessPrograms {
  PassThroughTcs flat_tcs;
  FlatTes flat_tes;
  PnTcs pn_tcs;
  PnTes pn_tes;
  PhongTcs phong_tcs;
  NlsaTcs nlsa_tcs;
  NagataTcs nagata_tcs;
  ScalarTaggedPnTcs tagged_pn_tcs;  // evaluated by pn_tes
  QuadraticTes quadratic_tes;  // the evaluation program of phong, nlsa and nagata
  SurfaceScheme scheme = SurfaceScheme::PN;
  const TessControlProgram& tcs() const {
    switch (scheme) {
      case SurfaceScheme::Flat: return flat_tcs;
      case SurfaceScheme::PN: return pn_tcs;
      case SurfaceScheme::Phong: return phong_tcs;
      case SurfaceScheme::NLSA: return nlsa_tcs;
      case SurfaceScheme::Nagata: return nagata_tcs;
      case SurfaceScheme::ScalarTaggedPN: return tagged_pn_tcs;
    }
    return pn_tcs;
  }
  const TessEvalProgram& scheme_tes() const {
    switch (scheme) {
      case SurfaceScheme::Flat: return flat_tes;
      case SurfaceScheme::PN: return pn_tes;
      case SurfaceScheme::Phong:
      case SurfaceScheme::NLSA:
      case SurfaceScheme::Nagata: return quadratic_tes;
      case SurfaceScheme::ScalarTaggedPN: return pn_tes;
    }
    return pn_tes;
  }
  // tessellation.displacement on top of the scheme's TES. Its base is bound here, on each call,
  // because this struct is returned and copied by value.
  mutable DisplacedTes displaced;
  const TessEvalProgram& tes() const {
    if (!displaced.displacement.enabled) return scheme_tes();
    displaced.base = &scheme_tes();
    return displaced;
  }
};
BuiltinTessPrograms builtin_tess_programs(const TessellationSettings& settings,
                                          const programs::TransformVertexShader& vs,
                                          const glm::vec2& viewport);

// The built-in C++ programs as a program object: the scene's transform vertex shader (positions
// at location 0, normals at location 1, three floats each), the scheme's control and evaluation
// programs when tessellating, and a fragment program. Its vertex outputs are what the built-in
// control programs read: kAttrPosition = (world, 1), kAttrNormal = (normal, 0), the scalar-tagged
// scheme's kAttrTags and kAttrCrease, and gl_Position at kAttrClipPosition.
inline constexpr int kAttrClipPosition = 4;
class BuiltinProgram final : public DrawProgram {
 public:
  // viewport: the framebuffer's size (adaptive levels). tags: the scalar-tagged PN scheme's, by
  // vertex (load_vertex_tags), else empty. fs must outlive the program.
  BuiltinProgram(const programs::TransformVertexShader& vs, const TessellationSettings& settings,
                 const glm::vec2& viewport, const FragmentProgram& fs, std::vector<VertexTags> tags = {});

  bool has_tes() const override { return settings_.enabled; }
  void run_vertices(const std::vector<VertexAttribute>& attributes, std::size_t first, std::size_t count,
                    int instance, StageVertex* out, const Parallel& parallel,
                    const std::uint32_t* vertex_ids = nullptr) const override;
  void rasterizer_vertex(const StageVertex& shaded, ClipVertex* records) const override;
  std::vector<CheckedOutput> checked_outputs() const override;
  std::shared_ptr<const TessControlProgram> control(int patch_vertices, const glm::vec4& default_outer,
                                                    const glm::vec2& default_inner) const override;
  std::shared_ptr<const TessEvalProgram> evaluation() const override;
  std::shared_ptr<const FragmentProgram> fragment() const override;
  int varyings() const override { return kBuiltinVaryings; }
  Tessellator tessellator() const override { return settings_.tessellator; }
  TessGrain tess_grain() const override;

  const programs::TransformVertexShader& vertex_shader() const { return vs_; }
  const BuiltinTessPrograms& tess_programs() const { return programs_; }

 private:
  programs::TransformVertexShader vs_;
  TessellationSettings settings_;
  BuiltinTessPrograms programs_;
  const FragmentProgram& fs_;
  std::vector<VertexTags> tags_;
};

// The mesh as the built-in vertex shader reads it: positions at location 0, normals at location 1.
std::vector<VertexAttribute> mesh_attributes(const Mesh& mesh);

}  // namespace tessref
