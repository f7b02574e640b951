#include "app/denoising/film_denoiser.h"

#include <cstdio>
#include <stdexcept>

namespace candela {

FilmDenoiser::FilmDenoiser(DenoiserChoice choice, const DenoiserParams& params) : choice_(choice), params_(params) {
  if (!inThisBuild(choice)) throw std::runtime_error(notInThisBuild(choice));
}

Image FilmDenoiser::apply(const Backend& backend, const Camera& camera, bool filmContinues, const AovImages* aovs) {
  switch (choice_) {
    case DenoiserChoice::None: return backend.readImage();
    case DenoiserChoice::Atrous: return backend.filters().atrous(params_.atrous);
    case DenoiserChoice::Bilateral: return backend.filters().bilateral(params_.bilateral);
    case DenoiserChoice::Temporal:
      if (!temporal_ || temporalBackend_ != &backend) {
        temporal_ = backend.filters().temporal(params_.temporal);
        temporalBackend_ = &backend;
      }
      return temporal_->denoise(camera, filmContinues);
    case DenoiserChoice::Optix: break;
  }
  const Image image = backend.readImage();
  if (optixFailed_) return image;
  try {
    if (!optix_) optix_ = makeOptixAiDenoiser();
    if (aovs) return optix_(image, *aovs);
    return optix_(image, backend.readAovs());
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "candela: %s; the image is kept without denoising\n", e.what());
    optixFailed_ = true;
  }
  return image;
}

}  // namespace candela
