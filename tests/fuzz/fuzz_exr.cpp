// libFuzzer entry point for OpenEXR environment maps: decoding from memory (data windows anywhere, every
// compression OpenEXR reads) and the sampling distribution of whatever decodes.
#include <cstddef>
#include <cstdint>

#include "scene/environment_distribution.h"
#include "scene/loaders/exr_decoding.h"
#include "scene/loaders/load_diagnostics.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    candela::Texture t = candela::decodeExr("fuzz.exr", data, size);
    std::vector<candela::Vec3> texels(size_t(t.width) * t.height);
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = {t.floats[3 * i], t.floats[3 * i + 1], t.floats[3 * i + 2]};
    candela::EnvironmentDistribution::build(texels, t.width, t.height);
  } catch (const candela::LoadError&) {
  }
  return 0;
}
