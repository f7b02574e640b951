#include "scene/transform.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace candela {

Affine3x4 toAffine(const glm::mat4& m) {
  Affine3x4 a;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) a.m[row * 4 + col] = m[col][row];  // glm is column-major
  return a;
}

glm::mat4 toMat4(const Affine3x4& a) {
  glm::mat4 m(1.0f);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) m[col][row] = a.m[row * 4 + col];
  return m;
}

Affine3x4 normalTransform(const Affine3x4& objectToWorld) {
  glm::mat3 linear(toMat4(objectToWorld));
  return toAffine(glm::mat4(glm::transpose(glm::inverse(linear))));
}

}  // namespace candela
