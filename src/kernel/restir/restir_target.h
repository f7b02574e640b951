#pragma once
// ReSTIR DI's target function: what a light sample (kernel/restir/restir_buffers.h) would contribute to a pixel's
// primary shading point, unshadowed, in the sample space's own measure; and the densities with which the initial
// candidates' two strategies (light sampling, BSDF sampling) produce a sample, for their MIS weights.
#include "kernel/bsdf/bsdf.h"
#include "kernel/interaction.h"
#include "kernel/lights.h"
#include "kernel/path_vertex.h"
#include "kernel/restir/restir_buffers.h"

namespace candela {

// A light sample seen from a point: the direction and distance to it, the radiance (or a punctual light's
// irradiance at a surface facing it) arriving, and `jacobian`, which turns a solid-angle density at the point into
// the sample space's measure (cos at the light / distance^2 on a triangle, 1 elsewhere).
struct RestirLightAt {
  Vec3 wi;
  float distance = kInf;
  Vec3 radiance;
  float jacobian = 0.0f;
  bool valid = false;
  bool isPunctual = false;  // counting measure: no BSDF sample can find it
};

// The point with barycentrics b (of vertices 1 and 2) on the emissive triangle lights[index].
CANDELA_FN RestirLightPoint restirLightPoint(const SceneView& scene, uint32_t index, Vec2 b) {
  const LightTriangle& light = scene.lights[index];
  RestirLightPoint point;
  point.position = light.p0 + light.edge1 * b.x + light.edge2 * b.y;
  // The unit normal is cross(edge1, edge2) over twice the area.
  point.normal = cross(light.edge1, light.edge2) * (light.frontSign * 0.5f / light.area);
  LightSample ls;
  ls.lightIndex = index;
  ls.barycentrics = b;
  ls.radiance = light.radiance;
  point.radiance = texturedLightRadiance(scene, ls);
  return point;
}

// A point on an emissive triangle seen from p.
CANDELA_FN RestirLightAt restirLightAt(const RestirLightPoint& point, Vec3 p) {
  RestirLightAt at;
  const Vec3 toLight = point.position - p;
  const float dist2 = dot(toLight, toLight);
  if (!(dist2 > 0.0f)) return at;
  at.distance = sqrtf(dist2);
  at.wi = toLight / at.distance;
  const float cosAtLight = -dot(point.normal, at.wi);
  if (!(cosAtLight > 0.0f)) return at;  // emitters are one-sided
  at.radiance = point.radiance;
  at.jacobian = cosAtLight / dist2;
  at.valid = !isBlack(at.radiance);
  return at;
}

// `sample` seen from p.
CANDELA_FN RestirLightAt restirLightAt(const SceneView& scene, const RestirSample& sample, Vec3 p) {
  RestirLightAt at;
  if (sample.light == kRestirEnvironment) {
    at.wi = sample.coordinates;
    at.radiance = environmentRadiance(scene, at.wi);
    at.jacobian = 1.0f;
    at.valid = !isBlack(at.radiance);
    return at;
  }
  if (sample.light < scene.lightCount)
    return restirLightAt(restirLightPoint(scene, sample.light, {sample.coordinates.x, sample.coordinates.y}), p);
  if (sample.light - scene.lightCount < scene.punctualLightCount) {
    const LightSample ls = samplePunctualLight(scene.punctualLights[sample.light - scene.lightCount], p, 1.0f);
    at.wi = ls.wi;
    at.distance = ls.distance;
    at.radiance = ls.radiance;
    at.jacobian = 1.0f;
    at.valid = ls.valid;
    at.isPunctual = true;
  }
  return at;
}

// A primary shading point rebuilt from its PrimarySurface, as shadeVertex builds a vertex's: its position, normals,
// the direction to the camera and its BSDF. `usable` is false where the camera ray found nothing or the BSDF has
// only delta lobes (light sampling cannot find those: such a pixel keeps next-event estimation's way, which skips
// them too).
struct RestirVertex {
  Vec3 position;
  Vec3 geometricNormal;
  Vec3 wo;
  float woSide = 0.0f;
  bool usable = false;  // before bsdf: rebuild() sets it while bsdf is initialised
  Bsdf bsdf;

  CANDELA_FN RestirVertex(const SceneView& scene, const RenderSettings& settings, const PrimarySurface& surface)
      : bsdf(rebuild(scene, settings, surface)) {}

  // The unshadowed contribution f * Le * |cos| of `light` (not yet in the sample space's measure: times
  // light.jacobian for that); black where the BSDF cannot send light that way, as in next-event estimation. Called,
  // not inlined, on the device: every candidate and every MIS term of the reuse evaluates it.
  CANDELA_FN_CALLED BsdfEval contribution(const RestirLightAt& light, Vec3& value) const {
    value = {};
    BsdfEval e;
    if (!usable || !light.valid) return e;
    const bool reachable = dot(light.wi, geometricNormal) * woSide > 0.0f || bsdf.hasTransmission();
    const bool sidesAgree = (dot(light.wi, geometricNormal) * woSide > 0.0f) == (dot(light.wi, bsdf.normal()) > 0.0f);
    if (!reachable || !sidesAgree) return e;
    e = bsdf.evalPdf(wo, light.wi);
    value = e.f * light.radiance * fabsf(dot(light.wi, bsdf.normal()));
    return e;
  }

  // The target function p-hat of `sample` here, in the sample space's measure: the luminance of the unshadowed
  // contribution. `light` receives the sample seen from here.
  CANDELA_FN float target(const SceneView& scene, const RestirSample& sample, RestirLightAt& light) const {
    if (!usable || sample.light == kRestirNoLight) return 0.0f;
    light = restirLightAt(scene, sample, position);
    Vec3 value;
    contribution(light, value);
    const float t = luminance(value) * light.jacobian;
    return t > 0.0f && t < kInf ? t : 0.0f;
  }

  // A shadow ray from here to the light seen as `light`, stopping short of it.
  CANDELA_FN Ray shadowRay(const RestirLightAt& light) const {
    return {offsetRayOrigin(position, geometricNormal, light.wi), light.wi, 0.0f,
            light.distance >= kInf ? kInf : light.distance * (1.0f - 1e-4f)};
  }

 private:
  // Called, not inlined, on the device: the pixel's own vertex and every reused neighbour's are rebuilt.
  CANDELA_FN_CALLED Bsdf rebuild(const SceneView& scene, const RenderSettings& settings,
                                 const PrimarySurface& surface) {
    SurfaceInteraction si;
    Material material;
    if (surface.found) {
      si = makeInteraction(scene, surface.hit, surface.ray);
      const Material& stored = scene.materials[si.materialId];
      if (hasTextures(stored))
        si.footprint =
            textureFootprint(scene, surface.hit, surface.ray.direction, surface.coneWidth, settings.textureFilter);
      wo = -surface.ray.direction;
      material = evaluateSurfaceMaterial(scene, si, wo);
      applyNormalMap(scene, material, si);
      keepReflectionAboveSurface(si, wo);
      position = si.position;
      geometricNormal = si.geometricNormal;
      woSide = dot(wo, si.geometricNormal);
    }
    Bsdf built(material, si, wo);
    usable = surface.found != 0 && !built.isDelta();
    return built;
  }
};

}  // namespace candela
