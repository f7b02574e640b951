#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/load_diagnostics.h"
#include "scene/scene.h"

namespace candela {

// How large textures may be once decoded. A texture over the size limit, or textures that together exceed the
// memory limit, are decoded smaller (area averaged) with a warning; the command line raises both
// (--max-texture-size, --max-texture-memory). The memory limit counts each texture's mip pyramid (about 4/3 of
// its finest level; textureBytesWithMips), which the renderer builds from it. Environment maps are not textures
// and are not limited here.
struct TextureLimits {
  uint32_t maxSize = 8192;                // largest width or height of a texture, in pixels
  uint64_t maxBytes = uint64_t(4) << 30;  // decoded bytes of all the textures of a scene, mip levels included
};

// The limits the texture loaders use, for the whole process; loadScene sets them from its options.
void setTextureLimits(const TextureLimits& limits);
TextureLimits textureLimits();

// A texture's size and how many bytes a pixel of it takes once decoded.
struct TextureExtent {
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t bytesPerPixel = 4;
};

// Bytes of a texture of this extent with all its mip levels (kernel/texture.h's level sizes).
uint64_t textureBytesWithMips(const TextureExtent& e);

// The sizes to decode images at so that they keep within `limits`: an image's own size when it fits, else the
// largest of about the same aspect ratio that does (never below 1x1).
std::vector<TextureExtent> fitTextureLimits(const std::vector<TextureExtent>& images, const TextureLimits& limits);

// "<name>: texture of WxH pixels downscaled to wxh (...)": the warning for an image decoded smaller.
std::string downscaleWarning(const std::string& name, TextureExtent from, TextureExtent to,
                             const TextureLimits& limits);

// Downscales the scene's decoded textures to keep within `limits`, with a warning for each: the loaders keep each
// model within them, this keeps a scene of several models (or of models from the scene cache) within them too.
void fitSceneTextures(Scene& scene, const TextureLimits& limits, LoadWarnings& warnings);

}  // namespace candela
