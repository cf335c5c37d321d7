#include "mesh/vertex_tags.h"

#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "scene/json_input.h"
#include "scene/json_reader.h"

namespace tessref {
namespace {

constexpr const char* kAppendix = " (seed 001, Appendix B)";

nlohmann::json read_json(const std::string& file) { return read_json_file(file, "tessellation.tags file"); }

// One entry of "vertices": every key optional (a smooth, untagged vertex is {}).
VertexTags read_entry(JsonObject o, float default_tension, const glm::vec3& normal) {
  VertexTags t;
  t.tension = o.has("tension") ? o.number_in("tension", -1.0f, 1.0f, false, false) : default_tension;
  if (o.has("sharpness")) t.sharpness = o.number_in("sharpness", 0.0f, 1.0f, false, false);
  if (o.has("bias")) t.bias = o.number_in("bias", -1.0f, 1.0f, false, false);
  if (o.has("crease")) t.crease = o.vec3("crease");
  const bool creased = t.creased();
  if (creased && !(t.sharpness > 0.0f))
    o.fail("crease", "a crease vector on a smooth vertex (sharpness 0): give it a sharpness in (0, 1] or "
                     "remove the crease; the crease vector acts through the sharpness" + std::string(kAppendix));
  if (!creased && t.sharpness > 0.0f)
    o.fail("sharpness", "sharpness needs a crease vector at the same vertex (\"crease\": [x, y, z])" +
                            std::string(kAppendix));
  if (!creased && t.bias != 0.0f)
    o.fail("bias", "bias needs a crease vector at the same vertex (\"crease\": [x, y, z])" + std::string(kAppendix));
  if (creased) {
    // In double: the test must not underflow for small but valid vectors.
    const glm::dvec3 c(t.crease), n(normal);
    const glm::dvec3 side = glm::cross(c, n);
    if (!(glm::dot(side, side) > 1e-12 * glm::dot(c, c) * glm::dot(n, n)))
      o.fail("crease", "must not be parallel to the vertex normal: it points across the crease, in the "
                       "tangent plane");
  }
  o.finish();
  return t;
}

void check_restrictions(const std::string& file, const Mesh& mesh, const std::vector<VertexTags>& tags) {
  // At most two crease vertices per triangle.
  std::map<std::uint32_t, std::set<std::uint32_t>> crease_edges;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const std::uint32_t* v = &mesh.indices[3 * t];
    int creased = 0;
    for (int c = 0; c < 3; ++c) creased += tags[v[c]].creased();
    if (creased > 2)
      throw InputError(file + ": triangle " + std::to_string(t) + " (vertices " + std::to_string(v[0]) + ", " +
                       std::to_string(v[1]) + ", " + std::to_string(v[2]) +
                       "): all three carry a crease vector; at most 2 crease vertices per triangle" + kAppendix);
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = v[c], b = v[(c + 1) % 3];
      if (tags[a].creased() && tags[b].creased()) {
        crease_edges[a].insert(b);
        crease_edges[b].insert(a);
      }
    }
  }
  // At most one crease through a vertex: a crease passes on through it along at most two edges.
  for (const auto& [vertex, others] : crease_edges)
    if (others.size() > 2) {
      std::string list;
      for (std::uint32_t o : others) list += (list.empty() ? "" : ", ") + std::to_string(o);
      throw InputError(file + ": vertex " + std::to_string(vertex) + ": " + std::to_string(others.size()) +
                       " crease edges meet here (to vertices " + list +
                       "); at most one crease may pass through a vertex" + kAppendix);
    }
}

}  // namespace

std::vector<VertexTags> load_vertex_tags(const TessellationSettings& settings, const Mesh& mesh) {
  std::vector<VertexTags> tags(mesh.vertex_count());
  for (VertexTags& t : tags) t.tension = settings.tension;
  if (settings.tags.empty()) return tags;
  const std::string file = settings.tags.string();
  const nlohmann::json root_json = read_json(file);
  const JsonSource source{file, {}};
  JsonObject root(root_json, "", source);
  if (root.has("description")) root.string("description");
  root.describe("vertices", "an array with one object per mesh vertex");
  const nlohmann::json& vertices = root.value("vertices");
  if (!vertices.is_array()) root.fail("vertices", "expected an array with one object per mesh vertex, got " + describe_json(vertices));
  if (vertices.size() < tags.size())
    root.fail("vertices", "vertex " + std::to_string(vertices.size()) + " has no entry: the file lists " +
                              std::to_string(vertices.size()) + " vertices, the mesh has " + std::to_string(tags.size()) +
                              " (every vertex needs one, {} for a smooth untagged vertex)");
  if (vertices.size() > tags.size())
    root.fail("vertices", "the file lists " + std::to_string(vertices.size()) + " vertices, the mesh has only " +
                              std::to_string(tags.size()) + " (vertex " + std::to_string(tags.size()) +
                              " and later name no mesh vertex)");
  for (std::size_t v = 0; v < tags.size(); ++v)
    tags[v] = read_entry(JsonObject(vertices[v], "vertices." + std::to_string(v), source), settings.tension,
                         mesh.normals[v]);
  root.finish();
  check_restrictions(file, mesh, tags);
  return tags;
}

void attach_vertex_tags(StageVertex* out, std::size_t first, std::size_t count,
                        const std::vector<VertexTags>& tags, const glm::mat3& normal_matrix) {
  for (std::size_t i = 0; i < count && first + i < tags.size(); ++i) {
    const VertexTags& t = tags[first + i];
    out[i].attr[kAttrTags] = glm::vec4(t.tension, t.sharpness, t.bias, 0.0f);
    out[i].attr[kAttrCrease] = glm::vec4(world_crease(normal_matrix, t.crease), 0.0f);
  }
}

}  // namespace tessref
