#pragma once
#include "core/math.h"
#include "core/sampling.h"

namespace candela {

// Pinhole camera, or a thin lens when `lensRadius` > 0. `right` and `up` are scaled so that pixel offsets in
// [-1, 1] span the image plane at distance 1 along `forward`. A thin lens keeps the plane at `focusDistance`
// along `forward` sharp.
struct Camera {
  Vec3 position{0, 0, 0};
  Vec3 forward{0, 0, 1};
  Vec3 right{1, 0, 0};
  Vec3 up{0, 1, 0};
  float lensRadius = 0.0f;
  float focusDistance = 1.0f;

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

  // Ray through the film point (px, py) in pixel units, (0, 0) the top-left corner; `uLens` picks the point on
  // the lens (unused by a pinhole).
  CANDELA_FN Ray generateRay(float px, float py, int width, int height, Vec2 uLens = {}) const {
    float sx = 2.0f * px / float(width) - 1.0f;
    float sy = 1.0f - 2.0f * py / float(height);
    Vec3 through = forward + right * sx + up * sy;
    if (lensRadius <= 0.0f) return {position, normalize(through), 0.0f, kInf};
    Vec2 lens = sampleUniformDiskConcentric(uLens);
    Vec3 origin = position + (normalize(right) * lens.x + normalize(up) * lens.y) * lensRadius;
    Vec3 focus = position + through * focusDistance;
    return {origin, normalize(focus - origin), 0.0f, kInf};
  }
};

}  // namespace candela
