#pragma once
#include "core/math.h"

namespace candela {

// Pinhole camera. `right` and `up` are scaled so that pixel offsets in [-1, 1] span the image plane at
// distance 1 along `forward`.
struct Camera {
  Vec3 position{0, 0, 0};
  Vec3 forward{0, 0, 1};
  Vec3 right{1, 0, 0};
  Vec3 up{0, 1, 0};

  CANDELA_FN static Camera lookAt(Vec3 eye, Vec3 target, Vec3 worldUp, float verticalFovDegrees, float aspect) {
    Camera c;
    c.position = eye;
    c.forward = normalize(target - eye);
    Vec3 r = normalize(cross(c.forward, worldUp));
    Vec3 u = cross(r, c.forward);
    float tanHalf = tanf(0.5f * verticalFovDegrees * kPi / 180.0f);
    c.right = r * (tanHalf * aspect);
    c.up = u * tanHalf;
    return c;
  }

  // Ray through the film point (px, py) in pixel units, (0, 0) the top-left corner.
  CANDELA_FN Ray generateRay(float px, float py, int width, int height) const {
    float sx = 2.0f * px / float(width) - 1.0f;
    float sy = 1.0f - 2.0f * py / float(height);
    return {position, normalize(forward + right * sx + up * sy), 0.0f, kInf};
  }
};

}  // namespace candela
