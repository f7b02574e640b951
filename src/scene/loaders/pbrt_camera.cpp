#include "scene/loaders/pbrt_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>

namespace candela {

bool pbrtWorldNeedsMirror(const glm::mat4& cameraFromWorld) {
  return glm::determinant(glm::mat3(cameraFromWorld)) >= 0.0f;
}

CameraDescription makePbrtCamera(const std::string& type, const PbrtParameters& params,
                                 const glm::mat4& cameraFromWorld, uint32_t width, uint32_t height, bool mirrorX,
                                 PbrtContext& context) {
  if (type != "perspective")
    context.warn("camera " + type, "'" + type + "' cameras are drawn as perspective cameras of the same field of view");
  glm::mat4 worldFromCamera = glm::inverse(cameraFromWorld);
  auto toCandela = [&](glm::vec4 v) { return Vec3{mirrorX ? -v.x : v.x, v.y, v.z}; };
  CameraDescription c;
  c.eye = toCandela(worldFromCamera * glm::vec4(0, 0, 0, 1));
  Vec3 forward = normalize(toCandela(worldFromCamera * glm::vec4(0, 0, 1, 0)));
  c.target = c.eye + forward;
  c.up = normalize(toCandela(worldFromCamera * glm::vec4(0, 1, 0, 0)));
  float fov = std::clamp(params.getFloat("fov", 90.0f), 0.01f, 179.0f);
  if (width < height)  // fov spans the shorter axis, here the horizontal one
    fov = 2.0f * std::atan(std::tan(0.5f * fov * kPi / 180.0f) * float(height) / float(width)) * 180.0f / kPi;
  c.verticalFovDegrees = std::clamp(fov, 0.01f, 179.0f);
  c.apertureRadius = std::max(0.0f, params.getFloat("lensradius", 0.0f));
  c.focusDistance = std::max(0.0f, params.getFloat("focaldistance", 1e6f));
  if (params.find("screenwindow") || params.find("frameaspectratio"))
    context.warn("camera screenwindow", "camera 'screenwindow' and 'frameaspectratio' are not applied");
  if (!isFinite(c.eye) || !isFinite(forward) || !isFinite(c.up)) params.fail("camera transform is not invertible");
  return c;
}

}  // namespace candela
