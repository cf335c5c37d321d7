#include "glref/pn_twins.h"

#include <epoxy/gl.h>

#include <fstream>
#include <glm/gtc/type_ptr.hpp>
#include <sstream>

#include "glref/gl_error.h"
#include "glref/glsl_rewrite.h"
#include "glref/shader_source.h"

namespace tessref::glref {
namespace {

// Appends a main() that runs the twin's own (renamed) main and then records the domain point and
// the draw-independent patch index, so captures can be matched record by record.
std::string wrap_tes_for_full_capture(const std::string& tes) {
  const std::string decl = "void main()";
  const std::size_t at = tes.find(decl);
  if (at == std::string::npos || tes.find(decl, at + 1) != std::string::npos)
    throw GlError("pn_twins: expected exactly one 'void main()' in the TES twin");
  std::string out = tes;
  out.replace(at, decl.size(), "void twin_main()");
  out = inject_after_version(out, "out vec3 tf_tess_coord;\nout int tf_patch_id;\nuniform int u_patch_base;\n");
  out += "\nvoid main() {\n  twin_main();\n  tf_tess_coord = gl_TessCoord;\n"
         "  tf_patch_id = u_patch_base + gl_PrimitiveID;\n}\n";
  return out;
}

int normal_mode_index(PnNormalMode m) {
  switch (m) {
    case PnNormalMode::Linear: return 0;
    case PnNormalMode::Quadratic: return 1;
    case PnNormalMode::QuadraticCorrected: return 2;
    case PnNormalMode::Analytic: return 3;
  }
  return 1;
}

}  // namespace

int twin_capture_words(TwinCapture c) {
  return c == TwinCapture::Full ? 10 : c == TwinCapture::PositionNormal ? 6 : 0;
}

std::string twin_source(const std::string& relative_path) {
  const std::string path = std::string(TESSREF_SOURCE_DIR) + "/" + relative_path;
  std::ifstream in(path);
  if (!in) throw GlError("pn_twins: cannot read " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Program link_twin_program(const TwinSetup& setup, TwinCapture capture) {
  if (setup.layout.domain != TessDomain::Triangles)
    throw GlError("pn_twins: the twins are linked for triangle patches only");
  const std::string scheme = setup.pn ? "stages/schemes/pn_triangles" : "stages/schemes/flat";
  std::string tes = set_tes_layout(twin_source(scheme + ".tese"), setup.layout);
  if (capture == TwinCapture::Full) tes = wrap_tes_for_full_capture(tes);
  std::vector<std::string> varyings;
  if (capture != TwinCapture::None) varyings = {"v_world_position", "v_world_normal"};
  if (capture == TwinCapture::Full) varyings.insert(varyings.end(), {"tf_tess_coord", "tf_patch_id"});
  return link_program({{GL_VERTEX_SHADER, twin_source("stages/programs/transform.vert"), "transform.vert"},
                       {GL_TESS_CONTROL_SHADER, twin_source(scheme + ".tesc"), scheme + ".tesc"},
                       {GL_TESS_EVALUATION_SHADER, tes, scheme + ".tese"}},
                      FeedbackVaryings{varyings, true});
}

void set_twin_uniforms(const Program& program, const TwinSetup& setup) {
  program.use();
  auto loc = [&](const char* name) { return glGetUniformLocation(program.id(), name); };
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(setup.model)));
  const TessLevelSettings& lv = setup.levels;
  const AdaptiveLevelSettings& s = lv.screen;
  int l;
  if ((l = loc("u_model")) >= 0) glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(setup.model));
  if ((l = loc("u_view_projection")) >= 0) glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(setup.view_proj));
  if ((l = loc("u_normal_matrix")) >= 0) glUniformMatrix3fv(l, 1, GL_FALSE, glm::value_ptr(normal_matrix));
  if ((l = loc("u_normal_mode")) >= 0) glUniform1i(l, normal_mode_index(setup.normal_mode));
  if ((l = loc("u_adaptive")) >= 0) glUniform1i(l, lv.adaptive ? 1 : 0);
  if ((l = loc("u_outer")) >= 0) glUniform4fv(l, 1, lv.constant.outer.data());
  if ((l = loc("u_inner")) >= 0) glUniform2fv(l, 1, lv.constant.inner.data());
  // The adaptive levels use the settings' own matrix (the pipeline sets it to the camera's).
  if ((l = loc("u_view_proj")) >= 0) {
    // One name, two meanings in the twins: the TCS's adaptive matrix and the TES's gl_Position
    // matrix. They are the same matrix in every tessref draw; insist on it.
    if (lv.adaptive && s.view_proj != setup.view_proj)
      throw GlError("pn_twins: levels.screen.view_proj must equal view_proj (one uniform in GLSL)");
    glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(setup.view_proj));
  }
  if ((l = loc("u_viewport")) >= 0) glUniform2f(l, s.viewport_pixels.x, s.viewport_pixels.y);
  if ((l = loc("u_pixels_per_segment")) >= 0) glUniform1f(l, s.pixels_per_segment);
  if ((l = loc("u_min_level")) >= 0) glUniform1f(l, s.min_level);
  if ((l = loc("u_max_level")) >= 0) glUniform1f(l, s.max_level);
  if ((l = loc("u_inner_rule")) >= 0) glUniform1i(l, s.inner_rule == InnerLevelRule::Max ? 0 : 1);
  check_gl("pn_twins: setting uniforms");
}

}  // namespace tessref::glref
