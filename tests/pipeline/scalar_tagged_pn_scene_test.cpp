// tessellation.scheme = scalar_tagged_pn through the pipeline: without tags, or with every tag
// neutral, the draw is PN's bit for bit; with a crease the GLSL twins (tagged_transform.vert,
// scalar_tagged_pn.tesc, pn_triangles.tese) on the executor give the C++ programs' records bit for
// bit; and the sidecar's errors name the file, the vertex (or triangle) and the rule.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/error.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "mesh/vertex_tags.h"
#include "test_util.h"
#include "twins_test_util.h"

namespace tessref {
namespace {

const std::vector<std::string> kIcosphere = {"mesh.type=icosphere", "mesh.icosphere.refinements=1",
                                             "image.width=160", "image.height=160"};

using test::differing_records;
using test::Frame;

Frame render(std::vector<std::string> sets) {
  sets.insert(sets.end(), kIcosphere.begin(), kIcosphere.end());
  return test::render_frame(sets);
}

Mesh icosphere() {
  const Scene scene = load_scene("", kIcosphere);
  std::vector<std::string> warnings;
  return build_mesh(scene.mesh, warnings);
}

std::string number(float f) { return std::to_string(double(f)); }
std::string vec(const glm::vec3& v) { return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]"; }

// A sidecar: one entry per vertex, `entries` replacing the empty ones.
std::string sidecar(std::size_t vertices, const std::map<std::size_t, std::string>& entries) {
  std::string s = "{\"vertices\": [";
  for (std::size_t v = 0; v < vertices; ++v) {
    const auto it = entries.find(v);
    s += (v ? ", " : "") + (it == entries.end() ? std::string("{}") : it->second);
  }
  return s + "]}";
}

// A crease entry at vertex v pointing across the edge towards w.
std::string crease(const Mesh& m, std::uint32_t v, std::uint32_t w, const std::string& more = "") {
  const glm::vec3 across = glm::normalize(glm::cross(m.normals[v], m.positions[w] - m.positions[v]));
  return "{\"sharpness\": 0.8, \"crease\": " + vec(across) + more + "}";
}

TEST(ScalarTaggedPnScene, UntaggedOrNeutralIsPnBitForBit) {
  const Mesh mesh = icosphere();
  test::TempDir dir;
  const auto neutral = dir.write("neutral.json", sidecar(mesh.vertex_count(), {{3, "{\"tension\": 0, \"bias\": 0}"}}));
  for (const char* mode : {"linear", "quadratic", "analytic"}) {
    const std::string m = std::string("tessellation.normal_mode=") + mode;
    const Frame pn = render({m});
    EXPECT_EQ(differing_records(pn, render({m, "tessellation.scheme=scalar_tagged_pn"})), 0u) << mode;
    const Frame tagged = render({m, "tessellation.scheme=scalar_tagged_pn", "tessellation.tags=" + neutral.string()});
    EXPECT_EQ(differing_records(pn, tagged), 0u) << mode;
    EXPECT_EQ(std::memcmp(pn.fb.color.data(), tagged.fb.color.data(), pn.fb.color.size() * sizeof(pn.fb.color[0])), 0);
  }
}

TEST(ScalarTaggedPnScene, TwinsOnTheExecutorMatchWithACrease) {
  const Mesh mesh = icosphere();
  const std::uint32_t a = mesh.indices[0], b = mesh.indices[1], c = mesh.indices[2];
  test::TempDir dir;
  const auto tags = dir.write("crease.json", sidecar(mesh.vertex_count(),
                                                     {{a, crease(mesh, a, b, ", \"bias\": 0.3")},
                                                      {b, crease(mesh, b, a)},
                                                      {c, "{\"tension\": 0.4}"}}));
  for (const char* mode : {"linear", "quadratic", "quadratic_corrected", "analytic"}) {
    const std::vector<std::string> sets = {std::string("tessellation.normal_mode=") + mode,
                                           "tessellation.scheme=scalar_tagged_pn", "tessellation.tags=" + tags.string()};
    const Frame cpp = render(sets);
    std::vector<std::string> twin_sets = sets;
    twin_sets.push_back("shaders.program=twins");
    const Frame twins = render(twin_sets);
    ASSERT_FALSE(cpp.dump.empty());
    EXPECT_EQ(differing_records(cpp, twins), 0u) << mode;
    // The tags did something: the patches around the three tagged vertices moved.
    EXPECT_GT(differing_records(cpp, render({std::string("tessellation.normal_mode=") + mode})), 100u) << mode;
  }
}

std::string error_of(const std::string& file_text, const Mesh& mesh, const test::TempDir& dir) {
  TessellationSettings s;
  s.scheme = SurfaceScheme::ScalarTaggedPN;
  s.tags = dir.write("tags.json", file_text);
  try {
    load_vertex_tags(s, mesh);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

void expect_mentions(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' in: " << message;
}

// The tags file goes through the same JSON limits as a scene file (scene/json_input.h): deep
// nesting is refused at its line and column, and 1e999 (an uncaught out_of_range before) too.
TEST(ScalarTaggedPnScene, SidecarJsonLimits) {
  const Mesh mesh = icosphere();
  test::TempDir dir;
  const std::string path = (dir.path() / "tags.json").string();
  EXPECT_EQ(error_of(std::string(100000, '[') + std::string(100000, ']'), mesh, dir),
            path + ": line 1, column 257: arrays and objects nested deeper than 256 levels (tessref's limit for JSON "
                   "input)");
  EXPECT_EQ(error_of("{\"vertices\": [\n  {\"tension\": 1e999}]}", mesh, dir),
            path + ": line 2, column 15: invalid JSON: number overflow parsing '1e999'");
  EXPECT_EQ(error_of("{\"vertices\": [}", mesh, dir),
            path + ": line 1, column 15: JSON syntax error: syntax error while parsing value - unexpected '}'; "
                   "expected '[', '{', or a literal");
}

TEST(ScalarTaggedPnScene, SidecarErrorsNameTheFileTheVertexAndTheRule) {
  const Mesh mesh = icosphere();
  const std::size_t n = mesh.vertex_count();
  test::TempDir dir;
  const std::uint32_t a = mesh.indices[0], b = mesh.indices[1], c = mesh.indices[2];

  expect_mentions(error_of(sidecar(n - 2, {}), mesh, dir),
                  {"tags.json", "vertices", "vertex " + std::to_string(n - 2) + " has no entry"});
  expect_mentions(error_of(sidecar(n, {{7, "{\"crease\": [1, 0, 0]}"}}), mesh, dir),
                  {"tags.json", "vertices.7.crease", "a crease vector on a smooth vertex"});
  expect_mentions(error_of(sidecar(n, {{5, "{\"sharpness\": 0.5}"}}), mesh, dir),
                  {"tags.json", "vertices.5.sharpness", "needs a crease vector"});
  expect_mentions(error_of(sidecar(n, {{4, "{\"tension\": 2}"}}), mesh, dir), {"tags.json", "vertices.4.tension"});
  expect_mentions(error_of(sidecar(n, {{9, "{\"sharpness\": 1, \"crease\": " + vec(mesh.normals[9]) + "}"}}), mesh, dir),
                  {"tags.json", "vertices.9.crease", "parallel to the vertex normal"});
  expect_mentions(error_of(sidecar(n, {{a, crease(mesh, a, b)}, {b, crease(mesh, b, a)}, {c, crease(mesh, c, a)}}), mesh, dir),
                  {"tags.json", "triangle", "at most 2 crease vertices per triangle"});

  // Three crease edges at one vertex, no triangle with three crease vertices: a vertex and three
  // of its neighbours no two of which share an edge.
  std::map<std::uint32_t, std::set<std::uint32_t>> adjacent;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t p = mesh.indices[3 * t + e], q = mesh.indices[3 * t + (e + 1) % 3];
      adjacent[p].insert(q);
      adjacent[q].insert(p);
    }
  bool found = false;
  for (const auto& [v, ring] : adjacent) {
    const std::vector<std::uint32_t> r(ring.begin(), ring.end());
    std::vector<std::uint32_t> pick;
    for (std::size_t x = 0; x < r.size() && pick.empty(); ++x)
      for (std::size_t y = x + 1; y < r.size() && pick.empty(); ++y)
        for (std::size_t z = y + 1; z < r.size() && pick.empty(); ++z)
          if (!adjacent[r[x]].count(r[y]) && !adjacent[r[x]].count(r[z]) && !adjacent[r[y]].count(r[z]))
            pick = {r[x], r[y], r[z]};
    if (pick.empty()) continue;
    std::map<std::size_t, std::string> e = {{v, crease(mesh, v, pick[0])}};
    for (std::uint32_t w : pick) e[w] = crease(mesh, w, v);
    expect_mentions(error_of(sidecar(n, e), mesh, dir),
                    {"tags.json", "vertex " + std::to_string(v) + ": 3 crease edges meet here",
                     "at most one crease may pass through a vertex"});
    found = true;
    break;
  }
  EXPECT_TRUE(found);

  // The scene keys: tags for another scheme, and the error surfacing from a render.
  try {
    load_scene("", {"tessellation.tags=x.json"});
    ADD_FAILURE() << "tags with scheme pn accepted";
  } catch (const InputError& e) {
    expect_mentions(e.what(), {"tessellation.tags", "scalar_tagged_pn"});
  }
  const auto bad = dir.write("bad.json", sidecar(n, {{7, "{\"crease\": [1, 0, 0]}"}}));
  EXPECT_THROW(render({"tessellation.scheme=scalar_tagged_pn", "tessellation.tags=" + bad.string()}), InputError);
}

}  // namespace
}  // namespace tessref
