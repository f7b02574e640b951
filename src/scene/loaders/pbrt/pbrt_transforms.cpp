#include "scene/loaders/pbrt/pbrt_transforms.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

namespace candela {

glm::mat4 pbrtTranslate(Vec3 d) { return glm::translate(glm::mat4(1.0f), glm::vec3(d.x, d.y, d.z)); }

glm::mat4 pbrtScale(Vec3 s) { return glm::scale(glm::mat4(1.0f), glm::vec3(s.x, s.y, s.z)); }

glm::mat4 pbrtRotate(float degrees, Vec3 axis) {
  glm::vec3 a(axis.x, axis.y, axis.z);
  float len = glm::length(a);
  if (!(len > 0.0f) || !std::isfinite(len)) return glm::mat4(1.0f);
  return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), a / len);
}

std::string pbrtRotateProblem(float degrees, Vec3 axis) {
  if (!std::isfinite(degrees)) return "the angle is not finite";
  const float len = glm::length(glm::vec3(axis.x, axis.y, axis.z));
  if (!(len > 0.0f) || !std::isfinite(len)) return "the axis has no direction (it is zero or not finite)";
  return {};
}

std::string pbrtLookAtProblem(Vec3 eyeIn, Vec3 lookIn, Vec3 upIn) {
  // In double, where the lengths of float vectors cannot overflow.
  const glm::dvec3 eye(eyeIn.x, eyeIn.y, eyeIn.z), look(lookIn.x, lookIn.y, lookIn.z), up(upIn.x, upIn.y, upIn.z);
  const glm::dvec3 dir = look - eye;
  if (!std::isfinite(glm::length(dir)) || !std::isfinite(glm::length(up)))
    return "a point or the up vector is not finite";
  if (!(glm::length(dir) > 0.0)) return "the eye and the point looked at are the same point";
  if (!(glm::length(glm::cross(glm::normalize(up), glm::normalize(dir))) > 1e-6))
    return "the up vector is zero or parallel to the view direction";
  return {};
}

glm::mat4 pbrtLookAt(Vec3 eyeIn, Vec3 lookIn, Vec3 upIn) {
  // In double, so that points far out (up to the largest float) neither overflow the lengths nor the inverse.
  const glm::dvec3 eye(eyeIn.x, eyeIn.y, eyeIn.z), look(lookIn.x, lookIn.y, lookIn.z), up(upIn.x, upIn.y, upIn.z);
  glm::dvec3 dir = look - eye;
  if (!(glm::length(dir) > 0.0) || !(glm::length(up) > 0.0)) return glm::mat4(1.0f);
  dir = glm::normalize(dir);
  glm::dvec3 right = glm::cross(glm::normalize(up), dir);
  if (!(glm::length(right) > 0.0)) return glm::mat4(1.0f);  // up parallel to the view direction
  right = glm::normalize(right);
  const glm::dvec3 newUp = glm::cross(dir, right);
  const glm::dmat4 worldFromCamera(glm::dvec4(right, 0), glm::dvec4(newUp, 0), glm::dvec4(dir, 0), glm::dvec4(eye, 1));
  return glm::mat4(glm::inverse(worldFromCamera));
}

glm::mat4 pbrtMatrix(const double* m) {
  glm::mat4 out;
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) out[column][row] = float(m[4 * column + row]);
  return out;
}

bool isFiniteMatrix(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

}  // namespace candela
