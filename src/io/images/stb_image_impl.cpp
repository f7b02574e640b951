// The stb_image implementation, compiled once for the whole program (and instrumented in sanitizer and fuzzing
// builds). The loaders read files themselves, so that their errors name the file, and give stb memory.
// decodeImage gives stb only TGA, BMP and Radiance HDR: PNG goes to libpng and JPEG to libjpeg-turbo, whose
// handling of hostile files is better tested. PNG stays compiled in for the tests that read back written images.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#define STBI_ONLY_PNG
#define STBI_ONLY_HDR
#define STBI_ONLY_TGA
#define STBI_ONLY_BMP
#include <stb/stb_image.h>
