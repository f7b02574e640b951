#include "backends/optix/device_textures.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "backends/optix/optix_error.h"

namespace candela::optix {

namespace {

// A level's texels widened to four channels the way fetchTexel reads them: grey repeats its channel, grey +
// alpha fills RGB from the grey, RGB gets an opaque alpha.
template <class Texel, class Channel>
std::vector<Texel> widenToFourChannels(const TextureView& view, const TextureLevel& level,
                                       const std::vector<Channel>& texels, Channel opaque) {
  const size_t count = size_t(level.width) * level.height;
  if (level.offset + count * view.channels > texels.size())
    throw std::runtime_error("a texture's texels run past the end of the scene's texel array");
  std::vector<Texel> out(count);
  for (size_t i = 0; i < count; ++i) {
    const Channel* c = texels.data() + level.offset + i * view.channels;
    switch (view.channels) {
      case 1: out[i] = {c[0], c[0], c[0], opaque}; break;
      case 2: out[i] = {c[0], c[0], c[0], c[1]}; break;
      case 3: out[i] = {c[0], c[1], c[2], opaque}; break;
      default: out[i] = {c[0], c[1], c[2], c[3]}; break;
    }
  }
  return out;
}

cudaTextureAddressMode addressMode(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Clamp: return cudaAddressModeClamp;
    case TextureWrap::Mirror: return cudaAddressModeMirror;
    case TextureWrap::Repeat: break;
  }
  return cudaAddressModeWrap;
}

cudaMipmappedArray_t allocateArray(const cudaChannelFormatDesc& format, const TextureView& view, size_t bytes) {
  cudaMipmappedArray_t array = nullptr;
  cudaError_t result =
      cudaMallocMipmappedArray(&array, &format, make_cudaExtent(view.width, view.height, 0), view.levels);
  if (result == cudaErrorMemoryAllocation) {
    cudaGetLastError();
    size_t free = 0, total = 0;
    cudaMemGetInfo(&free, &total);
    throw std::runtime_error("out of device memory: asked for " + formatBytes(bytes) + " for a " +
                             std::to_string(view.width) + "x" + std::to_string(view.height) + " texture (" +
                             std::to_string(view.levels) + " mip levels) with " + formatBytes(free) + " of " +
                             formatBytes(total) + " free");
  }
  checkCuda(result, "allocating a texture array");
  return array;
}

}  // namespace

DeviceTextures::DeviceTextures(const std::vector<TextureView>& views, const std::vector<uint8_t>& texelBytes,
                               const std::vector<float>& texelFloats)
    : views_(views) {
  try {
    for (TextureView& view : views_) {
      if (view.width == 0 || view.height == 0) continue;
      const bool bytes = view.format == TexelFormat::Unorm8;
      const size_t texelSize = bytes ? sizeof(uchar4) : sizeof(float4);
      size_t arrayBytes = 0;
      for (uint32_t level = 0; level < view.levels; ++level)
        arrayBytes += size_t(mipLevelSize(view.width, level)) * mipLevelSize(view.height, level) * texelSize;
      const cudaChannelFormatDesc format = bytes ? cudaCreateChannelDesc<uchar4>() : cudaCreateChannelDesc<float4>();
      cudaMipmappedArray_t array = allocateArray(format, view, arrayBytes);
      arrays_.push_back(array);
      bytes_ += arrayBytes;
      for (uint32_t level = 0; level < view.levels; ++level) {
        const TextureLevel texels = textureLevel(view, level);
        const size_t rowBytes = texels.width * texelSize;
        cudaArray_t levelArray = nullptr;
        checkCuda(cudaGetMipmappedArrayLevel(&levelArray, array, level), "finding a texture's mip level");
        if (bytes) {
          std::vector<uchar4> widened = widenToFourChannels<uchar4, uint8_t>(view, texels, texelBytes, 255);
          checkCuda(cudaMemcpy2DToArray(levelArray, 0, 0, widened.data(), rowBytes, rowBytes, texels.height,
                                        cudaMemcpyHostToDevice),
                    "uploading a texture");
        } else {
          std::vector<float4> widened = widenToFourChannels<float4, float>(view, texels, texelFloats, 1.0f);
          checkCuda(cudaMemcpy2DToArray(levelArray, 0, 0, widened.data(), rowBytes, rowBytes, texels.height,
                                        cudaMemcpyHostToDevice),
                    "uploading a texture");
        }
      }

      cudaResourceDesc resource{};
      resource.resType = cudaResourceTypeMipmappedArray;
      resource.res.mipmap.mipmap = array;
      cudaTextureDesc sampling{};
      sampling.addressMode[0] = addressMode(view.wrapU);
      sampling.addressMode[1] = addressMode(view.wrapV);
      sampling.filterMode = cudaFilterModeLinear;
      sampling.readMode = bytes ? cudaReadModeNormalizedFloat : cudaReadModeElementType;
      sampling.sRGB = bytes && view.srgb ? 1 : 0;
      sampling.normalizedCoords = 1;
      // Between levels as on the host (kernel/texture_filtering.h); anisotropic where tex2DGrad asks for it.
      sampling.mipmapFilterMode = cudaFilterModeLinear;
      sampling.minMipmapLevelClamp = 0.0f;
      sampling.maxMipmapLevelClamp = float(view.levels - 1);
      sampling.maxAnisotropy = kMaxAnisotropy;
      cudaTextureObject_t object = 0;
      checkCuda(cudaCreateTextureObject(&object, &resource, &sampling, nullptr), "creating a texture object");
      objects_.push_back(object);
      view.deviceTexture = object;
    }
  } catch (...) {
    release();
    throw;
  }
}

DeviceTextures::~DeviceTextures() { release(); }

DeviceTextures::DeviceTextures(DeviceTextures&& other) noexcept
    : views_(std::move(other.views_)),
      arrays_(std::move(other.arrays_)),
      objects_(std::move(other.objects_)),
      bytes_(std::exchange(other.bytes_, 0)) {
  other.arrays_.clear();
  other.objects_.clear();
}

DeviceTextures& DeviceTextures::operator=(DeviceTextures&& other) noexcept {
  if (this != &other) {
    release();
    views_ = std::move(other.views_);
    arrays_ = std::move(other.arrays_);
    objects_ = std::move(other.objects_);
    bytes_ = std::exchange(other.bytes_, 0);
    other.arrays_.clear();
    other.objects_.clear();
  }
  return *this;
}

void DeviceTextures::release() noexcept {
  for (cudaTextureObject_t object : objects_) cudaDestroyTextureObject(object);
  for (cudaMipmappedArray_t array : arrays_) cudaFreeMipmappedArray(array);
  objects_.clear();
  arrays_.clear();
  bytes_ = 0;
}

}  // namespace candela::optix
