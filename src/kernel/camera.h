#pragma once
#include "core/math.h"
#include "core/sampling.h"

namespace candela {

// The largest coordinate a camera ray may start at. Scene loading keeps cameras far inside it; the bound is what
// the ray tracers accept (Embree refuses rays beyond about 1.8e18, and its checked builds abort on them).
constexpr float kMaxCameraRayOrigin = 1e18f;

// Whether a ray from Camera::generateRay can be traced: a finite origin within kMaxCameraRayOrigin and a finite,
// non-zero direction. Written as comparisons that NaN fails.
CANDELA_FN bool isTraceableCameraRay(const Ray& ray) {
  const Vec3 o = ray.origin, d = ray.direction;
  return fabsf(o.x) <= kMaxCameraRayOrigin && fabsf(o.y) <= kMaxCameraRayOrigin && fabsf(o.z) <= kMaxCameraRayOrigin &&
         fabsf(d.x) <= 2.0f && fabsf(d.y) <= 2.0f && fabsf(d.z) <= 2.0f && dot(d, d) > 0.5f;
}

// Pinhole camera, or a thin lens when `lensRadius` > 0. `right` and `up` are scaled so that pixel offsets in
// [-1, 1] span the image plane at distance 1 along `forward` (which reaches the image's centre: off the view axis
// when the image is shifted). A thin lens keeps the plane at `focusDistance` along the view axis sharp.
// An orthographic camera sends parallel rays along `forward` from the image rectangle centred on `position` and
// spanned by `right` and `up` (in world units); its thin lens focuses the plane `focusDistance` ahead.
struct Camera {
  Vec3 position{0, 0, 0};
  Vec3 forward{0, 0, 1};
  Vec3 right{1, 0, 0};
  Vec3 up{0, 1, 0};
  float lensRadius = 0.0f;
  float focusDistance = 1.0f;
  bool orthographic = false;

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
    if (orthographic) return orthographicRay(position + right * sx + up * sy, uLens);
    Vec3 through = forward + right * sx + up * sy;
    if (lensRadius <= 0.0f) return {position, normalize(through), 0.0f, kInf};
    Vec2 lens = sampleUniformDiskConcentric(uLens);
    Vec3 origin = position + (normalize(right) * lens.x + normalize(up) * lens.y) * lensRadius;
    Vec3 focus = position + through * focusDistance;
    return {origin, normalize(focus - origin), 0.0f, kInf};
  }

 private:
  CANDELA_FN Ray orthographicRay(Vec3 onImage, Vec2 uLens) const {
    const Vec3 direction = normalize(forward);
    if (lensRadius <= 0.0f) return {onImage, direction, 0.0f, kInf};
    Vec2 lens = sampleUniformDiskConcentric(uLens);
    Vec3 origin = onImage + (normalize(right) * lens.x + normalize(up) * lens.y) * lensRadius;
    Vec3 focus = onImage + direction * focusDistance;
    return {origin, normalize(focus - origin), 0.0f, kInf};
  }
};

}  // namespace candela
