#pragma once
// Decoding images into Scene textures (sRGB rgba8, top row first) through OpenImageIO.

#include <cstddef>
#include <string>

#include "framework/scene/scene.h"

namespace lpvlab {

// Reads an image file. Throws an Error naming the file and OpenImageIO's reason.
TextureImage readTextureFile(const std::string& path);

// Decodes an image held in memory (e.g. a texture embedded in a .glb). `formatHint` is the file
// extension of its format ("png", "jpg"); `name` names it in TextureImage::path and in errors.
TextureImage decodeTexture(const void* data, std::size_t size, const std::string& formatHint,
                      const std::string& name);

}  // namespace lpvlab
