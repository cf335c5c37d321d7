// Procedural meshes, welding, validation and loading through assimp.
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <future>
#include <set>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "mesh/mesh.h"
#include "mesh/mesh_loader.h"
#include "mesh/procedural.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using test::TempDir;

// Every normal unit length, every index in range, every face turned outward (its normal agrees
// with its corners' normals) and every edge shared by exactly two triangles (closed, welded).
void expect_closed_smooth_mesh(const Mesh& m) {
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const std::uint32_t* i = &m.indices[3 * t];
    for (int k = 0; k < 3; ++k) ASSERT_LT(i[k], m.positions.size());
    glm::vec3 face = glm::cross(m.positions[i[1]] - m.positions[i[0]], m.positions[i[2]] - m.positions[i[0]]);
    EXPECT_GT(glm::dot(face, m.normals[i[0]] + m.normals[i[1]] + m.normals[i[2]]), 0.0f) << "triangle " << t;
    for (int k = 0; k < 3; ++k) directed[{i[k], i[(k + 1) % 3]}]++;
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge used twice in the same direction";
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << "open edge";
  }
}

TEST(Procedural, IcosphereCounts) {
  for (int n = 0; n <= 4; ++n) {
    SCOPED_TRACE(n);
    const Mesh m = make_icosphere(n, 2.0f);
    const std::size_t p = std::size_t(1) << (2 * n);  // 4^n
    EXPECT_EQ(m.vertex_count(), 10 * p + 2);
    EXPECT_EQ(m.triangle_count(), 20 * p);
    expect_closed_smooth_mesh(m);
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      EXPECT_NEAR(glm::length(m.positions[v]), 2.0f, 1e-5f);
      EXPECT_NEAR(glm::dot(m.normals[v], m.positions[v] / 2.0f), 1.0f, 1e-6f);
    }
  }
}

TEST(Procedural, TorusCounts) {
  const Mesh m = make_torus(1.0f, 0.25f, 16, 8);
  EXPECT_EQ(m.vertex_count(), 16u * 8u);
  EXPECT_EQ(m.triangle_count(), 2u * 16u * 8u);
  expect_closed_smooth_mesh(m);
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    // Distance to the tube's center circle is the minor radius, along the normal.
    glm::vec3 p = m.positions[v];
    glm::vec3 center = glm::normalize(glm::vec3(p.x, 0.0f, p.z));
    EXPECT_NEAR(glm::length(p - center), 0.25f, 1e-6f);
    EXPECT_NEAR(glm::dot(glm::normalize(p - center), m.normals[v]), 1.0f, 1e-6f);
  }
  EXPECT_EQ(make_torus(2.0f, 1.0f, 3, 3).triangle_count(), 18u);
}

TEST(Procedural, CubeIsWelded) {
  const Mesh m = make_cube(2.0f);
  EXPECT_EQ(m.vertex_count(), 8u);
  EXPECT_EQ(m.triangle_count(), 12u);
  expect_closed_smooth_mesh(m);
  for (std::size_t v = 0; v < 8; ++v) {
    EXPECT_EQ(glm::abs(m.positions[v]), glm::vec3(1.0f));
    EXPECT_NEAR(glm::dot(m.normals[v], m.positions[v] / std::sqrt(3.0f)), 1.0f, 1e-6f);
  }
}

TEST(Mesh, WeldingAveragesSplitNormals) {
  // Two triangles of a folded quad with split (face) normals: the shared edge welds and its
  // normals average.
  std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<glm::vec3> n = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  Mesh m = weld_by_position(p, n, {0, 1, 2, 3, 5, 4});
  EXPECT_EQ(m.vertex_count(), 4u);
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
  const glm::vec3 avg = glm::normalize(glm::vec3(1, 0, 1));
  EXPECT_NEAR(glm::distance(m.normals[1], avg), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(m.normals[2], avg), 0.0f, 1e-6f);
  EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals[3], glm::vec3(1, 0, 0));
}

TEST(Mesh, WeldingTreatsSignedZerosAlike) {
  Mesh m = weld_by_position({{0.0f, 0, 0}, {-0.0f, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {0, 2, 3, 1, 2, 3});
  EXPECT_EQ(m.vertex_count(), 3u);
}

TEST(Mesh, ValidateDropsDegenerateTriangles) {
  Mesh m = make_cube();
  m.indices.insert(m.indices.end(), {0, 0, 1, 2, 3, 2});  // repeated indices
  m.positions.push_back({5, 5, 5});
  m.normals.push_back({0, 0, 1});
  const std::uint32_t extra = 8;
  m.positions.push_back({6, 6, 6});
  m.normals.push_back({0, 0, 1});
  m.positions.push_back({7, 7, 7});
  m.normals.push_back({0, 0, 1});
  m.indices.insert(m.indices.end(), {extra, extra + 1, extra + 2});  // collinear: zero area
  MeshRepairs r = validate_mesh(m, "m");
  EXPECT_EQ(r.degenerate_triangles_dropped, 3u);
  EXPECT_EQ(m.triangle_count(), 12u);
}

TEST(Mesh, ValidateRecomputesZeroNormals) {
  Mesh m = make_cube();
  m.normals[3] = glm::vec3(0.0f);
  m.normals[5] = glm::vec3(NAN, 0.0f, 0.0f);
  MeshRepairs r = validate_mesh(m, "m");
  EXPECT_EQ(r.normals_recomputed, 2u);
  EXPECT_NEAR(glm::dot(m.normals[3], glm::normalize(m.positions[3])), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(m.normals[5], glm::normalize(m.positions[5])), 1.0f, 1e-6f);
}

std::string mesh_error(Mesh m) {
  try {
    validate_mesh(m, "file.obj");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Mesh, ValidateErrors) {
  EXPECT_EQ(mesh_error(Mesh{}), "file.obj: the mesh is empty (no triangles)");
  Mesh m = make_cube();
  m.positions[2].y = NAN;
  EXPECT_EQ(mesh_error(m), "file.obj: vertex 2 has a NaN or infinite coordinate");
  m = make_cube();
  m.positions[4].x = INFINITY;
  EXPECT_EQ(mesh_error(m), "file.obj: vertex 4 has a NaN or infinite coordinate");
  m = make_cube();
  m.indices[7] = 8;
  EXPECT_EQ(mesh_error(m), "file.obj: triangle 2 uses vertex 8, but the mesh has 8 vertices");
  m = make_cube();
  m.indices.pop_back();
  EXPECT_EQ(mesh_error(m), "file.obj: index count 35 is not a multiple of 3");
  m = Mesh{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {}, {0, 1, 2}};
  EXPECT_EQ(mesh_error(m), "file.obj: all 1 triangles are degenerate (zero area)");
  // Two faces back to back: their normals cancel at every vertex.
  m = Mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}}, {0, 1, 2, 0, 2, 1}};
  EXPECT_THAT(mesh_error(m), HasSubstr("file.obj: vertex 0 has no usable normal"));
}

// A unit cube as OBJ with one normal per face (24 position/normal pairs).
const char* kSplitCubeObj = R"(v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
vn 0 0 -1
vn 0 0 1
vn 0 -1 0
vn 0 1 0
vn -1 0 0
vn 1 0 0
f 1//1 4//1 3//1 2//1
f 5//2 6//2 7//2 8//2
f 1//3 2//3 6//3 5//3
f 4//4 8//4 7//4 3//4
f 1//5 5//5 8//5 4//5
f 2//6 3//6 7//6 6//6
)";

TEST(MeshLoader, SplitNormalCubeWeldsToEightPositions) {
  TempDir dir;
  std::vector<std::string> warnings;
  const Mesh m = load_mesh_file(dir.write("cube.obj", kSplitCubeObj), warnings);
  EXPECT_EQ(m.vertex_count(), 8u);
  EXPECT_EQ(m.triangle_count(), 12u);
  EXPECT_TRUE(warnings.empty());
  expect_closed_smooth_mesh(m);
  for (std::size_t v = 0; v < 8; ++v)
    EXPECT_NEAR(glm::dot(m.normals[v], m.positions[v] / std::sqrt(3.0f)), 1.0f, 1e-6f);
}

TEST(MeshLoader, WithoutNormalsTheFacesGiveThem) {
  TempDir dir;
  const char* obj = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";
  std::vector<std::string> warnings;
  const Mesh m = load_mesh_file(dir.write("cube.obj", obj), warnings);
  EXPECT_EQ(m.vertex_count(), 8u);
  EXPECT_EQ(m.triangle_count(), 12u);
  expect_closed_smooth_mesh(m);
  for (std::size_t v = 0; v < 8; ++v)
    EXPECT_NEAR(glm::dot(m.normals[v], m.positions[v] / std::sqrt(3.0f)), 1.0f, 1e-6f);
}

TEST(MeshLoader, DegenerateTrianglesAreDroppedWithAWarning) {
  TempDir dir;
  std::string obj = std::string(kSplitCubeObj) + "f 1 2 1\n";
  std::vector<std::string> warnings;
  const Mesh m = load_mesh_file(dir.write("cube.obj", obj), warnings);
  EXPECT_EQ(m.triangle_count(), 12u);
  EXPECT_THAT(warnings, ::testing::Contains(HasSubstr("degenerate")));
}

// Issue 11, defect 9: repairs and suspicious normals are reported, not done silently.
TEST(MeshLoader, BadStoredNormalsAreReplacedWithAWarning) {
  TempDir dir;
  const char* obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                    "vn 0 0 0\nvn nan 0 0\nvn inf 1 0\nvn 1 1 1\n"
                    "f 1//1 3//2 2//3\nf 1//1 2//3 4//4\nf 1//1 4//4 3//2\nf 2//3 3//2 4//4\n";
  std::vector<std::string> warnings;
  const Mesh m = load_mesh_file(dir.write("tet.obj", obj), warnings);
  ASSERT_EQ(m.vertex_count(), 4u);
  expect_closed_smooth_mesh(m);
  EXPECT_THAT(warnings, ::testing::Contains(HasSubstr(
                            "tet.obj: 3 stored normals are zero, NaN or infinite; replaced")));
}

TEST(MeshLoader, NormalsAgainstTheWindingAreReported) {
  TempDir dir;
  std::string inside_out = kSplitCubeObj;  // every stored normal negated
  const std::string normals = "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n";
  ASSERT_NE(inside_out.find(normals), std::string::npos);
  inside_out.replace(inside_out.find(normals), normals.size(),
                     "vn 0 0 1\nvn 0 0 -1\nvn 0 1 0\nvn 0 -1 0\nvn 1 0 0\nvn -1 0 0\n");
  std::vector<std::string> warnings;
  load_mesh_file(dir.write("cube.obj", inside_out), warnings);
  EXPECT_THAT(warnings, ::testing::Contains(HasSubstr(
                            "the stored normals point against the faces' winding on 12 of 12 triangles")));
  warnings.clear();
  load_mesh_file(dir.write("cube.obj", kSplitCubeObj), warnings);
  EXPECT_TRUE(warnings.empty());
}

TEST(MeshLoader, AssimpSpiderStlNormalsAgainstTheWinding) {
  for (const char* name : {"Spider_binary.stl", "Spider_ascii.stl"}) {
    const std::filesystem::path path = std::filesystem::path("/usr/share/assimp/models/STL") / name;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " missing (package assimp-testmodels)";
    std::vector<std::string> warnings;
    const Mesh m = load_mesh_file(path, warnings);
    EXPECT_THAT(warnings, ::testing::Contains(HasSubstr("the stored normals point against the faces' winding on 1308 of " +
                                                        std::to_string(m.triangle_count()))))
        << name;
  }
}

TEST(Mesh, CoordinatesTooLargeForSinglePrecision) {
  Mesh m = make_cube();
  for (glm::vec3& p : m.positions) p *= 1e37f;
  EXPECT_EQ(mesh_error(m), "file.obj: triangle 0: the cross product of its edges overflows single "
                           "precision (coordinates up to 5e+36); scale the mesh down (below 1e18)");
}

// Issue 24, defect 5: assimp's validation messages are put in the file's terms.
TEST(MeshLoader, ImporterMessagesNameTheFace) {
  TempDir dir;
  std::vector<std::string> warnings;
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  try {
    load_mesh_file(dir.write("past.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"), warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("past.ply: cannot be read: face 1 (counting from 1) names a vertex past the "
                                    "file's vertex list"));
  }
  try {
    load_mesh_file(dir.write("none.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n"), warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("none.off: cannot be read: no face could be read (the importer drops a face whose "
                                    "vertex count disagrees with its indices)"));
  }
}

// A NaN coordinate is named even when it is the only thing wrong (assimp's vertex joining would
// have merged it into another vertex), and a needle triangle's tip still gets a normal.
TEST(MeshLoader, NaNVertexIsNamedAndNeedleTipsGetNormals) {
  TempDir dir;
  std::vector<std::string> warnings;
  try {
    load_mesh_file(dir.write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"), warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("nan.obj: vertex 3 (counting from 1, as read) has a NaN or infinite coordinate"));
  }
  const Mesh m = load_mesh_file(
      dir.write("needle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1e6 1 0\nf 1 2 3\nf 2 4 3\n"), warnings);
  ASSERT_EQ(m.vertex_count(), 4u);
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0.0f, 0.0f, 1.0f));
}

TEST(MeshLoader, NaNCoordinatesAreAnError) {
  TempDir dir;
  std::vector<std::string> warnings;
  auto path = dir.write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  try {
    load_mesh_file(path, warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path.string() + ": "));
  }
}

TEST(MeshLoader, MissingFileAndDirectory) {
  std::vector<std::string> warnings;
  EXPECT_THROW(
      {
        try {
          load_mesh_file("/nonexistent/m.obj", warnings);
        } catch (const InputError& e) {
          EXPECT_STREQ(e.what(), "/nonexistent/m.obj: no such file");
          throw;
        }
      },
      InputError);
  EXPECT_THROW(load_mesh_file("/tmp", warnings), InputError);
}

// assimp-testmodels' invalid files: each is an InputError naming the file, never a crash.
TEST(MeshLoader, DeclaredCountsLargerThanTheFile) {
  TempDir dir;
  std::vector<std::string> warnings;
  auto off = dir.write("big.off", "OFF\n# comment\n1000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  try {
    load_mesh_file(off, warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), off.string() + ": the header declares 1000 vertex elements, "
                                                    "more than a file of 49 bytes can hold");
  }
  auto ply = dir.write("big.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 99999\n"
                                  "property list uchar int vertex_indices\nend_header\n"
                                  "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_THROW(load_mesh_file(ply, warnings), InputError);
  // Counts past 64 bits (fuzz_mesh): assimp read the OFF one as 2^32 - 1 faces and allocated 64 GB.
  auto error_of = [&](const std::filesystem::path& p) -> std::string {
    try {
      load_mesh_file(p, warnings);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string huge(76, '9');
  auto huge_off = dir.write("huge.off", "OFF\n3 " + huge + " 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_THAT(error_of(huge_off), HasSubstr("the header declares 18446744073709551615 face elements"));
  auto huge_ply = dir.write("huge.ply", "ply\nformat ascii 1.0\nelement vertex " + huge +
                                            "\nproperty float x\nend_header\n0\n");
  EXPECT_THAT(error_of(huge_ply), HasSubstr("the header declares 18446744073709551615 vertex elements"));
  // A count glued to the keyword (fuzz_mesh, 17 bytes): assimp read 99949999490 vertices as their
  // 32-bit wrap, 1165751682, and asked for 14 GB.
  auto glued = dir.write("glued.off", "OFF99949999490 9");
  EXPECT_THAT(error_of(glued), HasSubstr("the header declares 99949999490 vertex elements, more than a file of 16 bytes"));
  // The honest versions load.
  auto good = dir.write("good.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(load_mesh_file(good, warnings).triangle_count(), 1u);
}

// fuzz_mesh: assimp 5.2.5 never returns from a PLY header without an end_header line (a file cut
// short), so the loader refuses one first. The load runs on a thread with a deadline: the hang it
// was fails the test instead of stalling the suite.
TEST(MeshLoader, PlyHeaderWithoutEndIsAnError) {
  TempDir dir;
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n";
  auto error_of = [](const std::filesystem::path& path) {
    auto result = std::async(std::launch::async, [path] {
      std::vector<std::string> warnings;
      try {
        load_mesh_file(path, warnings);
      } catch (const InputError& e) {
        return std::string(e.what());
      }
      return std::string("no error");
    });
    if (result.wait_for(std::chrono::seconds(30)) != std::future_status::ready) {
      ADD_FAILURE() << path << ": load_mesh_file hangs";
      std::_Exit(1);  // the thread cannot be stopped
    }
    return result.get();
  };
  const auto cut = dir.write("cut.ply", header);
  EXPECT_EQ(error_of(cut), cut.string() + ": the PLY header has no end_header line (is the file cut short?)");
  // A vertical tab after end_header does not end the header for assimp (a hang too).
  const auto vtab = dir.write("vtab.ply", header + "end_header\v0\n1\n2\n");
  EXPECT_EQ(error_of(vtab), vtab.string() + ": the PLY header has no end_header line (is the file cut short?)");
  // Ended (even indented), the same header goes on to assimp (which finds no triangles in it).
  const auto ended = dir.write("ended.ply", header + "  end_header\n0\n1\n2\n");
  EXPECT_THAT(error_of(ended), Not(HasSubstr("end_header")));
}

// fuzz_mesh: assimp 5.2.5's triangulation aborts the process on a face without vertices (a PLY
// face "0"), which its validation lets through; the loader refuses one before triangulating.
TEST(MeshLoader, FaceWithoutVerticesIsAnError) {
  TempDir dir;
  std::vector<std::string> warnings;
  const auto ply = dir.write("empty_face.ply",
                             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                             "end_header\n0 0 0\n1 0 0\n0 1 0\n0\n");
  try {
    load_mesh_file(ply, warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(ply.string() + ": face 0 of mesh '"));
    EXPECT_THAT(e.what(), HasSubstr("' has no vertices"));
  }
}

TEST(MeshLoader, AssimpInvalidModels) {
  const std::filesystem::path dir = "/usr/share/assimp/models/invalid";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " missing (package assimp-testmodels)";
  int errors = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name == "readme.txt") continue;
    SCOPED_TRACE(name);
    std::vector<std::string> warnings;
    try {
      Mesh m = load_mesh_file(entry.path(), warnings);
      // A file assimp can repair (malformed2.obj: a missing material) must come out valid.
      EXPECT_GT(m.triangle_count(), 0u);
      EXPECT_EQ(m.normals.size(), m.vertex_count());
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(entry.path().string() + ": "));
      ++errors;
    }
  }
  EXPECT_GE(errors, 13);  // all but malformed2.obj: empty files, OutOfMemory.off, malformed.obj, ...
}

}  // namespace
}  // namespace tessref
