#include "scene/loaders/pbrt/pbrt_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <string>

#include "scene/scene_repair.h"

namespace candela {

namespace {

// pbrt's screen window: the image's rectangle in screen space (xmin, xmax, ymin, ymax). By default the shorter
// image axis spans [-1, 1] and the longer one keeps the frame's aspect ratio.
struct ScreenWindow {
  float xMin, xMax, yMin, yMax;
};

ScreenWindow screenWindowOf(const PbrtParameters& params, uint32_t width, uint32_t height) {
  const float frame = params.getFloat("frameaspectratio", float(width) / float(height));
  ScreenWindow w =
      frame > 1.0f ? ScreenWindow{-frame, frame, -1.0f, 1.0f} : ScreenWindow{-1.0f, 1.0f, -1.0f / frame, 1.0f / frame};
  if (params.find("screenwindow")) {
    const std::vector<double> sw = params.getNumbers("screenwindow");
    if (sw.size() != 4) params.fail("'screenwindow' needs 4 numbers: xmin xmax ymin ymax");
    w = {float(sw[0]), float(sw[1]), float(sw[2]), float(sw[3])};
  }
  if (!(std::isfinite(w.xMax - w.xMin) && std::isfinite(w.yMax - w.yMin) && w.xMax > w.xMin && w.yMax > w.yMin))
    params.fail("Camera 'screenwindow' (or 'frameaspectratio'): the window is empty or its size is not finite");
  return w;
}

}  // namespace

bool pbrtWorldNeedsMirror(const glm::mat4& cameraFromWorld) {
  return glm::determinant(glm::mat3(cameraFromWorld)) >= 0.0f;
}

CameraDescription makePbrtCamera(const std::string& type, const PbrtParameters& params,
                                 const glm::mat4& cameraFromWorld, const PbrtFilm& film, bool mirrorX,
                                 PbrtContext& context) {
  const bool orthographic = type == "orthographic";
  if (type != "perspective" && !orthographic)
    context.warn("camera " + type, "'" + type + "' cameras are drawn as perspective cameras of the same field of view");
  // In double: a camera placed far out would overflow the cofactors of a float inverse.
  const glm::mat4 worldFromCamera(glm::inverse(glm::dmat4(cameraFromWorld)));
  auto toCandela = [&](glm::vec4 v) { return Vec3{mirrorX ? -v.x : v.x, v.y, v.z}; };
  CameraDescription c;
  c.eye = toCandela(worldFromCamera * glm::vec4(0, 0, 0, 1));
  Vec3 forward = normalize(toCandela(worldFromCamera * glm::vec4(0, 0, 1, 0)));
  c.target = c.eye + forward;
  const Vec3 cameraUp = toCandela(worldFromCamera * glm::vec4(0, 1, 0, 0));
  c.up = normalize(cameraUp);

  // candela spans the image's height and takes the width from the image's aspect ratio; the window's centre
  // becomes the image shift, in units of its half height.
  const ScreenWindow full = screenWindowOf(params, film.fullWidth, film.fullHeight);
  // The crop window's part of it (pbrt's rows run down from the top, screen y up).
  const float columnWidth = (full.xMax - full.xMin) / float(film.fullWidth);
  const float rowHeight = (full.yMax - full.yMin) / float(film.fullHeight);
  const ScreenWindow window{full.xMin + columnWidth * float(film.cropX),
                            full.xMin + columnWidth * float(film.cropX + film.width),
                            full.yMax - rowHeight * float(film.cropY + film.height),
                            full.yMax - rowHeight * float(film.cropY)};
  const uint32_t width = film.width, height = film.height;
  const float halfHeight = 0.5f * (window.yMax - window.yMin);
  const float windowAspect = (window.xMax - window.xMin) / (window.yMax - window.yMin);
  if (std::fabs(windowAspect / (float(width) / float(height)) - 1.0f) > 0.01f)
    context.warn("camera aspect",
                 "the camera's screen window is not of the image's aspect ratio: candela keeps its "
                 "height and widens or narrows it to the image's");
  c.imageShift = {0.5f * (window.xMin + window.xMax) / halfHeight, 0.5f * (window.yMin + window.yMax) / halfHeight};

  if (orthographic) {
    // Screen space is camera space: the window is in the camera's units, scaled by its transform into the world.
    c.projection = Projection::Orthographic;
    c.orthographicHalfHeight = halfHeight * length(cameraUp);
  } else {
    // fov spans screen coordinates [-1, 1]: the shorter image axis of the default window.
    const float fov = params.getFloat("fov", 90.0f);
    if (!(fov > 0.0f && fov < 180.0f))
      params.fail("Camera 'fov' " + std::to_string(fov) + ": it must lie between 0 and 180 degrees");
    const float tanHalf = std::tan(0.5f * std::clamp(fov, 0.01f, 179.0f) * kPi / 180.0f) * halfHeight;
    c.verticalFovDegrees = std::clamp(2.0f * std::atan(tanHalf) * 180.0f / kPi, 0.01f, 179.0f);
  }
  // The limits the scene's repair holds every camera to (scene_repair.h), said here in pbrt's terms.
  const float limit = kMaxCameraCoordinate;
  auto within = [limit](float x) { return std::fabs(x) <= limit; };
  if (!within(c.imageShift.x) || !within(c.imageShift.y) || !std::isfinite(c.verticalFovDegrees) ||
      !(c.orthographicHalfHeight > 0.0f && c.orthographicHalfHeight <= limit))
    params.fail("Camera 'screenwindow': the window gives no field of view, or a size or shift beyond 1e9");
  const float lensRadius = params.getFloat("lensradius", 0.0f), focalDistance = params.getFloat("focaldistance", 1e6f);
  if (!(lensRadius >= 0.0f && lensRadius <= limit))
    params.fail("Camera 'lensradius' " + std::to_string(lensRadius) + ": it must lie between 0 and 1e9");
  if (!(focalDistance >= 0.0f && focalDistance <= limit))
    params.fail("Camera 'focaldistance' " + std::to_string(focalDistance) + ": it must lie between 0 and 1e9");
  c.apertureRadius = lensRadius;
  c.focusDistance = focalDistance;
  if (!isFinite(c.eye) || !isFinite(forward) || !isFinite(c.up))
    params.fail("Camera: the camera transform (the CTM at the Camera directive) is not invertible");
  if (!within(c.eye.x) || !within(c.eye.y) || !within(c.eye.z) || !within(c.target.x) || !within(c.target.y) ||
      !within(c.target.z))
    params.fail("Camera: the camera transform (the CTM at the Camera directive) places the camera beyond 1e9");
  return c;
}

}  // namespace candela
