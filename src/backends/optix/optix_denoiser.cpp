#include "backends/optix/optix_denoiser.h"

#include <optix.h>
#include <optix_stubs.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "backends/optix/device_buffer.h"
#include "backends/optix/optix_context.h"
#include "backends/optix/optix_error.h"

namespace candela {

using namespace optix;

namespace {

void checkDenoiser(OptixResult result, const char* what) {
  if (result == OPTIX_ERROR_INTERNAL_ERROR)
    throw OptixError(result, std::string("the OptiX denoiser failed while ") + what +
                                 " (OptiX error 7990): the driver's denoiser weights (nvoptix.bin) are missing or "
                                 "do not match the driver");
  checkOptix(result, what);
}

class DenoiserHandle {
 public:
  DenoiserHandle(OptixDeviceContext context, const OptixDenoiserOptions& options) {
    checkDenoiser(optixDenoiserCreate(context, OPTIX_DENOISER_MODEL_KIND_AOV, &options, &denoiser_),
                  "creating the denoiser");
  }
  ~DenoiserHandle() { optixDenoiserDestroy(denoiser_); }
  DenoiserHandle(const DenoiserHandle&) = delete;
  DenoiserHandle& operator=(const DenoiserHandle&) = delete;
  OptixDenoiser get() const { return denoiser_; }

 private:
  OptixDenoiser denoiser_ = nullptr;
};

OptixImage2D float3Image(const DeviceBuffer& buffer, uint32_t width, uint32_t height) {
  OptixImage2D image{};
  image.data = buffer.address();
  image.width = width;
  image.height = height;
  image.rowStrideInBytes = width * uint32_t(sizeof(Vec3));
  image.pixelStrideInBytes = sizeof(Vec3);
  image.format = OPTIX_PIXEL_FORMAT_FLOAT3;
  return image;
}

void requireSameSize(const Image* guide, const Image& beauty, const char* name) {
  if (guide && (guide->width != beauty.width || guide->height != beauty.height))
    throw std::invalid_argument(std::string("the denoiser's ") + name + " guide differs in size from the image");
}

}  // namespace

Image denoiseWithOptix(const Image& beauty, const DenoiserGuides& guides) {
  requireSameSize(guides.albedo, beauty, "albedo");
  requireSameSize(guides.normal, beauty, "normal");
  const uint32_t width = beauty.width, height = beauty.height;
  OptixContext context;
  cudaStream_t stream = context.stream();

  OptixDenoiserOptions options{};
  options.guideAlbedo = guides.albedo ? 1u : 0u;
  options.guideNormal = guides.normal ? 1u : 0u;
  options.denoiseAlpha = OPTIX_DENOISER_ALPHA_MODE_COPY;
  DenoiserHandle denoiser(context.get(), options);

  OptixDenoiserSizes sizes{};
  checkDenoiser(optixDenoiserComputeMemoryResources(denoiser.get(), width, height, &sizes),
                "sizing the denoiser's memory");
  DeviceBuffer state(sizes.stateSizeInBytes, "the denoiser's state");
  DeviceBuffer scratch(std::max({sizes.withoutOverlapScratchSizeInBytes, sizes.computeIntensitySizeInBytes,
                                 sizes.computeAverageColorSizeInBytes}),
                       "the denoiser's scratch memory");
  checkDenoiser(optixDenoiserSetup(denoiser.get(), stream, width, height, state.address(), state.size(),
                                   scratch.address(), scratch.size()),
                "setting the denoiser up");

  DeviceBuffer input = DeviceBuffer::fromVector(beauty.pixels, "the image to denoise");
  DeviceBuffer output(input.size(), "the denoised image");
  DeviceBuffer albedo = guides.albedo ? DeviceBuffer::fromVector(guides.albedo->pixels, "the albedo guide")
                                      : DeviceBuffer();
  DeviceBuffer normal = guides.normal ? DeviceBuffer::fromVector(guides.normal->pixels, "the normal guide")
                                      : DeviceBuffer();
  DeviceBuffer intensity(sizeof(float), "the denoiser's intensity");
  DeviceBuffer averageColor(3 * sizeof(float), "the denoiser's average colour");

  OptixDenoiserLayer layer{};
  layer.input = float3Image(input, width, height);
  layer.output = float3Image(output, width, height);
  OptixDenoiserGuideLayer guideLayer{};
  if (guides.albedo) guideLayer.albedo = float3Image(albedo, width, height);
  if (guides.normal) guideLayer.normal = float3Image(normal, width, height);

  checkDenoiser(optixDenoiserComputeIntensity(denoiser.get(), stream, &layer.input, intensity.address(),
                                              scratch.address(), scratch.size()),
                "measuring the image's intensity");
  checkDenoiser(optixDenoiserComputeAverageColor(denoiser.get(), stream, &layer.input, averageColor.address(),
                                                 scratch.address(), scratch.size()),
                "measuring the image's average colour");
  OptixDenoiserParams params{};
  params.hdrIntensity = intensity.address();
  params.hdrAverageColor = averageColor.address();
  params.blendFactor = 0.0f;
  checkDenoiser(optixDenoiserInvoke(denoiser.get(), stream, &params, state.address(), state.size(), &guideLayer,
                                    &layer, 1, 0, 0, scratch.address(), scratch.size()),
                "denoising");
  checkCuda(cudaStreamSynchronize(stream), "denoising");

  Image result(width, height);
  output.download(result.pixels.data(), output.size());
  return result;
}

}  // namespace candela
