#include "app/denoising/optix_ai_denoiser.h"

#include <memory>
#include <stdexcept>

#if CANDELA_HAS_OPTIX
#include "backends/optix/optix_denoiser.h"
#endif

namespace candela {

OptixAiDenoise makeOptixAiDenoiser() {
#if CANDELA_HAS_OPTIX
  auto denoiser = std::make_shared<OptixImageDenoiser>(DenoiserGuideKinds{true, true});
  return [denoiser](const Image& beauty, const AovImages& guides) {
    return denoiser->denoise(beauty, {&guides.albedo, &guides.normal});
  };
#else
  throw std::runtime_error(
      "the OptiX AI denoiser comes with the OptiX backend, which is not in this build (see README, 'GPU "
      "backend')");
#endif
}

}  // namespace candela
