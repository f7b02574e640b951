#include "scene/loaders/texture_limits.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <type_traits>

#include "io/images/area_downscaler.h"
#include "kernel/texture.h"

namespace candela {

namespace {

std::atomic<uint32_t> currentMaxSize{TextureLimits{}.maxSize};
std::atomic<uint64_t> currentMaxBytes{TextureLimits{}.maxBytes};

TextureExtent scaled(const TextureExtent& e, double scale) {
  TextureExtent s = e;
  s.width = uint32_t(std::clamp(std::floor(double(e.width) * scale), 1.0, double(e.width)));
  s.height = uint32_t(std::clamp(std::floor(double(e.height) * scale), 1.0, double(e.height)));
  return s;
}

}  // namespace

void setTextureLimits(const TextureLimits& limits) {
  currentMaxSize = limits.maxSize;
  currentMaxBytes = limits.maxBytes;
}

TextureLimits textureLimits() { return {currentMaxSize.load(), currentMaxBytes.load()}; }

uint64_t textureBytesWithMips(const TextureExtent& e) {
  uint64_t bytes = 0;
  for (uint32_t level = 0, levels = fullMipLevelCount(e.width, e.height); level < levels; ++level)
    bytes += uint64_t(mipLevelSize(e.width, level)) * mipLevelSize(e.height, level) * e.bytesPerPixel;
  return bytes;
}

std::vector<TextureExtent> fitTextureLimits(const std::vector<TextureExtent>& images, const TextureLimits& limits) {
  std::vector<TextureExtent> fitted;
  uint64_t total = 0;
  for (const TextureExtent& e : images) {
    TextureExtent f = e;
    // The longer side becomes the limit exactly; the other keeps the aspect ratio, rounded down.
    if (e.width >= e.height && e.width > limits.maxSize) {
      f.width = limits.maxSize;
      f.height = uint32_t(std::max<uint64_t>(1, uint64_t(e.height) * limits.maxSize / e.width));
    } else if (e.height > e.width && e.height > limits.maxSize) {
      f.height = limits.maxSize;
      f.width = uint32_t(std::max<uint64_t>(1, uint64_t(e.width) * limits.maxSize / e.height));
    }
    fitted.push_back(f);
    total += textureBytesWithMips(fitted.back());
  }
  if (total <= limits.maxBytes) return fitted;
  // One factor for every texture keeps their relative resolution. Sides round down, but the coarsest levels
  // stay 1 texel wide, so a pyramid need not shrink with the square of the factor: shrink on until it fits, or
  // until every texture is down to 1x1.
  double scale = std::sqrt(double(limits.maxBytes) / double(total));
  for (;;) {
    std::vector<TextureExtent> shrunk;
    uint64_t shrunkTotal = 0;
    bool smallest = true;
    for (const TextureExtent& e : fitted) {
      shrunk.push_back(scaled(e, scale));
      shrunkTotal += textureBytesWithMips(shrunk.back());
      smallest = smallest && shrunk.back().width == 1 && shrunk.back().height == 1;
    }
    if (shrunkTotal <= limits.maxBytes || smallest) return shrunk;
    scale *= 0.95;
  }
}

std::string downscaleWarning(const std::string& name, TextureExtent from, TextureExtent to,
                             const TextureLimits& limits) {
  auto size = [](TextureExtent e) { return std::to_string(e.width) + "x" + std::to_string(e.height); };
  const bool bySize =
      std::max(from.width, from.height) > limits.maxSize && std::max(to.width, to.height) == limits.maxSize;
  const std::string why =
      bySize ? "the texture size limit is " + std::to_string(limits.maxSize) + " pixels (--max-texture-size)"
             : "the scene's textures with their mip levels exceed the texture memory limit of " +
                   std::to_string(limits.maxBytes >> 20) + " MiB (--max-texture-memory)";
  return name + ": texture of " + size(from) + " pixels downscaled to " + size(to) + ": " + why;
}

void fitSceneTextures(Scene& scene, const TextureLimits& limits, LoadWarnings& warnings) {
  std::vector<TextureExtent> extents;
  for (const Texture& t : scene.textures)
    extents.push_back({t.width, t.height, t.channels * (t.floats.empty() ? 1u : uint32_t(sizeof(float)))});
  const std::vector<TextureExtent> fitted = fitTextureLimits(extents, limits);
  for (size_t i = 0; i < scene.textures.size(); ++i) {
    Texture& t = scene.textures[i];
    const TextureExtent& to = fitted[i];
    if (to.width == t.width && to.height == t.height) continue;
    warnings.messages.push_back(downscaleWarning(t.name, extents[i], to, limits));
    auto shrink = [&](auto& samples) {
      using Sample = typename std::decay_t<decltype(samples)>::value_type;
      AreaDownscaler<Sample> target(t.width, t.height, to.width, to.height, t.channels);
      for (uint32_t y = 0; y < t.height; ++y) target.addRow(&samples[size_t(y) * t.width * t.channels]);
      samples = target.finish();
    };
    if (t.floats.empty())
      shrink(t.bytes);
    else
      shrink(t.floats);
    t.width = to.width;
    t.height = to.height;
  }
}

}  // namespace candela
