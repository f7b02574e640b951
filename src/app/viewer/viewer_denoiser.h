#pragma once
#include <functional>
#include <string>

#include "app/viewer/post_settings.h"
#include "app/viewer/render_session.h"

namespace candela {

// The viewer's denoisers applied to the session's accumulated image. The OptiX AI denoiser is made when first
// asked for and kept for the frames after, so that its model and memory are not made again every frame.
class ViewerDenoiser {
 public:
  // Whether this build has the OptiX AI denoiser (it comes with the OptiX backend).
  static bool optixInThisBuild();

  // Makes the OptiX AI denoiser unless it is made already. Throws std::runtime_error with one sentence where it
  // cannot run: not in this build, no usable GPU, or no denoiser weights in the driver (OptiX error 7990).
  void prepareOptix();
  // For a window or page: prepares the OptiX AI denoiser where `choice` asks for it; where it cannot run, turns
  // `choice` to None and returns the sentence to show (empty when nothing went wrong).
  std::string prepareOrTurnOff(DenoiserChoice& choice);

  // The accumulated image through `choice` (None: as it is). The AOVs must be enabled for the others, and
  // prepareOptix must have succeeded for Optix.
  Image apply(const RenderSession& session, DenoiserChoice choice, const AtrousParams& atrousParams);

 private:
  std::function<Image(const Image&, const AovImages&)> optix_;
};

}  // namespace candela
