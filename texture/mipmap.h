#pragma once
// glGenerateMipmap (GL 4.6 8.14.4): levels base_level + 1 .. q computed from the base level.
// GL leaves the filter to the implementation; tessref filters as llvmpipe does (docs/textures.md).
#include "texture/texture.h"

namespace tessref::texture {

// Replaces levels base_level + 1 .. min(p, max_level) of t (p as in 8.17) with levels computed
// from the base level, each stored in t's format (the levels a texture allocated with every level
// has). Then finalize()s t.
void generate_mipmaps(Texture& t);

}  // namespace tessref::texture
