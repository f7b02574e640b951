// libFuzzer entry point for image decoding as environment maps use it (Radiance .hdr among stb_image's
// formats), followed by building the sampling distribution of whatever decodes.
#include <cstddef>
#include <cstdint>

#include "io/images/image_decoding.h"
#include "io/load_diagnostics.h"
#include "scene/environment_distribution.h"
#include "texture_decoding_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const candela::ImageInfo info = candela::inspectImage("fuzz.hdr", data, size);
    if (uint64_t(info.width) * info.height > candela::fuzz::kMaxFuzzedPixels) return 0;
    candela::Texture t = candela::decodeImage("fuzz.hdr", data, size, false);
    if (!t.floats.empty()) {
      std::vector<candela::Vec3> texels(size_t(t.width) * t.height);
      for (size_t i = 0; i < texels.size(); ++i)
        texels[i] = {t.floats[4 * i], t.floats[4 * i + 1], t.floats[4 * i + 2]};
      candela::EnvironmentDistribution::build(texels, t.width, t.height);
    }
  } catch (const candela::LoadError&) {
  }
  return 0;
}
