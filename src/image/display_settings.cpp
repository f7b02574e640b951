#include "image/display_settings.h"

#include <stdexcept>

namespace candela {

const char* toneMapperName(ToneMapper mapper) {
  switch (mapper) {
    case ToneMapper::Clamp: return "clamp";
    case ToneMapper::Reinhard: return "reinhard";
    case ToneMapper::AcesFilmic: break;
  }
  return "aces";
}

ToneMapper parseToneMapper(const std::string& name) {
  for (ToneMapper m : {ToneMapper::AcesFilmic, ToneMapper::Clamp, ToneMapper::Reinhard})
    if (name == toneMapperName(m)) return m;
  throw std::invalid_argument("unknown tone mapper '" + name + "' (use aces, clamp or reinhard)");
}

}  // namespace candela
