#pragma once
#include <embree3/rtcore.h>

#include <cstddef>
#include <string>

namespace candela {

// The scene's size as Embree's BVHs see it, for a message about building them.
struct EmbreeSceneSize {
  size_t meshes = 0, triangles = 0, instances = 0;
};

// One sentence for an Embree error while `what` ("building a mesh BVH"): running out of memory is said so, with
// the scene's size; the other errors by their names.
std::string embreeFailure(RTCError error, const std::string& what, const EmbreeSceneSize& size);

}  // namespace candela
