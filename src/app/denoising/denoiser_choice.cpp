#include "app/denoising/denoiser_choice.h"

#include <stdexcept>

namespace candela {

namespace {

const char* summary(DenoiserChoice choice) {
  switch (choice) {
    case DenoiserChoice::Atrous: return "edge-avoiding a-trous guided by albedo, normal and depth";
    case DenoiserChoice::Bilateral: return "keeps lights and emitters sharp";
    case DenoiserChoice::Temporal: return "a-trous with the history of the frames before, for --camera-path/-orbit";
    case DenoiserChoice::Optix: return "the OptiX AI denoiser with albedo and normal guides";
    case DenoiserChoice::None: break;
  }
  return "";
}

}  // namespace

DenoiserChoice parseDenoiser(const std::string& name) {
  std::string names;
  for (DenoiserChoice choice : kDenoiserChoices) {
    if (name == denoiserName(choice)) return choice;
    names += std::string(names.empty() ? "" : ", ") + denoiserName(choice);
  }
  throw std::invalid_argument("unknown denoiser '" + name + "' (use " + names + ")");
}

std::string describeDenoisers(const std::vector<DenoiserChoice>& choices) {
  std::string text;
  for (DenoiserChoice choice : choices) {
    if (!text.empty()) text += "; ";
    text += denoiserName(choice);
    if (*summary(choice)) text += std::string(" (") + summary(choice) + ")";
  }
  return text;
}

bool inThisBuild(DenoiserChoice choice) {
#if CANDELA_HAS_OPTIX
  (void)choice;
  return true;
#else
  return choice != DenoiserChoice::Optix;
#endif
}

std::string notInThisBuild(DenoiserChoice choice) {
  if (inThisBuild(choice)) return {};
  return "--denoise optix needs the OptiX backend, which is not in this build (see README, 'GPU backend')";
}

}  // namespace candela
