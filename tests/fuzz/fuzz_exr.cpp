// libFuzzer entry point for OpenEXR environment maps: decoding from memory (data windows anywhere, every
// compression OpenEXR reads) and the sampling distribution of whatever decodes.
#include <cstddef>
#include <cstdint>

#include "io/images/exr_decoding.h"
#include "io/load_diagnostics.h"
#include "scene/environment_distribution.h"

// Larger images take the same paths through OpenEXR and candela, only for longer: OpenEXR decodes every image it
// accepts in full, so images of millions of pixels (a few hundred bytes can claim them) kept the fuzzer at 10
// executions a second, and buffers beyond the sanitizer allocator's small sizes cost page faults on every run.
// 4096 pixels still hold several blocks of every compression (DWAB's 256 scanlines at 16 pixels wide). The
// header checks still run on every input.
constexpr uint64_t kMaxFuzzedPixels = uint64_t(1) << 12;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    candela::Texture t = candela::decodeExr("fuzz.exr", data, size, kMaxFuzzedPixels);
    std::vector<candela::Vec3> texels(size_t(t.width) * t.height);
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = {t.floats[3 * i], t.floats[3 * i + 1], t.floats[3 * i + 2]};
    candela::EnvironmentDistribution::build(texels, t.width, t.height);
  } catch (const candela::LoadError&) {
  }
  return 0;
}
