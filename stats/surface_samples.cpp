#include "stats/surface_samples.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/error.h"
#include "render/builtin_program.h"
#include "inspect/fragment_dump.h"
#include "stages/tess_stage.h"
#include "stats/surface_stats.h"

namespace tessref::stats {
namespace {

constexpr std::size_t kDumpChannels = 12;  // kFragmentDumpChannels, in that order

// The scheme as one of bezier_nets' interpolants, with the scene's parameters. Flat is Phong
// tessellation with alpha 0: its mid-edge points are the edge midpoints, the net the triangle.
schemes::Interpolant interpolant(const TessellationSettings& t, schemes::InterpolantParams& params) {
  params.phong_alpha = t.phong_alpha;
  params.nagata_eps = t.nagata_eps;
  switch (t.scheme) {
    case SurfaceScheme::Flat: params.phong_alpha = 0.0; return schemes::Interpolant::Phong;
    case SurfaceScheme::PN: return schemes::Interpolant::PN;
    case SurfaceScheme::Phong: return schemes::Interpolant::Phong;
    case SurfaceScheme::NLSA: return schemes::Interpolant::NLSA;
    case SurfaceScheme::Nagata: return schemes::Interpolant::Nagata;
    case SurfaceScheme::ScalarTaggedPN: break;
  }
  throw std::logic_error("surface_samples: no Bézier net for this scheme");
}

void check_scene(const Scene& scene, const char* option) {
  const std::string o(option);
  if (scene.shaders.program != ShaderProgram::Builtin)
    throw InputError(o + ": needs the built-in programs (shaders.program builtin): the exact surface "
                     "is known only for tessref's own schemes, not for GLSL programs");
  const TessellationSettings& t = scene.tessellation;
  if (!t.enabled)
    throw InputError(o + ": the scene does not tessellate (tessellation.enabled is false): there is no "
                     "patch surface to evaluate");
  if (t.scheme == SurfaceScheme::ScalarTaggedPN)
    throw InputError(o + ": tessellation.scheme scalar_tagged_pn is not supported: its tags bend the "
                     "net per vertex (docs/scalar-tagged-pn.md); use flat, pn, phong, nlsa or nagata");
  if (t.displacement.enabled)
    throw InputError(o + ": tessellation.displacement moves the surface off the scheme's Bézier net; "
                     "turn it off for surface images");
}

}  // namespace

std::vector<schemes::CubicNet<float>> world_patches(const Scene& scene, const Mesh& mesh,
                                                    const Parallel& parallel) {
  schemes::InterpolantParams params;
  const schemes::Interpolant s = interpolant(scene.tessellation, params);
  const programs::TransformVertexShader vs = scene_vertex_shader(scene);
  std::vector<schemes::CubicNet<float>> nets(mesh.triangle_count());
  parallel.for_each(nets.size(), [&](std::size_t t) {
    glm::vec3 p[3], n[3];
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = mesh.indices[3 * t + c];
      const programs::VertexOut out = vs.main(mesh.positions[v], mesh.normals[v]);
      p[c] = out.v_world_position;
      n[c] = safe_normalize(out.v_world_normal);  // as the control programs take it
    }
    nets[t] = schemes::cubic_net<float>(s, p, n, params);
  });
  return nets;
}

SurfaceSamples sample_surface(const Scene& scene, const Mesh& mesh, const Parallel& parallel,
                              const char* option) {
  check_scene(scene, option);
  const bool flat = scene.tessellation.scheme == SurfaceScheme::Flat;
  const std::vector<schemes::CubicNet<float>> float_nets = world_patches(scene, mesh, parallel);
  std::vector<schemes::CubicNet<double>> nets;
  for (const schemes::CubicNet<float>& f : float_nets) nets.push_back(widen(f));

  SurfaceSamples out;
  out.width = scene.width;
  out.height = scene.height;
  out.eye = glm::dvec3(scene.camera.eye);
  const glm::mat4 model = scene_vertex_shader(scene).u_model;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  std::vector<glm::dvec3> world(mesh.vertex_count());
  for (std::size_t v = 0; v < world.size(); ++v) {
    world[v] = glm::dvec3(glm::vec3(model * glm::vec4(mesh.positions[v], 1.0f)));
    lo = glm::min(lo, world[v]);
    hi = glm::max(hi, world[v]);
  }
  out.centre = (lo + hi) * 0.5;
  for (const glm::dvec3& w : world) out.radius = std::max(out.radius, glm::length(w - out.centre));

  const FragmentDump dump = dump_fragments(scene, mesh, parallel);
  if (kFragmentDumpChannels.size() != kDumpChannels)
    throw std::logic_error("surface_samples: the fragment dump's channels changed");
  out.pixels.resize(std::size_t(out.width) * std::size_t(out.height));
  parallel.for_each(out.pixels.size(), [&](std::size_t i) {
    const float* px = dump.pixels.data() + i * kDumpChannels;
    if (px[6] < 0.0f) return;  // patch_id -1: nothing drawn
    SurfaceSample& s = out.pixels[i];
    s.covered = true;
    s.patch = std::uint32_t(px[6]);
    if (s.patch >= nets.size())
      throw std::logic_error("surface_samples: a fragment names patch " + std::to_string(s.patch) +
                             " of " + std::to_string(nets.size()));
    s.tess_coord = {px[8], px[9], px[10]};
    // bezier_nets' (u, v) are the weights of corners 1 and 2, gl_TessCoord's y and z.
    const schemes::SurfacePoint<double> e = schemes::evaluate(nets[s.patch], s.tess_coord.y, s.tess_coord.z);
    s.position = e.position;
    s.position_deviation = glm::length(e.position - glm::dvec3(px[0], px[1], px[2]));
    const glm::dvec3 fn(px[3], px[4], px[5]);
    if (glm::dot(fn, fn) > 0.0) s.fragment_normal = glm::normalize(fn);
    s.normal = schemes::analytic_normal(e);
    if (glm::dot(s.normal, s.fragment_normal) < 0.0) s.normal = -s.normal;
    // A plane has K = 0 exactly; the elevated float net would give rounding noise instead.
    s.gaussian_curvature = flat ? 0.0 : gaussian_curvature(e);
  });
  return out;
}

}  // namespace tessref::stats
