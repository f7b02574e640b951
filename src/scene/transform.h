#pragma once
#include <glm/mat4x4.hpp>

#include "core/math.h"

namespace candela {

Affine3x4 toAffine(const glm::mat4& m);
glm::mat4 toMat4(const Affine3x4& a);
// Inverse transpose of the linear part, for transforming normals; no translation.
Affine3x4 normalTransform(const Affine3x4& objectToWorld);

}  // namespace candela
