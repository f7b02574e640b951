#pragma once
#include "core/sampling.h"
#include "core/spherical_triangle.h"
#include "kernel/hit.h"
#include "kernel/light_bvh.h"
#include "kernel/render_settings.h"
#include "kernel/scene_view.h"

namespace candela {

struct LightSample {
  Vec3 wi;                // unit direction from the shading point to the light
  float distance = kInf;  // to the sampled point; infinite for the environment
  Vec3 radiance;          // emitted towards the shading point
  float pdf = 0.0f;       // solid angle density of wi, light selection included; a delta light's pmf
  bool valid = false;
  bool isDelta = false;  // a punctual light: no BSDF sample can find it, so it takes no MIS weight
  // The light sampled, lights[i] below lightCount, else punctualLights[i - lightCount]; on a triangle the
  // point's barycentrics of its vertices 1 and 2.
  uint32_t lightIndex = 0;
  Vec2 barycentrics;
};

// Environment radiance arriving along `direction` (pointing away from the scene).
CANDELA_FN Vec3 environmentRadiance(const SceneView& scene, Vec3 direction) {
  return environmentRadiance(scene.environment, direction);
}

// Solid-angle density with which sampleLight() picks `direction` on the environment, selection included.
CANDELA_FN float environmentPdf(const SceneView& scene, Vec3 direction) {
  if (scene.environmentSelectProbability == 0.0f) return 0.0f;
  return scene.environmentSelectProbability * environmentDirectionPdf(scene.environment, direction);
}

// Solid-angle density of a point on a light at `distance` from the shading point, seen at cosAtLight from the
// light's normal, whose area density is `areaPdf`.
CANDELA_FN float solidAnglePdf(float areaPdf, float distance, float cosAtLight) {
  if (cosAtLight <= 0.0f) return 0.0f;
  return areaPdf * distance * distance / cosAtLight;
}

// Emitted power (luminance) of the bounded lights, by which the power table picks them: a one-sided triangle's
// pi x luminance(Le) x area; a point light's 4 pi x luminance(I); a spot light's 2 pi x luminance(I) x the
// solid-angle measure of its cone with the falloff (as pbrt-v4's SpotLight::Phi).
CANDELA_FN float trianglePower(Vec3 emittedRadiance, float area) { return kPi * luminance(emittedRadiance) * area; }
CANDELA_FN float punctualLightPower(const PunctualLight& light) {
  float perSteradian = luminance(light.intensity);
  if (light.type != PunctualLightType::Spot) return 4.0f * kPi * perSteradian;
  return 2.0f * kPi * perSteradian * ((1.0f - light.cosInner) + 0.5f * (light.cosInner - light.cosOuter));
}

// Probability with which the power table picks the triangle `light` among the bounded lights.
CANDELA_FN float powerTablePmf(const SceneView& scene, const LightTriangle& light) {
  return scene.inverseLightPower * light.power;
}

// Solid angles between which a light triangle is sampled by solid angle rather than by area, as pbrt-v4's
// Triangle: below, single precision cannot resolve the spherical construction; above (near a hemisphere) it
// becomes unstable.
constexpr float kMinSphericalSampleSolidAngle = 3e-4f;
constexpr float kMaxSphericalSampleSolidAngle = 6.22f;
// Below this estimated solid angle a triangle is sampled by area, without the exact construction: for small
// triangles the construction costs more time than the variance it removes, beside large ones it pays (the
// measurements are in docs/performance-log.md, 'Solid-angle sampling where it pays').
constexpr float kSphericalSamplingWorthwhile = 0.1f;

// Whether `light`, seen from p as a small patch at its centroid (area x |cos| / distance^2: cheap, and exact in the
// limit of small triangles), subtends kSphericalSamplingWorthwhile or more: only then is the exact construction tried.
CANDELA_FN bool sphericalSamplingWorthwhile(const LightTriangle& light, Vec3 p) {
  Vec3 toCentroid = light.p0 + (light.edge1 + light.edge2) * (1.0f / 3.0f) - p;
  float d2 = dot(toCentroid, toCentroid);
  float twiceAreaCosDistance = fabsf(dot(cross(light.edge1, light.edge2), toCentroid));
  return twiceAreaCosDistance >= kSphericalSamplingWorthwhile * 2.0f * d2 * sqrtf(d2);
}

// `light` seen from p where next-event estimation samples it by solid angle; a zero area where it samples it by
// area. Sampling and the density for MIS both decide through this one function.
CANDELA_FN SphericalTriangle sphericalSampling(const LightTriangle& light, Vec3 p) {
  if (!sphericalSamplingWorthwhile(light, p)) return {};
  SphericalTriangle seen = sphericalTriangle(light.p0, light.p0 + light.edge1, light.p0 + light.edge2, p);
  if (!(seen.area >= kMinSphericalSampleSolidAngle && seen.area <= kMaxSphericalSampleSolidAngle)) seen.area = 0.0f;
  return seen;
}

// The solid angle `light` subtends from p where next-event estimation samples it by solid angle; 0 where it
// samples it by area.
CANDELA_FN float sphericalSamplingSolidAngle(const LightTriangle& light, Vec3 p) {
  return sphericalSampling(light, p).area;
}

// The probability with which the power table picks the bounded light `index` (a triangle below lightCount, then the
// bounded punctual lights).
CANDELA_FN float boundedLightPowerPmf(const SceneView& scene, uint32_t index) {
  return index < scene.lightCount
             ? powerTablePmf(scene, scene.lights[index])
             : scene.inverseLightPower * punctualLightPower(scene.punctualLights[index - scene.lightCount]);
}

// Picks one of the bounded lights for ctx as `kind` says, with u: by the power table, or down the light BVH; pmf 0
// where none can be picked.
CANDELA_FN SampledLight sampleBoundedLight(const SceneView& scene, LightSamplerKind kind, LightSampleContext ctx,
                                           float u) {
  if (kind != LightSamplerKind::Power) return sampleLightBvh(scene, ctx, u);
  SampledLight picked;
  picked.index = uint32_t(findInterval(scene.lightCdf, int(boundedLightCount(scene)), u));
  picked.pmf = boundedLightPowerPmf(scene, picked.index);
  return picked;
}

// The probability with which sampleBoundedLight() picks the bounded light `index` for ctx.
CANDELA_FN float boundedLightPmf(const SceneView& scene, LightSamplerKind kind, LightSampleContext ctx,
                                 uint32_t index) {
  return kind == LightSamplerKind::Power ? boundedLightPowerPmf(scene, index) : lightBvhPmf(scene, ctx, index);
}

// Solid-angle density of a point on `light`, chosen with probability selectPmf, at `distance` and seen at
// cosAtLight from its normal: uniform over the solid angle where sphericalSamplingSolidAngle gave one, else
// uniform over the area.
CANDELA_FN float trianglePointPdf(const LightTriangle& light, float selectPmf, float solidAngle, float distance,
                                  float cosAtLight) {
  if (cosAtLight <= 0.0f) return 0.0f;
  if (solidAngle > 0.0f) return selectPmf / solidAngle;
  return selectPmf / light.area * distance * distance / cosAtLight;
}

// Solid-angle density with which sampleLight() picks the point `hit` reaches on an emissive triangle, seen from
// ctx.
CANDELA_FN float triangleLightPdf(const SceneView& scene, LightSamplerKind kind, LightSampleContext ctx, const Hit& hit,
                                  float distance, float cosAtLight) {
  if (cosAtLight <= 0.0f) return 0.0f;
  uint32_t index = findLightIndex(scene, hit.instanceId, hit.primitiveId);
  if (index == scene.lightCount) return 0.0f;
  const LightTriangle& light = scene.lights[index];
  float selectPmf = boundedLightPmf(scene, kind, ctx, index);
  return scene.boundedSelectProbability *
         trianglePointPdf(light, selectPmf, sphericalSamplingSolidAngle(light, ctx.p), distance, cosAtLight);
}

// A spot light's falloff between its cones: 1 inside cosInner, 0 outside cosOuter, smoothstep between (as
// pbrt-v4's SpotLight).
CANDELA_FN float spotFalloff(const PunctualLight& light, float cosAngle) {
  if (cosAngle >= light.cosInner) return 1.0f;
  if (cosAngle <= light.cosOuter) return 0.0f;
  float t = (cosAngle - light.cosOuter) / (light.cosInner - light.cosOuter);
  return t * t * (3.0f - 2.0f * t);
}

// What the punctual `light`, picked with probability `pmf`, sends to `from`: `radiance` is the irradiance it
// gives a surface facing it, `pdf` the pmf (no density: the direction is fixed).
CANDELA_FN LightSample samplePunctualLight(const PunctualLight& light, Vec3 from, float pmf) {
  LightSample ls;
  ls.isDelta = true;
  ls.pdf = pmf;
  if (light.type == PunctualLightType::Directional) {
    ls.wi = -light.direction;
    ls.radiance = light.intensity;
    ls.valid = pmf > 0.0f && !isBlack(ls.radiance);
    return ls;
  }
  Vec3 toLight = light.position - from;
  float dist2 = dot(toLight, toLight);
  if (!(dist2 > 0.0f)) return ls;
  ls.distance = sqrtf(dist2);
  ls.wi = toLight / ls.distance;
  float falloff = light.type == PunctualLightType::Spot ? spotFalloff(light, -dot(ls.wi, light.direction)) : 1.0f;
  ls.radiance = light.intensity * (falloff / dist2);
  ls.valid = pmf > 0.0f && !isBlack(ls.radiance);
  return ls;
}

// Samples one light for the shading point ctx (see SceneView): with uSelect the environment, a directional light
// or the bounded lights, then among those a bounded light as `kind` says. A triangle (one-sided: it emits along
// its geometric normal) is sampled at a point by solid angle or by area, with u; a punctual light is its point.
CANDELA_FN LightSample sampleLight(const SceneView& scene, LightSamplerKind kind, LightSampleContext ctx, float uSelect,
                                   Vec2 u) {
  LightSample ls;
  float pEnv = scene.environmentSelectProbability;
  if (uSelect < pEnv) {
    EnvironmentSample es = sampleEnvironment(scene.environment, u);
    ls.wi = es.direction;
    ls.radiance = environmentRadiance(scene, ls.wi);
    ls.pdf = pEnv * es.pdf;
    ls.valid = ls.pdf > 0.0f;
    return ls;
  }
  uint32_t directionalCount = scene.punctualLightCount - scene.boundedPunctualLightCount;
  float pDirectional = scene.directionalSelectProbability * float(directionalCount);
  float pBounded = scene.boundedSelectProbability;
  if (uSelect < pEnv + pDirectional || pBounded == 0.0f) {
    if (directionalCount == 0) return ls;
    uint32_t k = uint32_t((uSelect - pEnv) / scene.directionalSelectProbability);
    if (k >= directionalCount) k = directionalCount - 1;
    ls = samplePunctualLight(scene.punctualLights[scene.boundedPunctualLightCount + k], ctx.p,
                             scene.directionalSelectProbability);
    ls.lightIndex = scene.lightCount + scene.boundedPunctualLightCount + k;
    return ls;
  }
  float uBounded = fminf((uSelect - pEnv - pDirectional) / pBounded, 0.99999994f);
  const SampledLight picked = sampleBoundedLight(scene, kind, ctx, uBounded);
  if (picked.pmf == 0.0f) return ls;
  const uint32_t index = picked.index;
  const float selectPmf = picked.pmf;
  if (index >= scene.lightCount) {
    ls = samplePunctualLight(scene.punctualLights[index - scene.lightCount], ctx.p, pBounded * selectPmf);
    ls.lightIndex = index;
    return ls;
  }
  ls.lightIndex = index;
  const LightTriangle& light = scene.lights[ls.lightIndex];
  SphericalTriangle seen = sphericalSampling(light, ctx.p);
  float solidAngle = seen.area;
  if (solidAngle > 0.0f) {
    SphericalTriangleSample st =
        sampleSphericalTriangle(seen, light.p0, light.p0 + light.edge1, light.p0 + light.edge2, ctx.p, u);
    if (st.pdf == 0.0f) return ls;
    ls.barycentrics = st.barycentrics;
  } else {
    ls.barycentrics = sampleUniformTriangle(u);
  }
  Vec3 p = light.p0 + light.edge1 * ls.barycentrics.x + light.edge2 * ls.barycentrics.y;
  Vec3 toLight = p - ctx.p;
  float dist2 = dot(toLight, toLight);
  if (dist2 <= 0.0f) return ls;
  ls.distance = sqrtf(dist2);
  ls.wi = toLight / ls.distance;
  Vec3 n = normalize(cross(light.edge1, light.edge2)) * light.frontSign;
  ls.pdf = pBounded * trianglePointPdf(light, selectPmf, solidAngle, ls.distance, -dot(n, ls.wi));
  ls.radiance = light.radiance;
  ls.valid = ls.pdf > 0.0f;
  return ls;
}

}  // namespace candela
