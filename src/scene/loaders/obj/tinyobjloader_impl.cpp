// The tinyobjloader implementation from the system's header, compiled into candela so that the fuzzing and
// sanitizer builds instrument it too.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
