// The stb_image implementation, compiled once for the whole program. Files are read by the loaders, so that
// their errors name the file; stb only decodes memory.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
