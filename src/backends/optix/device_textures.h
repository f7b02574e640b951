#pragma once
// A scene's textures as CUDA arrays sampled through texture objects: the texture unit does the wrap, the
// bilinear filter and the sRGB decode that kernel code otherwise does texel by texel (kernel/texture.h).
#include <cuda_runtime.h>

#include <cstddef>
#include <vector>

#include "kernel/texture.h"

namespace candela::optix {

class DeviceTextures {
 public:
  DeviceTextures() = default;
  ~DeviceTextures();
  DeviceTextures(DeviceTextures&& other) noexcept;
  DeviceTextures& operator=(DeviceTextures&& other) noexcept;
  DeviceTextures(const DeviceTextures&) = delete;
  DeviceTextures& operator=(const DeviceTextures&) = delete;

  // One four-channel array and texture object per view with texels (8-bit views as uchar4 read as normalised
  // floats, sRGB-decoded where the view says so; float views as float4), normalised coordinates, linear
  // filtering and the view's wrap mode. The texels are read from the host arrays at the views' offsets.
  DeviceTextures(const std::vector<TextureView>& views, const std::vector<uint8_t>& texelBytes,
                 const std::vector<float>& texelFloats);

  // The views with deviceTexture set; views without texels (zero width or height) keep 0.
  const std::vector<TextureView>& views() const { return views_; }
  size_t deviceBytes() const { return bytes_; }

 private:
  void release() noexcept;

  std::vector<TextureView> views_;
  std::vector<cudaArray_t> arrays_;
  std::vector<cudaTextureObject_t> objects_;
  size_t bytes_ = 0;
};

}  // namespace candela::optix
