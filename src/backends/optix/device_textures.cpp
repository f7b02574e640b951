#include "backends/optix/device_textures.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "backends/optix/optix_error.h"

namespace candela::optix {

namespace {

// A view's texels widened to four channels the way fetchTexel reads them: grey repeats its channel, grey +
// alpha fills RGB from the grey, RGB gets an opaque alpha.
template <class Texel, class Channel>
std::vector<Texel> widenToFourChannels(const TextureView& view, const std::vector<Channel>& texels, Channel opaque) {
  const size_t count = size_t(view.width) * view.height;
  if (view.offset + count * view.channels > texels.size())
    throw std::runtime_error("a texture's texels run past the end of the scene's texel array");
  std::vector<Texel> out(count);
  for (size_t i = 0; i < count; ++i) {
    const Channel* c = texels.data() + view.offset + i * view.channels;
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

cudaArray_t allocateArray(const cudaChannelFormatDesc& format, const TextureView& view, size_t bytes) {
  cudaArray_t array = nullptr;
  cudaError_t result = cudaMallocArray(&array, &format, view.width, view.height);
  if (result == cudaErrorMemoryAllocation) {
    cudaGetLastError();
    size_t free = 0, total = 0;
    cudaMemGetInfo(&free, &total);
    throw std::runtime_error("out of device memory: asked for " + formatBytes(bytes) + " for a " +
                             std::to_string(view.width) + "x" + std::to_string(view.height) + " texture with " +
                             formatBytes(free) + " of " + formatBytes(total) + " free");
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
      const size_t rowBytes = view.width * texelSize;
      const cudaChannelFormatDesc format = bytes ? cudaCreateChannelDesc<uchar4>() : cudaCreateChannelDesc<float4>();
      cudaArray_t array = allocateArray(format, view, rowBytes * view.height);
      arrays_.push_back(array);
      bytes_ += rowBytes * view.height;
      if (bytes) {
        std::vector<uchar4> texels = widenToFourChannels<uchar4, uint8_t>(view, texelBytes, 255);
        checkCuda(cudaMemcpy2DToArray(array, 0, 0, texels.data(), rowBytes, rowBytes, view.height,
                                      cudaMemcpyHostToDevice),
                  "uploading a texture");
      } else {
        std::vector<float4> texels = widenToFourChannels<float4, float>(view, texelFloats, 1.0f);
        checkCuda(cudaMemcpy2DToArray(array, 0, 0, texels.data(), rowBytes, rowBytes, view.height,
                                      cudaMemcpyHostToDevice),
                  "uploading a texture");
      }

      cudaResourceDesc resource{};
      resource.resType = cudaResourceTypeArray;
      resource.res.array.array = array;
      cudaTextureDesc sampling{};
      sampling.addressMode[0] = addressMode(view.wrapU);
      sampling.addressMode[1] = addressMode(view.wrapV);
      sampling.filterMode = cudaFilterModeLinear;
      sampling.readMode = bytes ? cudaReadModeNormalizedFloat : cudaReadModeElementType;
      sampling.sRGB = bytes && view.srgb ? 1 : 0;
      sampling.normalizedCoords = 1;
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
  for (cudaArray_t array : arrays_) cudaFreeArray(array);
  objects_.clear();
  arrays_.clear();
  bytes_ = 0;
}

}  // namespace candela::optix
