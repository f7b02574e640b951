// libFuzzer entry point for JPEG textures (decodeImage hands them to libjpeg-turbo); see
// texture_decoding_target.h.
#include "texture_decoding_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::fuzz::decodeTexture("fuzz.jpeg", data, size, candela::isJpeg);
  return 0;
}
