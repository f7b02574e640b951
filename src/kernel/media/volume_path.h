#pragma once
// The path loop of scenes with participating media (pbrt-v4's VolPathIntegrator): the loop of kernel/integrator.h
// with the medium each ray travels in. Scenes without media never compile it (tracePath's kWithMedia), so their
// paths stay as they were.
//
// A ray in a medium first samples where it collides (medium_queries.h: exactly in a homogeneous medium, by delta
// tracking in a grid). A collision before the surface the ray found adds the medium's emission and scatters there:
// next-event estimation with the phase function, MIS against phase sampling, then a direction from the phase
// function. Otherwise the ray reaches the surface, whose vertex is a surface vertex as elsewhere (shadeVertex,
// continuePath), except that its shadow ray is attenuated by the media it crosses. Rays cross `interface` surfaces
// unchanged, into the medium on the far side; a direction leaving any surface travels in the medium on its side
// of the surface's MediumInterface, or stays in the ray's medium where the surface bounds none.
//
// The numbers a path draws: in a medium, 2 for the collision (channel and distance; a grid's tracking seeds its
// own numbers with them) before anything else at each segment; at a collision the light (1D, 2D), the shadow
// ray's pass-through bits (cut-out scenes, only where it carries light), the phase direction (2D), Russian
// roulette (1D) and the next ray's bits (cut-out scenes); at a step of a subsurface walk only the phase direction
// and the next ray's bits. Rays outside media draw as in scenes without media.
#include "kernel/media/henyey_greenstein.h"
#include "kernel/media/medium_queries.h"
#include "kernel/media/subsurface_walk.h"
#include "kernel/path_vertex.h"

namespace candela {

// A ray whose origin moves across this many interfaces in a row without any scattering is abandoned: only
// degenerate geometry (interfaces stacked on one another) makes a real path do so.
constexpr uint32_t kMaxInterfaceCrossings = 256;

// The medium a ray leaving the surface of `instanceId` (geometric normal `normal`) along `direction` travels in:
// the interface's side, or `current` where the surface bounds no medium.
CANDELA_FN uint32_t mediumBeyond(const SceneView& scene, uint32_t instanceId, Vec3 normal, Vec3 direction,
                                 uint32_t current) {
  const MediumInterface& media = scene.instances[instanceId].media;
  if (media.inside == media.outside) return current;
  return dot(direction, normal) > 0.0f ? media.outside : media.inside;
}

// Whether `hit` is on an interface surface, which only bounds media.
CANDELA_FN bool hitsInterface(const SceneView& scene, const Hit& hit) {
  return scene.materials[hitMaterial(scene, hit)].interfaceOnly != 0;
}

// The fraction of light that travels along the shadow ray `ray` (pass-through bits `bits`), which starts in
// `medium`: the media's transmittance over each piece between interfaces (exact in a homogeneous medium, ratio
// tracking in a grid), 0 where any other surface blocks it. Adds the rays traced after the first to `rays`.
template <class Tracer>
CANDELA_FN Vec3 shadowTransmittance(const SceneView& scene, const Tracer& tracer, Ray ray, uint32_t bits,
                                    uint32_t medium, uint32_t& rays) {
  Vec3 transmittance{1, 1, 1};
  for (uint32_t crossings = 0; crossings <= kMaxInterfaceCrossings; ++crossings) {
    if (crossings > 0) ++rays;
    Hit hit;
    const bool found = tracer.intersect(ray, hit, bits);
    if (found && !hitsInterface(scene, hit)) return {};
    const float length = found ? hit.t : ray.tMax;
    if (medium != kNoMedium) transmittance *= mediumSegmentTransmittance(scene, medium, ray, length);
    if (!found || isBlack(transmittance)) return transmittance;
    const SurfaceInteraction si = makeInteraction(scene, hit, ray);
    medium = mediumBeyond(scene, hit.instanceId, si.geometricNormal, ray.direction, medium);
    const float left = ray.tMax - hit.t;
    ray = {offsetRayOrigin(si.position, si.geometricNormal, ray.direction), ray.direction, 0.0f, left};
  }
  return {};
}

// A collision at `p` in medium `medium` (the ray arrived along -wo): next-event estimation with the phase function
// and a direction sampled from it, into `ray` (with pass-through bits `bits`). Returns false where the path ends
// here: at the maximum depth, or by Russian roulette. In a subsurface medium it is one step of a random walk
// (subsurface_walk.h), counted in `walkSteps`.
template <bool kWithAovs, class Tracer>
CANDELA_FN bool scatterInMedium(const SceneView& scene, const Tracer& tracer, const RenderSettings& settings,
                                PathState& s, PathAovState& a, PathSampler& sampler, uint32_t medium, Vec3 p, Vec3 wo,
                                Ray& ray, uint32_t& bits, uint32_t& walkSteps) {
  const bool walk = isSubsurfaceWalk(scene.media[medium]);
  if (walk) {
    if (++walkSteps > kMaxSubsurfaceSteps) return false;
    const PhaseSample phase = sampleHenyeyGreenstein(wo, scene.media[medium].g, sampler.next2D());
    s.bsdfPdf = phase.pdf;
    s.lastScatter = p;
    s.lastNormal = {};
    s.bounceFlags = kDeltaBounce;  // no light was sampled here: emission the walk finds takes its full weight
    s.cone = RayCone{};
    if (kWithAovs) a.cameraChain = false;
    ray = {p, phase.wi, 0.0f, kInf};
    ++s.rays;
    bits = passThroughBits(scene, sampler);
    return true;
  }
  if (s.depth >= settings.maxDepth) return false;
  const float g = scene.media[medium].g;
  const float uSelect = sampler.next1D();
  const Vec2 uLight = sampler.next2D();
  const LightSample ls = sampleLight(scene, settings.lightSampler, {p, Vec3{}}, uSelect, uLight);
  if (ls.valid) {
    const float phase = henyeyGreensteinPdf(wo, ls.wi, g);
    const Vec3 le = ls.isDelta || ls.distance >= kInf ? ls.radiance : texturedLightRadiance(scene, ls);
    const float w = ls.isDelta ? 1.0f : powerHeuristic(ls.pdf, phase);
    const Vec3 contribution = s.beta * le * (phase * w / ls.pdf);
    if (!isBlack(contribution)) {
      ++s.rays;
      const uint32_t shadowBits = passThroughBits(scene, sampler);
      const Ray shadow{p, ls.wi, 0.0f, ls.distance >= kInf ? kInf : ls.distance * (1.0f - 1e-4f)};
      s.radiance += contribution * shadowTransmittance(scene, tracer, shadow, shadowBits, medium, s.rays);
    }
  }
  // Sampled exactly: the phase function over its density is 1, and beta stays.
  const PhaseSample phase = sampleHenyeyGreenstein(wo, g, sampler.next2D());
  s.bsdfPdf = phase.pdf;
  s.lastScatter = p;
  s.lastNormal = {};  // the light sampler's context of a point in a medium has no normal
  s.bounceFlags = 0;
  s.cone = RayCone{};
  if (kWithAovs) a.cameraChain = false;
  ray = {p, phase.wi, 0.0f, kInf};
  ++s.depth;
  const float uRoulette = sampler.next1D();
  if (s.depth >= settings.rouletteDepth) {
    const float survive = fminf(0.95f, maxComponent(s.beta) * s.etaScale);
    if (uRoulette >= survive) return false;
    s.beta = s.beta / survive;
  }
  ++s.rays;
  bits = passThroughBits(scene, sampler);
  return true;
}

// followPath (kernel/integrator.h) for scenes with media: the rest of the path from `ray`, which travels in
// `medium`.
template <bool kWithAovs, class Tracer>
CANDELA_FN void followPathInMedia(const SceneView& scene, const Tracer& tracer, const RenderSettings& settings,
                                  PathState& s, PathAovState& a, PathSampler& sampler, Ray ray, uint32_t bits,
                                  uint32_t medium) {
  uint32_t crossings = 0;
  uint32_t walkSteps = 0;  // collisions since the path last left a surface (subsurface_walk.h)
  for (;;) {
    Hit hit;
    const bool found = tracer.intersect(ray, hit, bits);
    if (medium != kNoMedium) {
      const MediumStep step = sampleMediumCollision(scene, medium, ray, found ? hit.t : kInf, sampler.next2D());
      if (step.scattered) {
        s.radiance += s.beta * step.emission;
        if (kWithAovs && a.aovsPending) {
          const MediumPoint m = mediumAt(scene, medium, ray.origin + ray.direction * step.t);
          const Vec3 sigmaT = m.sigmaA + m.sigmaS;
          a.aovs.albedo = s.beta * Vec3{sigmaT.x > 0.0f ? m.sigmaS.x / sigmaT.x : 0.0f,
                                        sigmaT.y > 0.0f ? m.sigmaS.y / sigmaT.y : 0.0f,
                                        sigmaT.z > 0.0f ? m.sigmaS.z / sigmaT.z : 0.0f};
          a.aovs.normal = -ray.direction;
          a.aovs.depth = a.pathLength + step.t;
          a.aovsPending = false;
        }
        s.beta *= step.weight;
        if (isBlack(s.beta)) return;
        crossings = 0;
        const Vec3 p = ray.origin + ray.direction * step.t;
        if (!scatterInMedium<kWithAovs>(scene, tracer, settings, s, a, sampler, medium, p, -ray.direction, ray, bits,
                                        walkSteps))
          return;
        continue;
      }
      s.beta *= step.weight;
      if (isBlack(s.beta)) return;
    }
    if (found && hitsInterface(scene, hit)) {
      if (++crossings > kMaxInterfaceCrossings) return;
      const SurfaceInteraction si = makeInteraction(scene, hit, ray);
      medium = mediumBeyond(scene, hit.instanceId, si.geometricNormal, ray.direction, medium);
      if (kWithAovs && a.aovsPending) a.pathLength += hit.t;
      s.cone = s.cone.afterDeltaBounce(hit.t);
      ray = {offsetRayOrigin(si.position, si.geometricNormal, ray.direction), ray.direction, 0.0f, kInf};
      ++s.rays;
      continue;
    }
    crossings = 0;
    ShadowQuery shadow;
    VertexScatter scatter;
    if (!shadeVertex<kWithAovs>(scene, settings, s, a, sampler, ray, found, hit, shadow, scatter)) return;
    if (!isBlack(shadow.contribution)) {
      const uint32_t shadowMedium =
          mediumBeyond(scene, hit.instanceId, scatter.geometricNormal, shadow.ray.direction, medium);
      s.radiance +=
          shadow.contribution * shadowTransmittance(scene, tracer, shadow.ray, shadow.bits, shadowMedium, s.rays);
    }
    if (!continuePath<kWithAovs>(scene, settings, s, a, sampler, scatter, ray, bits)) return;
    walkSteps = 0;
    medium = mediumBeyond(scene, hit.instanceId, scatter.geometricNormal, ray.direction, medium);
  }
}

}  // namespace candela
