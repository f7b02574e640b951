#pragma once
#include "core/path_sampler.h"
#include "kernel/aovs.h"
#include "kernel/bsdf/bsdf.h"
#include "kernel/camera.h"
#include "kernel/interaction.h"
#include "kernel/lights.h"
#include "kernel/pass_through.h"
#include "kernel/ray_cone.h"
#include "kernel/render_settings.h"
#include "kernel/shading_normal.h"
#include "kernel/textured_material.h"
#include "kernel/volume_absorption.h"

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

// Radiance a sampled light point emits, with the emission texture of its material applied.
CANDELA_FN Vec3 texturedLightRadiance(const SceneView& scene, const LightSample& ls) {
  const LightTriangle& light = scene.lights[ls.lightIndex];
  Hit hit;
  hit.b1 = ls.barycentrics.x;
  hit.b2 = ls.barycentrics.y;
  hit.instanceId = light.instanceId;
  hit.primitiveId = light.primitiveId;
  const HitTriangle tri = hitTriangle(scene, hit);
  const Material& m = scene.materials[scene.triangleMaterials[tri.triangle]];
  if (m.emissionTexture == kNoTexture) return ls.radiance;
  const Vec2 uv = tri.mesh->hasUvs ? interpolate(scene.uvs, tri) : Vec2{};
  Vec4 c = lookup(scene, m.emissionTexture, uv);
  return ls.radiance * Vec3{c.x, c.y, c.z};
}

// Unidirectional path tracing with next-event estimation and BSDF sampling combined by MIS (power heuristic),
// Russian roulette after `rouletteDepth` bounces. `Tracer` answers the two ray queries:
//   bool intersect(const Ray&, Hit&, uint32_t randomBits) const;  bool occluded(const Ray&, uint32_t randomBits) const;
// Both look through cut-outs: a hit that passesThrough (kernel/pass_through.h) allows through, with these random
// bits, is no hit.
// Delta lobes (mirror, smooth glass) skip light sampling and take the emission they hit at full weight; rays
// that refract continue on the far side of the surface.
// With kWithAovs the path also records PathAovs at its first non-specular vertex; without, that code is not
// compiled in, so paths that do not need the guides pay nothing for them.
// `cone` is the pixel's footprint about `ray`; textures are filtered over it as long as the path follows it
// through delta bounces (kernel/ray_cone.h). A zero cone reads the finest texture level everywhere.
template <bool kWithAovs = false, class Tracer>
CANDELA_HD PathResult tracePath(const SceneView& scene, const Tracer& tracer, Ray ray, PathSampler& sampler,
                                const RenderSettings& settings, RayCone cone = {}) {
  PathResult result;
  Vec3 beta{1, 1, 1};
  float etaScale = 1.0f;  // product of eta^2 over refractions: undoes their radiance scaling for roulette
  bool specularBounce = false;
  bool cameraChain = true;        // every bounce so far was off a delta lobe: emission found now is seen directly
  float bsdfPdf = 0.0f;           // solid-angle pdf of the BSDF sample that produced `ray`
  Vec3 lastScatter = ray.origin;  // where that sample was taken
  Vec3 lastNormal;                // and the shading normal there, for the light sampler's density
  bool aovsPending = kWithAovs;
  float pathLength = 0.0f;  // camera to the current hit, summed while the AOVs are pending
  // Random bits for a ray query's pass-through decisions; scenes without cut-outs never ask for them.
  auto queryBits = [&] { return scene.hasCutouts ? sampler.nextBits() : 0u; };
  for (uint32_t depth = 0;;) {
    Hit hit;
    ++result.rays;
    if (!tracer.intersect(ray, hit, queryBits())) {
      if (kWithAovs && aovsPending) result.aovs.albedo = beta;
      Vec3 le = environmentRadiance(scene, ray.direction);
      if (!isBlack(le) && (depth > 0 || scene.environment.visibleToCamera)) {
        float w = (depth == 0 || specularBounce) ? 1.0f : powerHeuristic(bsdfPdf, environmentPdf(scene, ray.direction));
        result.radiance += beta * le * w;
        if (kWithAovs && cameraChain) result.emitted += beta * le;
      }
      break;
    }
    if (kWithAovs && aovsPending) pathLength += hit.t;
    SurfaceInteraction si = makeInteraction(scene, hit);
    const Material& stored = scene.materials[si.materialId];
    // A segment that ends on a surface's inner side ran inside its material, which may absorb.
    if (absorbs(stored) && dot(ray.direction, si.geometricNormal) > 0.0f) beta *= volumeTransmittance(stored, hit.t);
    if (hasTextures(stored))
      si.footprint = textureFootprint(scene, hit, ray.direction, cone.widthAt(hit.t), settings.textureFilter);
    Vec3 wo = -ray.direction;
    Material material = evaluateSurfaceMaterial(scene, si, wo);
    applyNormalMap(scene, material, si);
    keepReflectionAboveSurface(si, wo);
    if (kWithAovs && aovsPending && !isSpecularMaterial(material)) {
      result.aovs.albedo = beta * materialAlbedo(material);
      result.aovs.normal = dot(si.shadingNormal, wo) < 0.0f ? -si.shadingNormal : si.shadingNormal;
      result.aovs.depth = pathLength;
      aovsPending = false;
    }

    float cosAtSurface = dot(si.geometricNormal, wo);
    if (!isBlack(material.emission) && cosAtSurface > 0.0f) {
      float w = 1.0f;
      if (depth > 0 && !specularBounce) {
        float lightPdf = triangleLightPdf(scene, settings.lightSampler, {lastScatter, lastNormal}, hit,
                                          length(si.position - lastScatter), cosAtSurface);
        w = powerHeuristic(bsdfPdf, lightPdf);
      }
      result.radiance += beta * material.emission * w;
      if (kWithAovs && cameraChain) result.emitted += beta * material.emission;
    }
    if (depth >= settings.maxDepth) break;

    Bsdf bsdf(material, si, wo);
    float woSide = dot(wo, si.geometricNormal);
    // A direction counts only when the shading and geometric normals agree on which side of the surface it is.
    auto sidesAgree = [&](Vec3 wi) {
      return (dot(wi, si.geometricNormal) * woSide > 0.0f) == (dot(wi, bsdf.normal()) > 0.0f);
    };

    // Next-event estimation of one light of any kind: what it adds if a shadow ray finds it unoccluded, the BSDF's
    // value and density (for the MIS weight) evaluated in one call. A punctual light's sample takes no MIS
    // weight: no BSDF sample can hit it.
    float uSelect = sampler.next1D();
    Vec2 uLight = sampler.next2D();
    Vec3 lightContribution;
    Ray shadow;
    if (!bsdf.isDelta()) {
      LightSample ls = sampleLight(scene, settings.lightSampler, {si.position, bsdf.normal()}, uSelect, uLight);
      bool reachable = dot(ls.wi, si.geometricNormal) * woSide > 0.0f || bsdf.hasTransmission();
      BsdfEval e;
      if (ls.valid && reachable && sidesAgree(ls.wi)) e = bsdf.evalPdf(wo, ls.wi);
      if (!isBlack(e.f)) {
        Vec3 le = ls.isDelta || ls.distance >= kInf ? ls.radiance : texturedLightRadiance(scene, ls);
        float w = ls.isDelta ? 1.0f : powerHeuristic(ls.pdf, e.pdf);
        lightContribution = beta * e.f * le * (fabsf(dot(ls.wi, bsdf.normal())) * w / ls.pdf);
        shadow = {offsetRayOrigin(si.position, si.geometricNormal, ls.wi), ls.wi, 0.0f,
                  ls.distance >= kInf ? kInf : ls.distance * (1.0f - 1e-4f)};
      }
    }

    // The BSDF's sample for the path's next direction, taken before the shadow ray is traced: the BSDF, built
    // once for this vertex, is then done with, and its parameters need not be kept across the trace.
    float uChoice = sampler.next1D();
    Vec2 uBsdf = sampler.next2D();
    BsdfSample bs = bsdf.sample(wo, uChoice, uBsdf);

    if (!isBlack(lightContribution)) {
      ++result.rays;
      if (!tracer.occluded(shadow, queryBits())) result.radiance += lightContribution;
    }

    // Continue the path along the BSDF's sample.
    Vec3 next;
    if (!bs.valid || isBlack(bs.f) || !continuePathTowards(bs.wi, wo, si.geometricNormal, bsdf.normal(), next)) break;
    beta *= bs.f * (fabsf(dot(bs.wi, bsdf.normal())) / bs.pdf);
    etaScale *= bs.eta * bs.eta;
    specularBounce = bs.isDelta;
    cameraChain = cameraChain && bs.isDelta;
    bsdfPdf = bs.pdf;
    cone = bs.isDelta ? cone.afterDeltaBounce(hit.t) : RayCone{};
    lastScatter = si.position;
    lastNormal = bsdf.normal();
    ray = {offsetRayOrigin(si.position, si.geometricNormal, next), next, 0.0f, kInf};
    ++depth;

    float uRoulette = sampler.next1D();
    if (depth >= settings.rouletteDepth) {
      float survive = fminf(0.95f, maxComponent(beta) * etaScale);
      if (uRoulette >= survive) break;
      beta = beta / survive;
    }
  }
  return result;
}

// NaN, infinite or negative estimates come from numerical failures; they are dropped, never accumulated.
CANDELA_FN bool isValidSample(Vec3 l) { return isFinite(l) && l.x >= 0.0f && l.y >= 0.0f && l.z >= 0.0f; }

// One sample of pixel (x, y): a jittered camera ray, then the path. A camera ray that cannot be traced
// (isTraceableCameraRay) is not: the sample gets a negative estimate, which isValidSample drops and counts.
template <bool kWithAovs = false, class Tracer>
CANDELA_HD PathResult renderPixelSample(const SceneView& scene, const Tracer& tracer, const Camera& camera,
                                        const RenderSettings& settings, uint32_t x, uint32_t y, uint32_t sampleIndex) {
  PathSampler sampler(y * settings.width + x, sampleIndex, settings.seed, settings.sampler);
  Vec2 jitter = sampler.next2D();
  Vec2 uLens;
  if (camera.lensRadius > 0.0f) uLens = sampler.next2D();
  Ray ray =
      camera.generateRay(float(x) + jitter.x, float(y) + jitter.y, int(settings.width), int(settings.height), uLens);
  if (!isTraceableCameraRay(ray)) {
    PathResult dropped;
    dropped.radiance = {-1.0f, -1.0f, -1.0f};
    return dropped;
  }
  return tracePath<kWithAovs>(scene, tracer, ray, sampler, settings, cameraRayCone(camera, settings.height));
}

}  // namespace candela
