#pragma once
// Scalar Tagged PN's per-vertex tags (stages/schemes/scalar_tagged_pn.h) from the scene: the
// sidecar file tessellation.tags and the default tessellation.tension, checked against the mesh
// and seed 001 Appendix B's restrictions. Every error is an InputError naming the file, the vertex
// (or triangle) and the rule. docs/scalar-tagged-pn.md describes the file.
#include <vector>

#include "mesh/mesh.h"
#include "scene/tessellation_settings.h"
#include "stages/schemes/scalar_tagged_pn.h"
#include "stages/tess_stage.h"

namespace tessref {

// One entry per mesh vertex, in the mesh's vertex order.
std::vector<VertexTags> load_vertex_tags(const TessellationSettings& settings, const Mesh& mesh);

// The TCS inputs of vertices [first, first + count): out[i].attr[kAttrTags] = (tension, sharpness,
// bias, 0) and attr[kAttrCrease] = (world_crease(normal_matrix, crease), 0) of tags[first + i], as
// tagged_transform.vert writes them. Vertices past the tags are left as they are.
void attach_vertex_tags(StageVertex* out, std::size_t first, std::size_t count,
                        const std::vector<VertexTags>& tags, const glm::mat3& normal_matrix);

}  // namespace tessref
