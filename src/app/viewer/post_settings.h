#pragma once
#include "image/filters/bilateral.h"
#include "image/image_io.h"

namespace candela {

// What happens to the accumulated image between the backend and the screen (or a screenshot).
struct PostSettings {
  DisplaySettings display;
  bool bilateral = false;
  BilateralParams bilateralParams;
};

}  // namespace candela
