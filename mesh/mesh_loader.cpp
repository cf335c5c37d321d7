#include "mesh/mesh_loader.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <exception>
#include <fstream>
#include <new>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "common/error.h"
#include "common/hash.h"

namespace tessref {
namespace {

// Raw vertices of all meshes, before welding.
struct Soup {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;
  std::size_t skipped_faces = 0;
  std::vector<bool> stored;  // per vertex: the file gave its normal
};

// Stored normals that point into the surface on most faces (a mesh with its faces wound
// clockwise, or normals negated: assimp's Spider_binary.stl): the faces' winding is what culling
// and PN triangles go by, so such a mesh renders lit from behind. The count of faces whose normal
// (from the winding) opposes the sum of its corners' normals.
std::size_t faces_against_normals(const Mesh& m) {
  std::size_t against = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const std::uint32_t* i = &m.indices[3 * t];
    const glm::vec3 face = glm::cross(m.positions[i[1]] - m.positions[i[0]], m.positions[i[2]] - m.positions[i[0]]);
    if (glm::dot(face, m.normals[i[0]] + m.normals[i[1]] + m.normals[i[2]]) < 0.0f) ++against;
  }
  return against;
}

// Vertices with bit-identical position and normal become one, so that a corner repeated by every
// face that uses it counts once when welding averages the normals at a position.
void join_exact_duplicates(Soup& soup) {
  struct Key {
    glm::vec3 p, n;
    bool operator==(const Key& o) const { return std::memcmp(this, &o, sizeof(Key)) == 0; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint32_t w[6];
      std::memcpy(w, &k, sizeof w);
      Fnv1a f;
      for (std::uint32_t x : w) f.mix(x);
      return std::size_t(f.h);
    }
  };
  static_assert(sizeof(Key) == 6 * sizeof(float));
  std::unordered_map<Key, std::uint32_t, Hash> first;
  std::vector<std::uint32_t> remap(soup.positions.size());
  Soup joined;
  for (std::size_t v = 0; v < soup.positions.size(); ++v) {
    const auto [it, inserted] = first.try_emplace(Key{soup.positions[v], soup.normals[v]},
                                                  static_cast<std::uint32_t>(joined.positions.size()));
    if (inserted) {
      joined.positions.push_back(soup.positions[v]);
      joined.normals.push_back(soup.normals[v]);
      joined.stored.push_back(soup.stored[v]);
    }
    remap[v] = it->second;
  }
  for (std::uint32_t& i : soup.indices) i = remap[i];
  soup.positions = std::move(joined.positions);
  soup.normals = std::move(joined.normals);
  soup.stored = std::move(joined.stored);
}

// Stored normals that welding must replace (from their twins at the position, else the faces).
std::size_t bad_stored_normals(const Soup& soup) {
  std::size_t bad = 0;
  for (std::size_t v = 0; v < soup.normals.size(); ++v) bad += soup.stored[v] && !usable_normal(soup.normals[v]);
  return bad;
}

glm::mat4 to_glm(const aiMatrix4x4& m) {
  // aiMatrix4x4 is row-major (a1..a4 is the first row); glm is column-major.
  return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                   m.b4, m.c4, m.d4);
}

void append_mesh(const aiMesh& mesh, const glm::mat4& transform, Soup& soup,
                 const std::string& name) {
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  const auto base = static_cast<std::uint32_t>(soup.positions.size());
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    soup.positions.push_back(glm::vec3(transform * glm::vec4(p.x, p.y, p.z, 1.0f)));
    if (mesh.HasNormals()) {
      const aiVector3D& n = mesh.mNormals[v];
      soup.stored.push_back(true);
      soup.normals.push_back(normal_matrix * glm::vec3(n.x, n.y, n.z));
    } else {
      soup.stored.push_back(false);
      soup.normals.push_back(glm::vec3(0.0f));  // welding fills it in from the faces
    }
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) {
      ++soup.skipped_faces;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      std::uint32_t i = face.mIndices[k];
      if (i >= mesh.mNumVertices)
        throw InputError(name + ": face " + std::to_string(f) + " of mesh '" + mesh.mName.C_Str() +
                         "' uses vertex " + std::to_string(i) + ", but that mesh has " +
                         std::to_string(mesh.mNumVertices) + " vertices");
      soup.indices.push_back(base + i);
    }
  }
}

void append_node(const aiScene& scene, const aiNode& node, const glm::mat4& parent, Soup& soup,
                 std::vector<bool>& used, const std::string& name) {
  const glm::mat4 transform = parent * to_glm(node.mTransformation);
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    unsigned m = node.mMeshes[k];
    if (m >= scene.mNumMeshes || !scene.mMeshes[m]) continue;
    append_mesh(*scene.mMeshes[m], transform, soup, name);
    used[m] = true;
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    if (node.mChildren[c]) append_node(scene, *node.mChildren[c], transform, soup, used, name);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// OFF and PLY headers declare element counts that assimp allocates (and zero-fills) before
// reading a single element: the invalid test model OutOfMemory.off declares 3.5e11 vertices in
// 309 bytes and makes assimp touch 16 GB. Every element takes at least one byte, so a count
// larger than the file is a lie; refuse it before assimp sees it.
void check_declared_counts(const std::filesystem::path& path, std::uintmax_t file_size) {
  const std::string ext = lower(path.extension().string());
  if (ext != ".off" && ext != ".ply") return;
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), head.size());
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::istringstream text(head);
  std::vector<std::pair<std::string, unsigned long long>> counts;
  std::string line;
  if (ext == ".ply") {
    while (std::getline(text, line) && line.rfind("end_header", 0) != 0) {
      std::istringstream words(line);
      std::string keyword, element;
      unsigned long long n = 0;
      // A count past 64 bits reads as ULLONG_MAX (with failbit): more than any file holds.
      if (words >> keyword >> element && keyword == "element" && (words >> n || n == ULLONG_MAX))
        counts.push_back({element, n});
    }
  } else {
    // [ST][C][N][4][n]OFF, then (with n) the dimension, then vertex, face and edge counts.
    std::vector<std::string> tokens;
    while (std::getline(text, line) && tokens.size() < 8) {
      std::istringstream words(line.substr(0, line.find('#')));
      for (std::string w; words >> w;) tokens.push_back(w);
    }
    std::size_t i = 0;
    if (!tokens.empty() && tokens[0].find("OFF") != std::string::npos) {
      // assimp reads a count glued to the keyword ("OFF99949999490": fuzz_mesh, which assimp took
      // for 1165751682 vertices, its 32-bit wrap, and allocated 14 GB for): split it off.
      const std::size_t end = tokens[0].find("OFF") + 3;
      if (end < tokens[0].size()) {
        tokens.insert(tokens.begin() + 1, tokens[0].substr(end));
        tokens[0].resize(end);
      }
      i = tokens[0].size() >= 4 && tokens[0][tokens[0].size() - 4] == 'n' ? 2 : 1;
    }
    const char* names[2] = {"vertex", "face"};
    for (int k = 0; k < 2 && i + k < tokens.size(); ++k) {
      try {
        counts.push_back({names[k], std::stoull(tokens[i + k])});
      } catch (const std::out_of_range&) {
        // Past 64 bits (fuzz_mesh: 76 digits, which assimp read as 2^32 - 1 and allocated for).
        counts.push_back({names[k], ULLONG_MAX});
      } catch (const std::exception&) {
        break;  // not a number: assimp reports the bad header
      }
    }
  }
  for (const auto& [element, n] : counts)
    if (n > file_size)
      throw InputError(path.string() + ": the header declares " + std::to_string(n) + " " + element +
                       " elements, more than a file of " + std::to_string(file_size) +
                       " bytes can hold");
}

// assimp 5.2.5's PLY reader never returns from a header without an end_header line (a file cut
// short in its header, found by fuzz_mesh), so such a file is refused before assimp sees it.
bool ply_header_ends(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  for (std::string line; std::getline(in, line);) {
    // The line as assimp matches it: blanks, "end_header", then the line's end or a blank. Not a
    // vertical tab, which std::isspace counts: after one assimp reads on and never returns either.
    const std::size_t k = line.find_first_not_of(" \t");
    if (k != std::string::npos && line.compare(k, 10, "end_header") == 0 &&
        (line.size() == k + 10 || std::strchr(" \t\r\f", line[k + 10]) != nullptr))  // '\0' too
      return true;
  }
  return false;
}

// assimp's validation messages in the file's terms: they name its internal structures.
std::string explained_import_error(const std::string& message) {
  // "Validation failed: aiMesh::mFaces[F]::mIndices[K] is out of range"
  const std::string faces = "aiMesh::mFaces[";
  if (const std::size_t at = message.find(faces); at != std::string::npos && message.ends_with("is out of range")) {
    const unsigned long face = std::strtoul(message.c_str() + at + faces.size(), nullptr, 10);
    return "face " + std::to_string(face + 1) + " (counting from 1) names a vertex past the file's vertex list";
  }
  if (message.find("contains no faces") != std::string::npos)
    return "no face could be read (the importer drops a face whose vertex count disagrees with its indices); "
           "the importer said: " + message;
  return "the importer (assimp) said: " + message;
}

}  // namespace

Mesh load_mesh_file(const std::filesystem::path& path, std::vector<std::string>& warnings, bool split_normals) {
  const std::string name = path.string();
  auto fail = [&](const std::string& what) { throw InputError(name + ": " + what); };
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail("no such file");
  if (std::filesystem::is_directory(path, ec)) fail("is a directory, not a mesh file");
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  if (ec) fail("cannot read: " + ec.message());
  if (file_size == 0) fail("the file is empty");
  check_declared_counts(path, file_size);
  if (lower(path.extension().string()) == ".ply" && !ply_header_ends(path))
    fail("the PLY header has no end_header line (is the file cut short?)");

  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // No aiProcess_JoinIdenticalVertices: it merges a vertex with a NaN coordinate into another one
  // (its comparisons are false), moving the triangle silently; join_exact_duplicates does its
  // job after the coordinates have been checked.
  const aiScene* scene = nullptr;
  auto run = [&](const auto& step) {
    try {
      scene = step();
    } catch (const std::bad_alloc&) {
      throw;  // the memory budget: the command says so
    } catch (const std::exception& e) {
      fail("cannot be read: " + explained_import_error(e.what()));
    }
    if (!scene) fail("cannot be read: " + explained_import_error(importer.GetErrorString()));
  };
  run([&] { return importer.ReadFile(name, aiProcess_ValidateDataStructure); });
  // assimp 5.2.5's triangulation aborts the process (an ai_assert that Debian's build keeps) on a
  // face without vertices, which its PLY reader makes of a face "0" and its validation lets
  // through (fuzz_mesh): such a file is refused before triangulation.
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned f = 0; scene->mMeshes[m] && f < scene->mMeshes[m]->mNumFaces; ++f)
      if (scene->mMeshes[m]->mFaces[f].mNumIndices == 0)
        fail("face " + std::to_string(f) + " of mesh '" + scene->mMeshes[m]->mName.C_Str() + "' has no vertices");
  run([&] { return importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType); });
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || scene->mNumMeshes == 0)
    fail("contains no triangle mesh");

  Soup soup;
  std::vector<bool> used(scene->mNumMeshes, false);
  if (scene->mRootNode) append_node(*scene, *scene->mRootNode, glm::mat4(1.0f), soup, used, name);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)  // meshes no node refers to: as they are
    if (!used[m] && scene->mMeshes[m]) append_mesh(*scene->mMeshes[m], glm::mat4(1.0f), soup, name);
  if (soup.skipped_faces)
    warnings.push_back(name + ": skipped " + std::to_string(soup.skipped_faces) +
                       " point and line primitives");

  if (soup.indices.empty()) fail("the mesh is empty (no triangles)");
  for (std::size_t v = 0; v < soup.positions.size(); ++v) {
    const glm::vec3& p = soup.positions[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      // Counted from 1, as OBJ and PLY files number their vertices (the count is the importer's,
      // which unrolls some formats; its coordinates are not shown: a "nan" in one makes the
      // importer read the whole line as NaN).
      fail("vertex " + std::to_string(v + 1) + " (counting from 1, as read) has a NaN or infinite coordinate");
  }
  join_exact_duplicates(soup);
  const std::size_t bad_normals = bad_stored_normals(soup);
  Mesh mesh;
  if (split_normals) {
    // Vertices stay as stored (joined only where position and normal both match); a normal that
    // cannot be used is zeroed here and recomputed from the faces by validate_mesh.
    mesh.positions = soup.positions;
    mesh.indices = soup.indices;
    for (std::size_t v = 0; v < soup.normals.size(); ++v)
      mesh.normals.push_back(soup.stored[v] && usable_normal(soup.normals[v]) ? glm::normalize(soup.normals[v])
                                                                                : glm::vec3(0.0f));
  } else {
    mesh = weld_by_position(soup.positions, soup.normals, soup.indices);
  }
  MeshRepairs repairs = validate_mesh(mesh, name);
  if (repairs.degenerate_triangles_dropped)
    warnings.push_back(name + ": dropped " + std::to_string(repairs.degenerate_triangles_dropped) +
                       " degenerate triangles");
  if (repairs.normals_recomputed)
    warnings.push_back(name + ": recomputed " + std::to_string(repairs.normals_recomputed) +
                       " zero-length normals from the faces");
  if (bad_normals)
    warnings.push_back(name + ": " + std::to_string(bad_normals) +
                       " stored normals are zero, NaN or infinite; replaced by the normals of "
                       "their welded twins or of the faces around them");
  if (std::find(soup.stored.begin(), soup.stored.end(), true) != soup.stored.end()) {
    const std::size_t against = faces_against_normals(mesh);
    if (2 * against > mesh.triangle_count())
      warnings.push_back(name + ": the stored normals point against the faces' winding on " +
                         std::to_string(against) + " of " + std::to_string(mesh.triangle_count()) +
                         " triangles (negated normals or clockwise faces?): culling goes by the "
                         "winding and lighting by the normals, so it will look lit from behind");
  }
  return mesh;
}

}  // namespace tessref
