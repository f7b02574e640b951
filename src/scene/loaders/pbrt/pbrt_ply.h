#pragma once
#include <string>

#include "scene/scene.h"

namespace candela {

// Reads a PLY mesh as pbrt's `plymesh` shape names it: ASCII or binary (either byte order), gzip-compressed when
// the name ends in ".gz". Vertex positions, normals (nx ny nz) and texture coordinates (u v, s t, texture_u
// texture_v or texture_s texture_t, as in the file: pbrt's v runs up the image) are kept; faces of 3 or 4
// vertices become triangles. The file is opened as InputFile does (file_bytes.h); a malformed file, an index
// out of range or a face of another size throws LoadError naming it.
Mesh readPlyMesh(const std::string& path);

}  // namespace candela
