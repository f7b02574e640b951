#pragma once
#include "app/denoising/denoiser_choice.h"
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "io/images/image_io.h"

namespace candela {

// The denoisers the viewer and the page offer for the accumulated image before the display passes; each makes the
// backend accumulate the AOVs that guide it. The a-trous filter runs where the backend's film is, with the temporal
// filter's history while the camera moves (viewer_denoiser.h); the bilateral filter is a display pass of its own
// (PostSettings::bilateral).
constexpr DenoiserChoice kViewerDenoiserChoices[] = {DenoiserChoice::None, DenoiserChoice::Atrous,
                                                     DenoiserChoice::Optix};

// What happens to the accumulated image between the backend and the screen (or a screenshot).
struct PostSettings {
  DisplaySettings display;
  DenoiserChoice denoiser = DenoiserChoice::None;
  AtrousParams atrousParams;
  bool bilateral = false;
  BilateralParams bilateralParams;
};

}  // namespace candela
