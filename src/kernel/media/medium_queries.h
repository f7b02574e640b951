#pragma once
// What the path loop asks of the medium a ray is in, for either kind: homogeneous media answer exactly
// (medium.h, distance_sampling.h), grid media by tracking against their majorants (grid_tracking.h).
#include "kernel/media/grid_tracking.h"
#include "kernel/scene_view.h"

namespace candela {

// Where the ray in `medium` whose segment ends at tMax first collides, from the segment's two numbers u.
CANDELA_FN MediumStep sampleMediumCollision(const SceneView& scene, uint32_t medium, const Ray& ray, float tMax,
                                            Vec2 u) {
  const Medium& m = scene.media[medium];
  if (m.grid == kHomogeneous) return sampleMediumDistance(m, tMax, u.x, u.y);
  return sampleGridMediumDistance(m, scene.mediumGrids[m.grid], scene.mediumGridValues, ray, tMax, u.x, u.y);
}

// The transmittance of `medium` along the ray from 0 to `length`: exact where homogeneous, an unbiased estimate
// where a grid.
CANDELA_FN Vec3 mediumSegmentTransmittance(const SceneView& scene, uint32_t medium, const Ray& ray, float length) {
  const Medium& m = scene.media[medium];
  if (m.grid == kHomogeneous) return mediumTransmittance(m, length);
  return gridMediumTransmittance(m, scene.mediumGrids[m.grid], scene.mediumGridValues, ray, length);
}

// The coefficients of `medium` at world point p.
CANDELA_FN MediumPoint mediumAt(const SceneView& scene, uint32_t medium, Vec3 p) {
  const Medium& m = scene.media[medium];
  if (m.grid == kHomogeneous) return {m.sigmaA, m.sigmaS, m.emission};
  return gridMediumAt(m, scene.mediumGrids[m.grid], scene.mediumGridValues, p);
}

}  // namespace candela
