// Layout rewrites, and tessref's GLSL twins (stages/) compiled through them on the driver.
#include <epoxy/gl.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "glref/gl_error.h"
#include "glref/gl_program.h"
#include "glref/glsl_rewrite.h"

namespace tessref::glref {
namespace {

TessLayout layout_of(TessDomain d, TessSpacing s, TessWinding w = TessWinding::Ccw, bool points = false) {
  TessLayout l;
  l.domain = d;
  l.spacing = s;
  l.winding = w;
  l.point_mode = points;
  return l;
}

TEST(GlslRewrite, SpecializeUniformsRewritesOnlyTheNamedScalarDeclarations) {
  const std::string src =
      "#version 450\n"
      "uniform int u_num_lights;  // how many\n"
      "uniform int u_num_lights2;\n"
      "uniform vec3 u_light_position[8];\n"
      "  uniform   bool u_adaptive ;\n"
      "void main() { }\n";
  const std::string out = specialize_uniforms(
      src, {{"u_num_lights", "1"}, {"u_adaptive", "false"}, {"u_light_position", "x"}, {"u_absent", "3"}});
  EXPECT_EQ(out,
            "#version 450\n"
            "const int u_num_lights = 1;  // how many\n"
            "uniform int u_num_lights2;\n"
            "uniform vec3 u_light_position[8];\n"
            "const bool u_adaptive = false;\n"
            "void main() { }\n");
  EXPECT_EQ(specialize_uniforms(src, {}), src);
}

TEST(GlslRewrite, LayoutQualifier) {
  EXPECT_EQ(tes_layout_qualifier(layout_of(TessDomain::Triangles, TessSpacing::FractionalOdd)),
            "layout(triangles, fractional_odd_spacing, ccw) in;\n");
  EXPECT_EQ(tes_layout_qualifier(layout_of(TessDomain::Quads, TessSpacing::Equal, TessWinding::Cw, true)),
            "layout(quads, equal_spacing, cw, point_mode) in;\n");
}

TEST(GlslRewrite, ReplacesTheTesLayoutLineAndDefinesTheDomain) {
  const std::string src =
      "#version 450\n// layout(triangles) in; in a comment is not at line start\n"
      "  layout(triangles, fractional_odd_spacing, ccw) in;  // default\n"
      "layout(location = 0) out vec3 p;\nvoid main() {}\n";
  EXPECT_EQ(set_tes_layout(src, layout_of(TessDomain::Isolines, TessSpacing::FractionalEven, TessWinding::Cw)),
            "#version 450\n#define TESSREF_ISOLINES\n// layout(triangles) in; in a comment is not at line start\n"
            "layout(isolines, fractional_even_spacing, cw) in;\n"
            "layout(location = 0) out vec3 p;\nvoid main() {}\n");
  const std::string tri = set_tes_layout(src, layout_of(TessDomain::Triangles, TessSpacing::Equal));
  EXPECT_EQ(tri.find("#define"), std::string::npos);
  EXPECT_NE(tri.find("\nlayout(triangles, equal_spacing, ccw) in;\n"), std::string::npos);
  EXPECT_THROW(set_tes_layout("#version 450\nvoid main() {}\n", TessLayout{}), GlError);
}

TEST(GlslRewrite, ReplacesTheTcsVertexCount) {
  EXPECT_EQ(set_tcs_vertices("#version 450\nlayout(vertices = 3) out;\nvoid main() {}\n", 4),
            "#version 450\nlayout(vertices = 4) out;\nvoid main() {}\n");
  EXPECT_THROW(set_tcs_vertices("#version 450\nvoid main() {}\n", 4), GlError);
}

std::string read_source(const std::string& relative) {
  std::ifstream in(std::string(TESSREF_SOURCE_DIR) + "/" + relative);
  if (!in) return {};
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// tessref's programs and their GLSL twins belong to stages/; this checks that glref can turn
// them into a program for every layout, which the scene renderer will need.
TEST(GlslTwins, FlatAndPnSchemesLinkForEveryLayout) {
  TESSREF_REQUIRE_GL(ctx);
  const std::string vs = read_source("stages/programs/transform.vert");
  const std::string fs = read_source("stages/programs/phong.frag");
  const std::string flat_tcs = read_source("stages/schemes/flat.tesc");
  const std::string flat_tes = read_source("stages/schemes/flat.tese");
  const std::string pn_tcs = read_source("stages/schemes/pn_triangles.tesc");
  const std::string pn_tes = read_source("stages/schemes/pn_triangles.tese");
  if (vs.empty() || fs.empty() || flat_tcs.empty() || flat_tes.empty())
    GTEST_SKIP() << "stages/ GLSL twins not found under " << TESSREF_SOURCE_DIR;
  int linked = 0;
  for (TessDomain d : {TessDomain::Triangles, TessDomain::Quads, TessDomain::Isolines})
    for (TessSpacing s : {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven})
      for (bool points : {false, true}) {
        const TessLayout layout = layout_of(d, s, TessWinding::Cw, points);
        const int n = d == TessDomain::Triangles ? 3 : d == TessDomain::Quads ? 4 : 2;
        SCOPED_TRACE(tes_layout_qualifier(layout));
        Program p = link_program({{GL_VERTEX_SHADER, vs, "transform.vert"},
                                  {GL_TESS_CONTROL_SHADER, set_tcs_vertices(flat_tcs, n), "flat.tesc"},
                                  {GL_TESS_EVALUATION_SHADER, set_tes_layout(flat_tes, layout), "flat.tese"},
                                  {GL_FRAGMENT_SHADER, fs, "phong.frag"}});
        linked += static_cast<bool>(p);
        if (d == TessDomain::Triangles && !pn_tcs.empty() && !pn_tes.empty()) {
          Program pn = link_program({{GL_VERTEX_SHADER, vs, "transform.vert"},
                                     {GL_TESS_CONTROL_SHADER, pn_tcs, "pn_triangles.tesc"},
                                     {GL_TESS_EVALUATION_SHADER, set_tes_layout(pn_tes, layout), "pn_triangles.tese"},
                                     {GL_FRAGMENT_SHADER, fs, "phong.frag"}});
          linked += static_cast<bool>(pn);
        }
      }
  EXPECT_GE(linked, 18);
}

}  // namespace
}  // namespace tessref::glref
