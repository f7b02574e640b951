#pragma once
#include <memory>

#include "app/denoising/denoiser_choice.h"
#include "app/denoising/optix_ai_denoiser.h"
#include "backends/backend.h"
#include "backends/film_filters.h"

namespace candela {

// The parameters of the filters a choice may use.
struct DenoiserParams {
  AtrousParams atrous;
  BilateralParams bilateral;
  TemporalParams temporal;
};

// One denoiser for the images of one backend's film, made once for a render or a sequence of frames, so that what
// it keeps (the OptiX AI denoiser's model and memory, the temporal filter's history) serves every image. The film
// filters run where the backend's film is (Backend::filters); the OptiX AI denoiser on the image and guides read
// back.
class FilmDenoiser {
 public:
  // Throws std::runtime_error with one sentence where `choice` is not in this build.
  FilmDenoiser(DenoiserChoice choice, const DenoiserParams& params);
  DenoiserChoice choice() const { return choice_; }

  // The backend's accumulated image through the denoiser (its AOVs enabled unless the choice is None). `camera`
  // saw the film; `filmContinues` says that it is the film of the previous call with samples added since (the
  // temporal filter then keeps its history). `aovs`, where the caller read them already, saves reading them again.
  // Where the OptiX AI denoiser cannot run (no GPU, no weights in the driver), it says so on stderr, once, and the
  // image is returned as rendered.
  Image apply(const Backend& backend, const Camera& camera, bool filmContinues, const AovImages* aovs = nullptr);

 private:
  DenoiserChoice choice_;
  DenoiserParams params_;
  std::unique_ptr<TemporalDenoiser> temporal_;
  const Backend* temporalBackend_ = nullptr;  // the one temporal_ filters
  OptixAiDenoise optix_;
  bool optixFailed_ = false;
};

}  // namespace candela
