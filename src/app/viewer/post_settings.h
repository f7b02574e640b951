#pragma once
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "image/image_io.h"

namespace candela {

// What happens to the accumulated image between the backend and the screen (or a screenshot).
struct PostSettings {
  DisplaySettings display;
  // The a-trous denoiser on every frame, where the backend's film is (CPU filter, or CUDA for the optix backend);
  // it makes the backend accumulate the AOVs that guide it.
  bool atrous = false;
  AtrousParams atrousParams;
  bool bilateral = false;
  BilateralParams bilateralParams;
};

}  // namespace candela
