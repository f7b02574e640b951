#pragma once
// A scene's textures as CUDA mipmapped arrays sampled through texture objects: the texture unit does the wrap,
// the bilinear, trilinear and anisotropic filters and the sRGB decode that kernel code otherwise does texel by
// texel (kernel/texture.h, kernel/texture_filtering.h).
#include <cuda_runtime.h>

#include <cstddef>
#include <vector>

#include "kernel/texture_filtering.h"

namespace candela::optix {

class DeviceTextures {
 public:
  DeviceTextures() = default;
  ~DeviceTextures();
  DeviceTextures(DeviceTextures&& other) noexcept;
  DeviceTextures& operator=(DeviceTextures&& other) noexcept;
  DeviceTextures(const DeviceTextures&) = delete;
  DeviceTextures& operator=(const DeviceTextures&) = delete;

  // One four-channel mipmapped array, with the view's levels, and texture object per view with texels (8-bit
  // views as uchar4 read as normalised floats, sRGB-decoded where the view says so; float views as float4),
  // normalised coordinates, linear filtering within and between levels, anisotropy up to kMaxAnisotropy and the
  // view's wrap modes. The texels of every level are read from the host arrays at the views' offsets.
  DeviceTextures(const std::vector<TextureView>& views, const std::vector<uint8_t>& texelBytes,
                 const std::vector<float>& texelFloats);

  // The views with deviceTexture set; views without texels (zero width or height) keep 0.
  const std::vector<TextureView>& views() const { return views_; }
  size_t deviceBytes() const { return bytes_; }

 private:
  void release() noexcept;

  std::vector<TextureView> views_;
  std::vector<cudaMipmappedArray_t> arrays_;
  std::vector<cudaTextureObject_t> objects_;
  size_t bytes_ = 0;
};

}  // namespace candela::optix
