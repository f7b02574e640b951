#include "backends/optix/optix_denoiser.h"

#include <optix.h>
#include <optix_stubs.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends/optix/device_buffer.h"
#include "backends/optix/optix_context.h"
#include "backends/optix/optix_error.h"
#include "image/filters/atrous_kernel.h"

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

// A guide the denoiser was made for must be given, the size of the image; one it was not made for must not.
void checkGuide(const Image* guide, bool expected, const Image& beauty, const char* name) {
  if (bool(guide) != expected)
    throw std::invalid_argument(std::string("the denoiser was made ") + (expected ? "with" : "without") + " the " +
                                name + " guide");
  requireSameSize(guide, beauty, name);
}

}  // namespace

struct OptixImageDenoiser::State {
  explicit State(DenoiserGuideKinds guideKinds) : kinds(guideKinds), denoiser(context.get(), options(guideKinds)) {}

  static OptixDenoiserOptions options(DenoiserGuideKinds kinds) {
    OptixDenoiserOptions options{};
    options.guideAlbedo = kinds.albedo ? 1u : 0u;
    options.guideNormal = kinds.normal ? 1u : 0u;
    options.denoiseAlpha = OPTIX_DENOISER_ALPHA_MODE_COPY;
    return options;
  }

  // Memory and set-up for images of this size, unless the last image had it.
  void prepare(uint32_t newWidth, uint32_t newHeight) {
    if (newWidth == width && newHeight == height) return;
    width = height = 0;  // until set-up has succeeded
    OptixDenoiserSizes sizes{};
    checkDenoiser(optixDenoiserComputeMemoryResources(denoiser.get(), newWidth, newHeight, &sizes),
                  "sizing the denoiser's memory");
    state = DeviceBuffer(sizes.stateSizeInBytes, "the denoiser's state");
    scratch = DeviceBuffer(std::max({sizes.withoutOverlapScratchSizeInBytes, sizes.computeIntensitySizeInBytes,
                                     sizes.computeAverageColorSizeInBytes}),
                           "the denoiser's scratch memory");
    checkDenoiser(optixDenoiserSetup(denoiser.get(), context.stream(), newWidth, newHeight, state.address(),
                                     state.size(), scratch.address(), scratch.size()),
                  "setting the denoiser up");
    const size_t bytes = size_t(newWidth) * newHeight * sizeof(Vec3);
    input = DeviceBuffer(bytes, "the image to denoise");
    output = DeviceBuffer(bytes, "the denoised image");
    albedo = kinds.albedo ? DeviceBuffer(bytes, "the albedo guide") : DeviceBuffer();
    normal = kinds.normal ? DeviceBuffer(bytes, "the normal guide") : DeviceBuffer();
    width = newWidth;
    height = newHeight;
  }

  DenoiserGuideKinds kinds;
  OptixContext context;
  DenoiserHandle denoiser;
  uint32_t width = 0, height = 0;
  DeviceBuffer state, scratch, input, output, albedo, normal;
  DeviceBuffer intensity{sizeof(float), "the denoiser's intensity"};
  DeviceBuffer averageColor{3 * sizeof(float), "the denoiser's average colour"};
};

OptixImageDenoiser::OptixImageDenoiser(DenoiserGuideKinds kinds) : state_(std::make_unique<State>(kinds)) {}

OptixImageDenoiser::~OptixImageDenoiser() = default;

Image OptixImageDenoiser::denoise(const Image& beauty, const DenoiserGuides& guides) {
  State& s = *state_;
  checkGuide(guides.albedo, s.kinds.albedo, beauty, "albedo");
  checkGuide(guides.normal, s.kinds.normal, beauty, "normal");
  const uint32_t width = beauty.width, height = beauty.height;
  s.prepare(width, height);
  const size_t bytes = s.input.size();
  s.input.upload(beauty.pixels.data(), bytes);
  if (guides.albedo) s.albedo.upload(guides.albedo->pixels.data(), bytes);
  if (guides.normal) {
    std::vector<Vec3> unit(guides.normal->pixels.size());
    std::transform(guides.normal->pixels.begin(), guides.normal->pixels.end(), unit.begin(), unitOrZero);
    s.normal.upload(unit.data(), bytes);
  }

  OptixDenoiserLayer layer{};
  layer.input = float3Image(s.input, width, height);
  layer.output = float3Image(s.output, width, height);
  OptixDenoiserGuideLayer guideLayer{};
  if (guides.albedo) guideLayer.albedo = float3Image(s.albedo, width, height);
  if (guides.normal) guideLayer.normal = float3Image(s.normal, width, height);

  cudaStream_t stream = s.context.stream();
  checkDenoiser(optixDenoiserComputeIntensity(s.denoiser.get(), stream, &layer.input, s.intensity.address(),
                                              s.scratch.address(), s.scratch.size()),
                "measuring the image's intensity");
  checkDenoiser(optixDenoiserComputeAverageColor(s.denoiser.get(), stream, &layer.input, s.averageColor.address(),
                                                 s.scratch.address(), s.scratch.size()),
                "measuring the image's average colour");
  OptixDenoiserParams params{};
  params.hdrIntensity = s.intensity.address();
  params.hdrAverageColor = s.averageColor.address();
  params.blendFactor = 0.0f;
  checkDenoiser(optixDenoiserInvoke(s.denoiser.get(), stream, &params, s.state.address(), s.state.size(), &guideLayer,
                                    &layer, 1, 0, 0, s.scratch.address(), s.scratch.size()),
                "denoising");
  checkCuda(cudaStreamSynchronize(stream), "denoising");

  Image result(width, height);
  s.output.download(result.pixels.data(), bytes);
  return result;
}

Image denoiseWithOptix(const Image& beauty, const DenoiserGuides& guides) {
  // Before the GPU is asked for anything, so that a wrong call says so even where the denoiser cannot run.
  requireSameSize(guides.albedo, beauty, "albedo");
  requireSameSize(guides.normal, beauty, "normal");
  OptixImageDenoiser denoiser({guides.albedo != nullptr, guides.normal != nullptr});
  return denoiser.denoise(beauty, guides);
}

}  // namespace candela
