// The stb_image implementation, compiled once for the whole program (and instrumented in sanitizer and fuzzing
// builds). The loaders read files themselves, so that their errors name the file, and give stb memory.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
