#pragma once
#include "kernel/camera.h"
#include "kernel/media/volume_path.h"
#include "kernel/path_vertex.h"

namespace candela {

struct PathResult {
  Vec3 radiance;
  // The part of `radiance` that the camera sees emitted: by the first surface the path hits, by the environment it
  // escapes to at once, or by either at the end of a chain of mirrors and smooth glass from the camera. It is no
  // reflected light, so the denoisers keep it out of what they demodulate by the albedo and smooth. Only the
  // kWithAovs instantiations, whose films the denoisers read, record it.
  Vec3 emitted;
  uint32_t rays = 0;  // camera, bounce and shadow rays traced for this path
  PathAovs aovs;      // filled only by the kWithAovs instantiations
};

// The rest of a path, vertex by vertex (kernel/path_vertex.h) until it ends, from `ray` (with pass-through bits
// `bits`) on, with `s`, `a` and `sampler` as the path left them. With kTraced the ray has been traced already:
// `found` tells whether it found `hit`. (Without, the loop is the one tracePath always ran: the template
// parameter keeps the one-thread schedule's compiled code as it was.)
template <bool kWithAovs, bool kTraced, class Tracer>
CANDELA_FN_ALWAYS_INLINE void followPath(const SceneView& scene, const Tracer& tracer, const RenderSettings& settings,
                                         PathState& s, PathAovState& a, PathSampler& sampler, Ray ray, uint32_t bits,
                                         bool found = false, Hit hit = {}) {
  for (bool first = true;; first = false) {
    if (!kTraced || !first) {
      hit = Hit{};
      found = tracer.intersect(ray, hit, bits);
    }
    ShadowQuery shadow;
    VertexScatter scatter;
    if (!shadeVertex<kWithAovs>(scene, settings, s, a, sampler, ray, found, hit, shadow, scatter)) return;
    if (!isBlack(shadow.contribution) && !tracer.occluded(shadow.ray, shadow.bits)) s.radiance += shadow.contribution;
    if (!continuePath<kWithAovs>(scene, settings, s, a, sampler, scatter, ray, bits)) return;
  }
}

// Unidirectional path tracing with next-event estimation and BSDF sampling combined by MIS (power heuristic),
// Russian roulette after `rouletteDepth` bounces, one vertex at a time (kernel/path_vertex.h). `Tracer` answers
// the two ray queries:
//   bool intersect(const Ray&, Hit&, uint32_t randomBits) const;  bool occluded(const Ray&, uint32_t randomBits) const;
// Both look through cut-outs: a hit that passesThrough (kernel/pass_through.h) allows through, with these random
// bits, is no hit. Rays that refract continue on the far side of the surface.
// With kWithAovs the path also records PathAovs at its first non-specular vertex; without, that code is not
// compiled in, so paths that do not need the guides pay nothing for them.
// `cone` is the pixel's footprint about `ray`; textures are filtered over it as long as the path follows it
// through delta bounces (kernel/ray_cone.h). A zero cone reads the finest texture level everywhere.
// With kWithMedia the path follows the participating media the camera and the instances' interfaces put its rays
// in (kernel/media/volume_path.h); scenes without media (SceneView::mediumCount 0) are rendered without, so that
// they do not compile that code.
template <bool kWithAovs = false, bool kWithMedia = false, class Tracer>
CANDELA_HD PathResult tracePath(const SceneView& scene, const Tracer& tracer, Ray ray, PathSampler& sampler,
                                const RenderSettings& settings, RayCone cone = {}) {
  PathState s = startPath(cone);
  PathAovState a;
  if constexpr (kWithMedia)
    followPathInMedia<kWithAovs>(scene, tracer, settings, s, a, sampler, ray, passThroughBits(scene, sampler),
                                 scene.cameraMedium);
  else
    followPath<kWithAovs, false>(scene, tracer, settings, s, a, sampler, ray, passThroughBits(scene, sampler));
  PathResult result;
  result.radiance = s.radiance;
  result.rays = s.rays;
  if (kWithAovs) {
    result.emitted = a.emitted;
    result.aovs = a.aovs;
  }
  return result;
}

// NaN, infinite or negative estimates come from numerical failures; they are dropped, never accumulated.
CANDELA_FN bool isValidSample(Vec3 l) { return isFinite(l) && l.x >= 0.0f && l.y >= 0.0f && l.z >= 0.0f; }

// The camera ray of a sample of pixel (x, y): jittered within the pixel, through the lens where there is one. Draws
// the sample's first dimensions from `sampler`, the pixel's.
CANDELA_FN Ray pixelSampleRay(const Camera& camera, const RenderSettings& settings, uint32_t x, uint32_t y,
                              PathSampler& sampler) {
  Vec2 jitter = sampler.next2D();
  Vec2 uLens;
  if (camera.lensRadius > 0.0f) uLens = sampler.next2D();
  return camera.generateRay(float(x) + jitter.x, float(y) + jitter.y, int(settings.width), int(settings.height), uLens);
}

// The sample of a camera ray that cannot be traced (isTraceableCameraRay): a negative estimate, which
// isValidSample drops and the film counts.
CANDELA_FN PathResult droppedSample() {
  PathResult dropped;
  dropped.radiance = {-1.0f, -1.0f, -1.0f};
  return dropped;
}

// One sample of pixel (x, y): a jittered camera ray, then the path.
template <bool kWithAovs = false, bool kWithMedia = false, class Tracer>
CANDELA_HD PathResult renderPixelSample(const SceneView& scene, const Tracer& tracer, const Camera& camera,
                                        const RenderSettings& settings, uint32_t x, uint32_t y, uint32_t sampleIndex) {
  PathSampler sampler(y * settings.width + x, sampleIndex, settings.seed, settings.sampler);
  const Ray ray = pixelSampleRay(camera, settings, x, y, sampler);
  if (!isTraceableCameraRay(ray)) return droppedSample();
  return tracePath<kWithAovs, kWithMedia>(scene, tracer, ray, sampler, settings,
                                          cameraRayCone(camera, settings.height));
}

}  // namespace candela
