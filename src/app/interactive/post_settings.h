#pragma once
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "image/image_io.h"

namespace candela {

// The denoiser the accumulated image goes through before the display passes. Each makes the backend accumulate
// the AOVs (albedo, normal, depth) that guide it.
enum class DenoiserChoice {
  None,
  Atrous,  // where the backend's film is: the CPU filter, or CUDA for the optix backend
  Optix,   // the OptiX AI denoiser, on the GPU, from the image and AOVs read back
};
constexpr DenoiserChoice kDenoiserChoices[] = {DenoiserChoice::None, DenoiserChoice::Atrous, DenoiserChoice::Optix};

// The choice's name on the command line and in the viewer's state file.
constexpr const char* denoiserName(DenoiserChoice choice) {
  switch (choice) {
    case DenoiserChoice::Atrous: return "atrous";
    case DenoiserChoice::Optix: return "optix";
    case DenoiserChoice::None: break;
  }
  return "none";
}

// What happens to the accumulated image between the backend and the screen (or a screenshot).
struct PostSettings {
  DisplaySettings display;
  DenoiserChoice denoiser = DenoiserChoice::None;
  AtrousParams atrousParams;
  bool bilateral = false;
  BilateralParams bilateralParams;
};

}  // namespace candela
