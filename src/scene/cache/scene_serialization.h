#pragma once
#include "scene/cache/binary_stream.h"
#include "scene/scene.h"

namespace candela {

// The binary layout of a Scene in the scene cache: every field in order, arrays as a count and their bytes.
// Plain structs (Material, Instance, CameraDescription, Vec3...) are stored as their bytes, so a file is only
// for the build that wrote it (the cache key says which).
void writeScene(BinaryWriter& out, const Scene& scene);

// Reads what writeScene wrote. False when the bytes cannot be a scene: the reader ran out, or a count does not
// fit in what is left of the file.
bool readScene(BinaryReader& in, Scene& scene);

}  // namespace candela
