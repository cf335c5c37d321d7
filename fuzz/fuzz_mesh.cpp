// Fuzzes mesh files: assimp's OBJ, PLY, STL and OFF readers behind load_mesh_file
// (mesh_loader.h), with its header checks, welding (weld_by_position) and validation.
//
// Input: the first byte picks the extension (.obj, .ply, .stl, .off), the rest is the file, written
// to a temporary file (assimp reads files). Expected: a mesh, or InputError for a bad file. A
// finding: any other exception, a crash, UB, or a returned mesh that breaks what validate_mesh
// promises (triangles, indices in range, finite positions, unit normals).
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "mesh/mesh_loader.h"

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_mesh: a loaded mesh breaks a rule: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".obj", ".ply", ".stl", ".off"};
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("fuzz_mesh_" + std::to_string(::getpid()) + kExtensions[data[0] % 4]);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  std::vector<std::string> warnings;
  tessref::Mesh mesh;
  try {
    mesh = tessref::load_mesh_file(path, warnings);
  } catch (const tessref::InputError&) {
    std::filesystem::remove(path);
    return 0;
  }
  std::filesystem::remove(path);
  check(mesh.triangle_count() > 0 && mesh.indices.size() % 3 == 0, "at least one triangle");
  check(mesh.normals.size() == mesh.positions.size(), "one normal per position");
  for (std::uint32_t i : mesh.indices) check(i < mesh.positions.size(), "indices in range");
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    check(a != b && b != c && a != c, "no triangle repeats a vertex");
  }
  for (const glm::vec3& p : mesh.positions)
    check(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "finite positions");
  for (const glm::vec3& n : mesh.normals) check(std::fabs(glm::length(n) - 1.0f) < 1e-3f, "unit normals");
  return 0;
}
