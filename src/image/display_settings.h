#pragma once
// How an image's linear radiance is shown: exposure and tone mapper, for PNG files, the viewer and the browser.
#include <string>

#include "image/tonemap.h"

namespace candela {

struct DisplaySettings {
  float exposure = 0.0f;  // stops
  ToneMapper toneMapper = ToneMapper::AcesFilmic;
};

// "aces", "clamp" or "reinhard"; parseToneMapper throws std::invalid_argument for other names.
const char* toneMapperName(ToneMapper mapper);
ToneMapper parseToneMapper(const std::string& name);

}  // namespace candela
