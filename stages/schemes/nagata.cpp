#include "stages/schemes/nagata.h"

namespace tessref {

glm::vec3 NagataTcs::edge_point(const glm::vec3& p0, const glm::vec3& n0, const glm::vec3& p1,
                                const glm::vec3& n1) const {
  return schemes::nagata_edge_point(p0, n0, p1, n1, eps);
}

}  // namespace tessref
