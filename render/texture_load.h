#pragma once
// A scene's textures as tessref samples them and the GL runner uploads them: image files or raw
// bytes per level in the declared internal format, glGenerateMipmap's levels, or a buffer
// texture's range of one of the scene's buffers.
#include <string>

#include "scene/scene.h"
#include "texture/texture.h"

namespace tessref {

// shaders.textures[k] as a texture: its level files in its internal format (rows from the bottom,
// as GL numbers them), glGenerateMipmap's levels when asked, its sampler state, finalized; for
// GL_TEXTURE_BUFFER, its range of the scene's buffer. InputError, naming `key` ("SCENE:
// shaders.textures.NAME"), for an unreadable file, a file whose channels are not the declared
// format's, a level whose size is not the one glTexStorage* gives it, or a buffer range that the
// buffer does not hold.
texture::Texture load_texture(const TextureSetting& t, const std::string& key, const Scene& scene);

}  // namespace tessref
