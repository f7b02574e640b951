#pragma once
#include <string>

#include "scene/loaders/obj/obj_geometry_reader.h"
#include "scene/scene.h"

namespace candela {

// Makes one mesh of OBJ geometry. Corners with the same position, texture coordinate and normal share a vertex.
// A triangle takes normals from the file only when all three corners have one; others get generated ones
// (normal_generation.h). v is flipped to the Mesh convention (0 at the top of the image); normals are made unit
// length (zero ones stay zero: the kernel then shades with the geometric normal); kObjNoMaterial becomes
// `defaultMaterial`. The geometry's arrays are consumed as they are used, to keep the peak memory low.
Mesh buildObjMesh(std::string name, ObjGeometry&& geometry, uint32_t defaultMaterial);

}  // namespace candela
