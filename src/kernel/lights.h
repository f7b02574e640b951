#pragma once
#include "core/sampling.h"
#include "kernel/hit.h"
#include "kernel/light_bvh.h"
#include "kernel/render_settings.h"
#include "kernel/scene_view.h"

namespace candela {

struct LightSample {
  Vec3 wi;                // unit direction from the shading point to the light
  float distance = kInf;  // to the sampled point; infinite for the environment
  Vec3 radiance;          // emitted towards the shading point
  float pdf = 0.0f;       // solid angle density of wi, light selection included
  bool valid = false;
  uint32_t lightIndex = 0;  // the triangle sampled, and the point's barycentrics of its vertices 1 and 2
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

// Area density, within the triangle choice, with which the power table picks a point on a triangle emitting
// `emittedRadiance`: choosing a triangle by power and then a point by area gives pi * luminance(Le) / total
// power, independent of which triangle it is.
CANDELA_FN float powerTableAreaPdf(const SceneView& scene, Vec3 emittedRadiance) {
  return scene.lightAreaPdfScale * luminance(emittedRadiance);
}

// Solid-angle density with which sampleLight() picks a point on the emissive triangle `hit` lies on, seen from
// ctx. With the power table the density follows from the untextured emission alone; the BVH needs the light.
CANDELA_FN float triangleLightPdf(const SceneView& scene, LightSamplerKind kind, LightSampleContext ctx, const Hit& hit,
                                  Vec3 emittedRadiance, float distance, float cosAtLight) {
  if (cosAtLight <= 0.0f) return 0.0f;
  float areaPdf;
  if (kind == LightSamplerKind::Power) {
    areaPdf = powerTableAreaPdf(scene, emittedRadiance);
  } else {
    uint32_t index = findLightIndex(scene, hit.instanceId, hit.primitiveId);
    if (index == scene.lightCount) return 0.0f;
    areaPdf = lightBvhPmf(scene, ctx, index) / scene.lights[index].area;
  }
  return solidAnglePdf((1.0f - scene.environmentSelectProbability) * areaPdf, distance, cosAtLight);
}

// Samples the environment or one emissive triangle (one-sided: emits along its geometric normal), the triangle
// chosen as `kind` says for the shading point ctx.
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
  if (scene.lightCount == 0) return ls;
  float uTri = fminf((uSelect - pEnv) / (1.0f - pEnv), 0.99999994f);
  float areaPdf;
  if (kind == LightSamplerKind::Power) {
    ls.lightIndex = uint32_t(findInterval(scene.lightCdf, int(scene.lightCount), uTri));
    areaPdf = powerTableAreaPdf(scene, scene.lights[ls.lightIndex].radiance);
  } else {
    SampledLight picked = sampleLightBvh(scene, ctx, uTri);
    if (picked.pmf == 0.0f) return ls;
    ls.lightIndex = picked.index;
    areaPdf = picked.pmf / scene.lights[ls.lightIndex].area;
  }
  const LightTriangle& light = scene.lights[ls.lightIndex];
  Vec2 b = sampleUniformTriangle(u);
  ls.barycentrics = b;
  Vec3 p = light.p0 + light.edge1 * b.x + light.edge2 * b.y;
  Vec3 toLight = p - ctx.p;
  float dist2 = dot(toLight, toLight);
  if (dist2 <= 0.0f) return ls;
  ls.distance = sqrtf(dist2);
  ls.wi = toLight / ls.distance;
  Vec3 n = normalize(cross(light.edge1, light.edge2)) * light.frontSign;
  ls.pdf = solidAnglePdf((1.0f - pEnv) * areaPdf, ls.distance, -dot(n, ls.wi));
  ls.radiance = light.radiance;
  ls.valid = ls.pdf > 0.0f;
  return ls;
}

// A spot light's falloff between its cones: 1 inside cosInner, 0 outside cosOuter, smoothstep between (as
// pbrt-v4's SpotLight).
CANDELA_FN float spotFalloff(const PunctualLight& light, float cosAngle) {
  if (cosAngle >= light.cosInner) return 1.0f;
  if (cosAngle <= light.cosOuter) return 0.0f;
  float t = (cosAngle - light.cosOuter) / (light.cosInner - light.cosOuter);
  return t * t * (3.0f - 2.0f * t);
}

// Picks one punctual light uniformly and returns the light it sends to `from`: `radiance` is the irradiance it
// gives a surface facing it, `pdf` the probability of the pick (no density: the direction is fixed).
CANDELA_FN LightSample samplePunctualLight(const SceneView& scene, Vec3 from, float uSelect) {
  LightSample ls;
  if (scene.punctualLightCount == 0) return ls;
  uint32_t index = uint32_t(uSelect * float(scene.punctualLightCount));
  if (index >= scene.punctualLightCount) index = scene.punctualLightCount - 1;
  const PunctualLight& light = scene.punctualLights[index];
  ls.lightIndex = index;
  ls.pdf = 1.0f / float(scene.punctualLightCount);
  if (light.type == PunctualLightType::Directional) {
    ls.wi = -light.direction;
    ls.radiance = light.intensity;
    ls.valid = !isBlack(ls.radiance);
    return ls;
  }
  Vec3 toLight = light.position - from;
  float dist2 = dot(toLight, toLight);
  if (!(dist2 > 0.0f)) return ls;
  ls.distance = sqrtf(dist2);
  ls.wi = toLight / ls.distance;
  float falloff = light.type == PunctualLightType::Spot ? spotFalloff(light, -dot(ls.wi, light.direction)) : 1.0f;
  ls.radiance = light.intensity * (falloff / dist2);
  ls.valid = !isBlack(ls.radiance);
  return ls;
}

}  // namespace candela
