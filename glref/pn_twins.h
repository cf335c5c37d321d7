#pragma once
// tessref's GLSL twins (stages/programs/transform.vert + stages/schemes/{flat,pn_triangles}.tes*)
// linked as one GL program for a given layout, with the uniforms the C++ programs take, so the
// driver can run exactly what PnTcs/PnTes (or PassThroughTcs/FlatTes) run in tessref.
#include <string>

#include <glm/glm.hpp>

#include "glref/gl_program.h"
#include "stages/schemes/pn_triangles.h"
#include "stages/tess_levels_adaptive.h"
#include "stages/tpg.h"

namespace tessref::glref {

// What transform feedback records per emitted TES vertex (interleaved 32-bit words).
enum class TwinCapture {
  None,            // no feedback varyings (drawing)
  PositionNormal,  // v_world_position, v_world_normal: 6 words
  Full,            // + gl_TessCoord (3 floats) + u_patch_base + gl_PrimitiveID (int): 10 words
};
int twin_capture_words(TwinCapture c);

struct TwinSetup {
  bool pn = true;  // false: the flat scheme (pass-through TCS, barycentric TES)
  PnNormalMode normal_mode = PnNormalMode::Quadratic;
  TessLayout layout{TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw, false};
  TessLevelSettings levels;
  glm::mat4 model{1.0f};
  glm::mat4 view_proj{1.0f};  // the VS's u_view_projection and the TES's u_view_proj
};

// The twins' text, read from the source tree (TESSREF_SOURCE_DIR) at run time: they belong to
// stages/, not to glref's embedded shaders. Throws GlError when a file is missing.
std::string twin_source(const std::string& relative_path);

// Compiles and links VS + TCS + TES (triangles; layout rewritten from setup.layout). With
// TwinCapture::Full the TES's main is wrapped to also write tf_tess_coord and tf_patch_id.
Program link_twin_program(const TwinSetup& setup, TwinCapture capture);

// Sets every uniform the twins read (those the driver kept), as the C++ programs hold them:
// u_normal_matrix is the inverse transpose of mat3(model), as TransformVertexShader::from.
void set_twin_uniforms(const Program& program, const TwinSetup& setup);

}  // namespace tessref::glref
