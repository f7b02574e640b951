// libFuzzer entry point for PNG textures (decodeImage hands them to libpng); see
// texture_decoding_target.h.
#include "texture_decoding_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::fuzz::decodeTexture("fuzz.png", data, size, candela::isPng);
  return 0;
}
