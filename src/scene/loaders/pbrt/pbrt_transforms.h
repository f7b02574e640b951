#pragma once
#include <glm/mat4x4.hpp>
#include <string>

#include "core/math.h"

namespace candela {

// The transforms of pbrt's directives, as pbrt-v4 builds them (each is post-multiplied onto the current one).
glm::mat4 pbrtTranslate(Vec3 d);
glm::mat4 pbrtScale(Vec3 s);
glm::mat4 pbrtRotate(float degrees, Vec3 axis);
// Camera-from-world of `LookAt eye look up` (pbrt's left-handed frame: +x to the right of the image).
glm::mat4 pbrtLookAt(Vec3 eye, Vec3 look, Vec3 up);
// Why `Rotate degrees axis` or `LookAt eye look up` has no transform, or "" when it has one (the functions above
// give the identity then).
std::string pbrtRotateProblem(float degrees, Vec3 axis);
std::string pbrtLookAtProblem(Vec3 eye, Vec3 look, Vec3 up);
// The 16 numbers of `Transform` / `ConcatTransform`, which pbrt writes column by column.
glm::mat4 pbrtMatrix(const double* sixteen);

bool isFiniteMatrix(const glm::mat4& m);

}  // namespace candela
