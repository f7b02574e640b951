#pragma once
// The path tracer's loop body, split where its rays are traced, so that one source serves two schedules: a thread
// that follows its path from ray to ray (tracePath, kernel/integrator.h), and launches that each advance every
// path by one step, with the path kept in memory between them (the GPU's wavefront schedule,
// backends/optix/device/wavefront_programs.h). Both draw the same numbers in the same order and so compute the
// same samples.
//
// One vertex: the radiance ray has been traced; shadeVertex adds the emission found, prepares the shadow ray of
// next-event estimation and samples the BSDF; then, once the shadow ray is traced (or only queued), continuePath
// turns the BSDF sample into the next radiance ray or ends the path. Both are inlined (CANDELA_FN): as calls,
// their structures pass through the stack, which made the one-thread schedule's frames markedly longer
// (docs/performance-log.md).
#include "core/path_sampler.h"
#include "kernel/aovs.h"
#include "kernel/bsdf/bsdf.h"
#include "kernel/interaction.h"
#include "kernel/lights.h"
#include "kernel/pass_through.h"
#include "kernel/ray_cone.h"
#include "kernel/render_settings.h"
#include "kernel/shading_normal.h"
#include "kernel/textured_material.h"
#include "kernel/volume_absorption.h"

namespace candela {

// What a path carries from one vertex to the next.
struct PathState {
  Vec3 radiance;
  uint32_t rays = 0;  // camera, bounce and shadow rays traced for this path
  Vec3 beta{1, 1, 1};
  float etaScale = 1.0f;  // product of eta^2 over refractions: undoes their radiance scaling for roulette
  Vec3 lastScatter;       // where the BSDF sample that produced the current ray was taken
  float bsdfPdf = 0.0f;   // its solid-angle density
  Vec3 lastNormal;        // the shading normal there, for the light sampler's density
  uint32_t depth = 0;
  RayCone cone;              // the pixel's footprint about the current ray (kernel/ray_cone.h)
  uint32_t bounceFlags = 0;  // how the current ray left its vertex: kDeltaBounce, kDirectLightCounted
};

// PathState::bounceFlags. kDeltaBounce: the current ray left a delta lobe. kDirectLightCounted: the vertex it left
// took its direct light from a ReSTIR reservoir (shadeVertex's directFromReservoir), which already counts all the
// light a non-delta lobe receives straight from emitters, so the emission this ray finds takes weight 0.
constexpr uint32_t kDeltaBounce = 1u;
constexpr uint32_t kDirectLightCounted = 2u;

// A path about to trace its first ray, whose footprint is `cone`.
CANDELA_FN PathState startPath(RayCone cone) {
  PathState s;
  s.cone = cone;
  s.rays = 1;
  return s;
}

// What only paths that record the denoisers' guides carry (the kWithAovs instantiations).
struct PathAovState {
  Vec3 emitted;  // PathResult::emitted
  PathAovs aovs;
  float pathLength = 0.0f;  // camera to the current hit, summed while the AOVs are pending
  bool cameraChain = true;  // every bounce so far was off a delta lobe: emission found now is seen directly
  bool aovsPending = true;
};

// A shadow ray: `contribution` joins the path's radiance when the ray reaches its light. Black when there is none.
struct ShadowQuery {
  Ray ray;
  Vec3 contribution;
  uint32_t bits = 0;  // pass-through bits (kernel/pass_through.h)
};

// What shadeVertex decided that continuePath needs: the BSDF's sample for the next direction and the surface it
// leaves from.
struct VertexScatter {
  BsdfSample sample;
  Vec3 position;
  Vec3 geometricNormal;
  Vec3 shadingNormal;
  Vec3 wo;
  float hitDistance = 0.0f;
  bool directFromReservoir = false;  // the vertex's direct light came from a reservoir, not from next-event estimation
};

// Random bits for a ray query's pass-through decisions; scenes without cut-outs never ask for them.
CANDELA_FN uint32_t passThroughBits(const SceneView& scene, PathSampler& sampler) {
  return scene.hasCutouts ? sampler.nextBits() : 0u;
}

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

// The vertex where `ray` ended (`found`: at `hit`; else it escaped): adds the emission found there, with its MIS
// weight; prepares `shadow`, one light of any kind sampled for next-event estimation with the BSDF's value and
// density (for the MIS weight) evaluated in one call; samples the BSDF into `scatter`. Returns false where the
// path ends here (it escaped, or reached the maximum depth), and then prepares neither.
// Delta lobes (mirror, smooth glass) skip light sampling and take the emission they hit at full weight. A punctual
// light's sample takes no MIS weight: no BSDF sample can hit it. With kWithAovs the path also records its AOVs at
// its first non-specular vertex.
//
// directFromReservoir: the caller adds this vertex's direct light itself, from a ReSTIR DI reservoir
// (kernel/restir/restir_passes.h), which estimates the whole of it: all the light that the BSDF's non-delta lobes
// receive straight from emitters (triangles, punctual lights, the environment). Without ReSTIR that integral is
// split between next-event estimation here and the emission the BSDF's sample finds at the next vertex, with MIS
// weights that sum to 1. With the reservoir both of those must be left out, or the direct light is counted twice:
// next-event estimation is skipped here, and continuePath marks the next ray kDirectLightCounted, whose emission
// (an emitter's or the environment's) then takes weight 0. A sample of a delta lobe is not marked: the reservoir's
// target (the BSDF's eval) has no delta lobes, so the emission found along one keeps its full weight, as always.
// Emission found further on, and next-event estimation at every later vertex, are as without ReSTIR.
template <bool kWithAovs>
CANDELA_FN bool shadeVertex(const SceneView& scene, const RenderSettings& settings, PathState& s, PathAovState& a,
                            PathSampler& sampler, const Ray& ray, bool found, const Hit& hit, ShadowQuery& shadow,
                            VertexScatter& scatter, bool directFromReservoir = false) {
  const bool specularBounce = (s.bounceFlags & kDeltaBounce) != 0;
  const bool directCounted = (s.bounceFlags & kDirectLightCounted) != 0;
  if (!found) {
    if (kWithAovs && a.aovsPending) a.aovs.albedo = s.beta;
    Vec3 le = environmentRadiance(scene, ray.direction);
    if (!isBlack(le) && (s.depth > 0 || scene.environment.visibleToCamera)) {
      float w = (s.depth == 0 || specularBounce) ? 1.0f
                : directCounted                  ? 0.0f
                                                 : powerHeuristic(s.bsdfPdf, environmentPdf(scene, ray.direction));
      s.radiance += s.beta * le * w;
      if (kWithAovs && a.cameraChain) a.emitted += s.beta * le;
    }
    return false;
  }
  if (kWithAovs && a.aovsPending) a.pathLength += hit.t;
  SurfaceInteraction si = makeInteraction(scene, hit, ray);
  const Material& stored = scene.materials[si.materialId];
  // A segment that ends on a surface's inner side ran inside its material, which may absorb.
  if (absorbs(stored) && dot(ray.direction, si.geometricNormal) > 0.0f) s.beta *= volumeTransmittance(stored, hit.t);
  if (hasTextures(stored))
    si.footprint = textureFootprint(scene, hit, ray.direction, s.cone.widthAt(hit.t), settings.textureFilter);
  Vec3 wo = -ray.direction;
  Material material = evaluateSurfaceMaterial(scene, si, wo);
  applyNormalMap(scene, material, si);
  keepReflectionAboveSurface(si, wo);
  if (kWithAovs && a.aovsPending && !isSpecularMaterial(material)) {
    a.aovs.albedo = s.beta * materialAlbedo(material);
    a.aovs.normal = dot(si.shadingNormal, wo) < 0.0f ? -si.shadingNormal : si.shadingNormal;
    a.aovs.depth = a.pathLength;
    a.aovsPending = false;
  }

  float cosAtSurface = dot(si.geometricNormal, wo);
  if (!isBlack(material.emission) && cosAtSurface > 0.0f) {
    float w = 1.0f;
    if (s.depth > 0 && !specularBounce && directCounted) {
      w = 0.0f;
    } else if (s.depth > 0 && !specularBounce) {
      float lightPdf = triangleLightPdf(scene, settings.lightSampler, {s.lastScatter, s.lastNormal}, hit,
                                        length(si.position - s.lastScatter), cosAtSurface);
      w = powerHeuristic(s.bsdfPdf, lightPdf);
    }
    s.radiance += s.beta * material.emission * w;
    if (kWithAovs && a.cameraChain) a.emitted += s.beta * material.emission;
  }
  if (s.depth >= settings.maxDepth) return false;

  Bsdf bsdf(material, si, wo);
  float woSide = dot(wo, si.geometricNormal);
  // A direction counts only when the shading and geometric normals agree on which side of the surface it is.
  auto sidesAgree = [&](Vec3 wi) {
    return (dot(wi, si.geometricNormal) * woSide > 0.0f) == (dot(wi, bsdf.normal()) > 0.0f);
  };

  float uSelect = sampler.next1D();
  Vec2 uLight = sampler.next2D();
  shadow.contribution = {};
  if (!bsdf.isDelta() && !directFromReservoir) {
    LightSample ls = sampleLight(scene, settings.lightSampler, {si.position, bsdf.normal()}, uSelect, uLight);
    bool reachable = dot(ls.wi, si.geometricNormal) * woSide > 0.0f || bsdf.hasTransmission();
    BsdfEval e;
    if (ls.valid && reachable && sidesAgree(ls.wi)) e = bsdf.evalPdf(wo, ls.wi);
    if (!isBlack(e.f)) {
      Vec3 le = ls.isDelta || ls.distance >= kInf ? ls.radiance : texturedLightRadiance(scene, ls);
      float w = ls.isDelta ? 1.0f : powerHeuristic(ls.pdf, e.pdf);
      shadow.contribution = s.beta * e.f * le * (fabsf(dot(ls.wi, bsdf.normal())) * w / ls.pdf);
      shadow.ray = {offsetRayOrigin(si.position, si.geometricNormal, ls.wi), ls.wi, 0.0f,
                    ls.distance >= kInf ? kInf : ls.distance * (1.0f - 1e-4f)};
    }
  }

  // The BSDF's sample for the path's next direction, taken before the shadow ray is traced: the BSDF, built once
  // for this vertex, is then done with, and its parameters need not be kept across the trace.
  float uChoice = sampler.next1D();
  Vec2 uBsdf = sampler.next2D();
  scatter.sample = bsdf.sample(wo, uChoice, uBsdf);
  scatter.position = si.position;
  scatter.geometricNormal = si.geometricNormal;
  scatter.shadingNormal = bsdf.normal();
  scatter.wo = wo;
  scatter.hitDistance = hit.t;
  scatter.directFromReservoir = directFromReservoir;

  if (!isBlack(shadow.contribution)) {
    ++s.rays;
    shadow.bits = passThroughBits(scene, sampler);
  }
  return true;
}

// Continues the path along the BSDF's sample of shadeVertex: returns true with `ray` the next radiance ray and
// `bits` its pass-through bits, or false where the sample is unusable or Russian roulette (after
// settings.rouletteDepth bounces) ends the path.
template <bool kWithAovs>
CANDELA_FN bool continuePath(const SceneView& scene, const RenderSettings& settings, PathState& s, PathAovState& a,
                             PathSampler& sampler, const VertexScatter& scatter, Ray& ray, uint32_t& bits) {
  const BsdfSample& bs = scatter.sample;
  Vec3 next;
  if (!bs.valid || isBlack(bs.f) ||
      !continuePathTowards(bs.wi, scatter.wo, scatter.geometricNormal, scatter.shadingNormal, next))
    return false;
  s.beta *= bs.f * (fabsf(dot(bs.wi, scatter.shadingNormal)) / bs.pdf);
  s.etaScale *= bs.eta * bs.eta;
  s.bounceFlags = bs.isDelta ? kDeltaBounce : (scatter.directFromReservoir ? kDirectLightCounted : 0u);
  if (kWithAovs) a.cameraChain = a.cameraChain && bs.isDelta;
  s.bsdfPdf = bs.pdf;
  s.cone = bs.isDelta ? s.cone.afterDeltaBounce(scatter.hitDistance) : RayCone{};
  s.lastScatter = scatter.position;
  s.lastNormal = scatter.shadingNormal;
  ray = {offsetRayOrigin(scatter.position, scatter.geometricNormal, next), next, 0.0f, kInf};
  ++s.depth;

  float uRoulette = sampler.next1D();
  if (s.depth >= settings.rouletteDepth) {
    float survive = fminf(0.95f, maxComponent(s.beta) * s.etaScale);
    if (uRoulette >= survive) return false;
    s.beta = s.beta / survive;
  }
  ++s.rays;
  bits = passThroughBits(scene, sampler);
  return true;
}

}  // namespace candela
