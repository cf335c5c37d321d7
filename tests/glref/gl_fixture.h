#pragma once
// One GL context shared by every test in the binary; tests skip with the reason when the
// machine cannot create one. And one scene drawn by both tessref and the GL driver.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "glref/gl_context.h"
#include "glref/scene_renderer.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace tessref::glref::testing {

// Null when no context could be made; reason() says why.
GlContext* shared_context();
const std::string& context_failure();

// The default scene with the --set overrides `sets`, drawn by tessref's pipeline and then by the
// GL driver (SceneRenderer) into a framebuffer of the same size.
struct BothDraws {
  RenderResult ours;
  Framebuffer gl;
};
inline BothDraws draw_both(GlContext& ctx, const std::vector<std::string>& sets) {
  const Scene scene = load_scene("", sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  BothDraws d{render_scene(scene, mesh, Parallel()), {}};
  SceneRenderer renderer(ctx, scene, mesh);
  d.gl = renderer.render();
  return d;
}

}  // namespace tessref::glref::testing

#define TESSREF_REQUIRE_GL(ctx)                                                            \
  ::tessref::glref::GlContext* ctx = ::tessref::glref::testing::shared_context();          \
  if (!ctx) GTEST_SKIP() << "no GL 4.5 context: " << ::tessref::glref::testing::context_failure()
