#include <gtest/gtest.h>

#include <cmath>

#include "kernel/integrator.h"

namespace candela {
namespace {

// Counts the queries the integrator makes; nothing is ever hit.
struct CountingTracer {
  mutable int queries = 0;
  bool intersect(const Ray&, Hit&, uint32_t) const { return ++queries, false; }
  bool occluded(const Ray&, uint32_t) const { return ++queries, false; }
};

RenderSettings tinySettings() {
  RenderSettings s;
  s.width = 4;
  s.height = 4;
  return s;
}

TEST(CameraRayGuard, UntraceableCameraRaysAreDroppedAsInvalidSamplesWithoutTracing) {
  const SceneView scene{};
  const float nan = std::nanf("");
  Camera farAway, notFinite, noDirection, thinLensOverflow;
  farAway.position = {3e38f, 0, 0};
  notFinite.position = {0, nan, 0};
  noDirection.forward = noDirection.right = noDirection.up = {0, 0, 0};
  thinLensOverflow.lensRadius = 3e38f;
  thinLensOverflow.focusDistance = 3e38f;
  for (const Camera& camera : {farAway, notFinite, noDirection, thinLensOverflow}) {
    CountingTracer tracer;
    PathResult r = renderPixelSample(scene, tracer, camera, tinySettings(), 1, 2, 0);
    EXPECT_EQ(tracer.queries, 0);
    EXPECT_EQ(r.rays, 0u);
    EXPECT_FALSE(isValidSample(r.radiance));
  }
}

TEST(CameraRayGuard, OrdinaryCameraRaysAreTraced) {
  const SceneView scene{};
  Camera camera = Camera::lookAt({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 40.0f, 1.0f);
  camera.lensRadius = 0.1f;
  CountingTracer tracer;
  PathResult r = renderPixelSample(scene, tracer, camera, tinySettings(), 1, 2, 0);
  EXPECT_EQ(tracer.queries, 1);
  EXPECT_TRUE(isValidSample(r.radiance));
}

}  // namespace
}  // namespace candela
