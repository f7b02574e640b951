#pragma once
#include "scene/scene.h"

namespace candela {

// Checks every field a scene cache file carries, the way loaded scenes are checked: validateScene's invariants
// (index ranges, material and texture ids, finite positions), and further every number finite, every enum in
// range, texture and environment sizes that agree with their arrays (with no overflow), one name per material,
// a camera that can be built, render hints in the ranges a scene file accepts, and an animation that
// validateAnimation accepts. A file passes the checksum
// whenever its writer computed one, so a hand-built or foreign cache file is only as trustworthy as this.
// Throws std::runtime_error naming the first problem.
void validateCachedScene(const Scene& scene);

}  // namespace candela
