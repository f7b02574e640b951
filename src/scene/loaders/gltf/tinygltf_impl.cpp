// The tinygltf implementation from the system's header, compiled into candela so that the fuzzing and
// sanitizer builds instrument it too. Candela reads files and decodes images itself: tinygltf's own file access
// would expand paths through wordexp(3), and its images would bypass the loader's size limits.
#include <fstream>  // the header needs it but includes it only when it has file access

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_FS
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
