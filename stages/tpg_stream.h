#pragma once
// The generator's output as a transform-feedback capture sees it: one gl_TessCoord per emitted
// vertex, primitive after primitive. Used by `tessref tpg`, the tests and the reference datasets.
#include <iosfwd>
#include <vector>

#include "stages/tpg.h"

namespace tessref {

enum class StreamFormat { Text, Hex };

std::vector<glm::vec3> emitted_stream(const TessDomainPoints& points);

// One line per emitted vertex: u v w for triangles, u v for quads and isolines. Text prints %.9g
// (round-trips a float); Hex prints each component's IEEE-754 bits as 8 lowercase hex digits.
void write_stream(std::ostream& os, TessDomain domain, const std::vector<glm::vec3>& stream,
                  StreamFormat format);

}  // namespace tessref
