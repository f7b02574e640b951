#pragma once
// Ray cones (Akenine-Moller et al. 2021, "Improved Shader and Texture Level of Detail Using Ray Cones", JCGT
// 10(1)): the cone about a path's ray that one pixel spans, followed from the camera through mirror and smooth
// glass bounces, and the texture footprint it leaves on the surface it hits.
#include "kernel/camera.h"
#include "kernel/curve_attributes.h"
#include "kernel/hit.h"
#include "kernel/scene_view.h"
#include "kernel/texture_filtering.h"
#include "kernel/triangle_attributes.h"

namespace candela {

// A cone by its width where its ray starts and how fast it widens. A zero cone (the default) is a ray with
// no footprint: lookups along it read the finest level.
//
// Bounces: a delta bounce (mirror, smooth glass) keeps the spread and starts the next ray with the width the
// cone had at the hit, taking the surface as locally flat; a curved mirror widens the true footprint more, so
// its reflections are filtered less than they could be, never more. A diffuse or glossy bounce ends the cone:
// what such a path sees further on is spread over the lobe, no longer one pixel's footprint, and reading the
// finest level there keeps those lookups exactly as without filtering (the choice of the paper's path tracer
// variant that filters the first hits only).
struct RayCone {
  float width = 0.0f;   // at the ray's origin
  float spread = 0.0f;  // width gained per unit distance along the ray (radians)

  CANDELA_FN float widthAt(float t) const { return fabsf(width + spread * t); }
  // The cone of the ray that continues from a hit at distance t, after a delta bounce.
  CANDELA_FN RayCone afterDeltaBounce(float t) const { return {widthAt(t), spread}; }
};

// The cone of a camera ray: a pinhole's, one pixel across (the image plane at distance 1 is 2 |up| tall).
// A thin lens's rays start as such cones too; defocus itself comes from the lens samples.
CANDELA_FN RayCone cameraRayCone(const Camera& camera, uint32_t imageHeight) {
  return {0.0f, 2.0f * length(camera.up) / float(imageHeight > 0 ? imageHeight : 1)};
}

// The texture coordinates' change across the ellipse the cone of `width` (at the hit) cuts from the hit triangle's
// plane, along the ellipse's two axes (Akenine-Moller et al. 2021, section 4.2): the first axis lies along the
// ray's direction in the plane, stretched by 1/cos of the incidence, the second across it. Each axis is one cone
// width long as seen from the ray, as a rasteriser's derivatives span one pixel.
CANDELA_FN TextureFootprint textureFootprint(const SceneView& scene, const Hit& hit, Vec3 direction, float width,
                                             TextureFilter filter) {
  if (filter == TextureFilter::Finest || !(width > 0.0f) || isCurveHit(scene, hit)) return {};
  const HitTriangle tri = hitTriangle(scene, hit);
  if (!tri.mesh->hasUvs) return {};
  const Affine3x4& toWorld = tri.instance->objectToWorld;
  const Vec3 p0 = scene.positions[tri.v0];
  const Vec3 e1 = toWorld.vector(scene.positions[tri.v1] - p0), e2 = toWorld.vector(scene.positions[tri.v2] - p0);
  const Vec3 n = cross(e1, e2);
  const float n2 = dot(n, n);
  if (!(n2 > 0.0f)) return {};
  const Vec3 normal = n / sqrtf(n2);
  Vec3 along = direction - normal * dot(normal, direction);
  if (dot(along, along) < 1e-12f) along = e1;  // head-on: any direction in the plane
  along = normalize(along);
  const Vec3 across = cross(normal, along);
  // A unit vector in the plane seen from the ray: its part perpendicular to the ray is cos(incidence) long.
  const Vec3 seenAlong = along - direction * dot(direction, along);
  const Vec3 axis1 = along * (width / fmaxf(length(seenAlong), 1e-4f)), axis2 = across * width;

  const Vec2 uv0 = scene.uvs[tri.v0], uv1 = scene.uvs[tri.v1], uv2 = scene.uvs[tri.v2];
  const Vec2 d1{uv1.x - uv0.x, uv1.y - uv0.y}, d2{uv2.x - uv0.x, uv2.y - uv0.y};
  // A vector a in the plane is b1 e1 + b2 e2 with these barycentric coordinates; uv changes by b1 d1 + b2 d2.
  auto uvChange = [&](Vec3 a) {
    const float b1 = dot(n, cross(a, e2)) / n2, b2 = dot(n, cross(e1, a)) / n2;
    return Vec2{b1 * d1.x + b2 * d2.x, b1 * d1.y + b2 * d2.y};
  };
  return {uvChange(axis1), uvChange(axis2), filter};
}

}  // namespace candela
