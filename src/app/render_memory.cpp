#include "app/render_memory.h"

#include "io/available_memory.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

namespace candela {

namespace {

// Bytes per pixel of the buffers: Vec3 images, a float depth, the a-trous denoiser's 22 float planes (six guides, and
// eight for each of its two signals).
constexpr uint64_t kImage = 12, kAovs = 12 + 12 + 4, kAtrousPlanes = 22 * 4, kBilateralPlanes = 3 * 4;
// An encoded 8-bit RGB output (stb builds the PNG in memory) or the rows OpenEXR and PFM write from.
constexpr uint64_t kEncoded = 10;

std::string gib(uint64_t bytes) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f GiB", double(bytes) / double(1ull << 30));
  return buffer;
}

}  // namespace

uint64_t estimateRenderBytes(const RenderJob& job) {
  const uint64_t pixels = uint64_t(job.settings.width) * job.settings.height;
  const bool aovs = !job.aovs.empty() || needsAovs(job.denoiser);
  const uint64_t film = kImage + (aovs ? kAovs : 0);
  // The peak is the largest of three moments. Denoising, with the film still there: the image read out, the
  // guides, the denoiser's planes and its result.
  uint64_t denoising = film + kImage;
  switch (job.denoiser) {
    case DenoiserChoice::Atrous:
    case DenoiserChoice::Temporal: denoising += kAovs + kAtrousPlanes + kImage; break;
    case DenoiserChoice::Bilateral: denoising += kBilateralPlanes + kImage; break;
    case DenoiserChoice::Optix: denoising += kAovs + kImage; break;
    case DenoiserChoice::None: break;
  }
  // Reading the AOVs for the output, the film still there.
  const uint64_t readingAovs = film + kImage + (aovs ? kAovs : 0);
  // Writing, the backend gone: the image, the AOVs, each file encoded (the depth AOV first becomes an image).
  const bool depth = std::find(job.aovs.begin(), job.aovs.end(), Aov::Depth) != job.aovs.end();
  const uint64_t writing =
      kImage + (job.aovs.empty() ? 0 : kAovs) + kEncoded * (1 + job.aovs.size()) + (depth ? kImage : 0);
  return pixels * std::max({denoising, readingAovs, writing});
}

void checkRenderMemory(const RenderJob& job) {
  const uint64_t needed = estimateRenderBytes(job), available = availableMemoryBytes();
  if (needed > available)
    throw std::runtime_error("a " + std::to_string(job.settings.width) + "x" + std::to_string(job.settings.height) +
                             " render with these AOVs and denoiser needs about " + gib(needed) + " of memory, but " +
                             gib(available) + " is available; render smaller, with fewer AOVs or without denoising");
}

}  // namespace candela
