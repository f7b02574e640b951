#pragma once
// The denoisers an image can go through, by one name everywhere: the command line, the viewer's state file, the
// browser's messages.
#include <string>
#include <vector>

namespace candela {

enum class DenoiserChoice {
  None,
  Atrous,     // edge-avoiding a-trous wavelets guided by albedo, normal and depth, where the film is
  Bilateral,  // the bilateral filter, which keeps the emission apart
  Temporal,   // the a-trous filter with a history reprojected from the frames before: image sequences only
  Optix,      // the OptiX AI denoiser, from the image and the albedo and normal guides read back
};

constexpr DenoiserChoice kDenoiserChoices[] = {DenoiserChoice::None, DenoiserChoice::Atrous, DenoiserChoice::Bilateral,
                                               DenoiserChoice::Temporal, DenoiserChoice::Optix};

// "none", "atrous", "bilateral", "temporal" or "optix".
constexpr const char* denoiserName(DenoiserChoice choice) {
  switch (choice) {
    case DenoiserChoice::Atrous: return "atrous";
    case DenoiserChoice::Bilateral: return "bilateral";
    case DenoiserChoice::Temporal: return "temporal";
    case DenoiserChoice::Optix: return "optix";
    case DenoiserChoice::None: break;
  }
  return "none";
}
// The choice of that name; throws std::invalid_argument naming the choices for another.
DenoiserChoice parseDenoiser(const std::string& name);
// One line for --help: the choices with what each does.
std::string describeDenoisers(const std::vector<DenoiserChoice>& choices);

// Every denoiser but None reads the AOVs (the bilateral filter the emission, which is recorded with them).
constexpr bool needsAovs(DenoiserChoice choice) { return choice != DenoiserChoice::None; }
// Whether this build can run it: the OptiX AI denoiser comes with the OptiX backend.
bool inThisBuild(DenoiserChoice choice);
// The sentence that says why a choice is not in this build; empty where it is.
std::string notInThisBuild(DenoiserChoice choice);

}  // namespace candela
