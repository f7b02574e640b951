#pragma once
#include "core/rng.h"
#include "kernel/bsdf/bsdf.h"
#include "kernel/camera.h"
#include "kernel/interaction.h"
#include "kernel/lights.h"
#include "kernel/render_settings.h"

namespace candela {

struct PathResult {
  Vec3 radiance;
  uint32_t rays = 0;  // camera, bounce and shadow rays traced for this path
};

// Unidirectional path tracing with next-event estimation and BSDF sampling combined by MIS (power heuristic),
// Russian roulette after `rouletteDepth` bounces. `Tracer` answers the two ray queries:
//   bool intersect(const Ray&, Hit&) const;  bool occluded(const Ray&) const;
template <class Tracer>
CANDELA_HD PathResult tracePath(const SceneView& scene, const Tracer& tracer, Ray ray, PathSampler& sampler,
                                const RenderSettings& settings) {
  PathResult result;
  Vec3 beta{1, 1, 1};
  bool specularBounce = false;
  float bsdfPdf = 0.0f;  // solid-angle pdf of the BSDF sample that produced `ray`
  for (uint32_t depth = 0;; ++depth) {
    Hit hit;
    ++result.rays;
    if (!tracer.intersect(ray, hit)) {
      Vec3 le = environmentRadiance(scene, ray.direction);
      if (!isBlack(le) && (depth > 0 || scene.environment.visibleToCamera)) {
        float w = (depth == 0 || specularBounce) ? 1.0f : powerHeuristic(bsdfPdf, environmentPdf(scene, ray.direction));
        result.radiance += beta * le * w;
      }
      break;
    }
    SurfaceInteraction si = makeInteraction(scene, hit);
    const Material& material = scene.materials[si.materialId];
    Vec3 wo = -ray.direction;

    float cosAtSurface = dot(si.geometricNormal, wo);
    if (!isBlack(material.emission) && cosAtSurface > 0.0f) {
      float w = 1.0f;
      if (depth > 0 && !specularBounce) {
        float lightPdf = triangleLightPdf(scene, material.emission, hit.t * length(ray.direction), cosAtSurface);
        w = powerHeuristic(bsdfPdf, lightPdf);
      }
      result.radiance += beta * material.emission * w;
    }
    if (depth >= settings.maxDepth) break;

    Bsdf bsdf(material, si, wo);
    float woSide = dot(wo, si.geometricNormal);

    // Next-event estimation.
    float uSelect = sampler.next1D();
    Vec2 uLight{sampler.next1D(), sampler.next1D()};
    LightSample ls = sampleLight(scene, si.position, uSelect, uLight);
    if (ls.valid && dot(ls.wi, si.geometricNormal) * woSide > 0.0f) {
      Vec3 f = bsdf.eval(wo, ls.wi);
      if (!isBlack(f)) {
        Ray shadow{offsetRayOrigin(si.position, si.geometricNormal, ls.wi), ls.wi, 0.0f,
                   ls.distance >= kInf ? kInf : ls.distance * (1.0f - 1e-4f)};
        ++result.rays;
        if (!tracer.occluded(shadow)) {
          float w = powerHeuristic(ls.pdf, bsdf.pdf(wo, ls.wi));
          result.radiance += beta * f * ls.radiance * (fabsf(dot(ls.wi, bsdf.normal())) * w / ls.pdf);
        }
      }
    }

    // Continue the path by sampling the BSDF.
    Vec2 uBsdf{sampler.next1D(), sampler.next1D()};
    BsdfSample bs = bsdf.sample(wo, uBsdf);
    if (!bs.valid || dot(bs.wi, si.geometricNormal) * woSide <= 0.0f) break;
    beta *= bs.f * (fabsf(dot(bs.wi, bsdf.normal())) / bs.pdf);
    specularBounce = bs.isDelta;
    bsdfPdf = bs.pdf;
    ray = {offsetRayOrigin(si.position, si.geometricNormal, bs.wi), bs.wi, 0.0f, kInf};

    float uRoulette = sampler.next1D();
    if (depth + 1 >= settings.rouletteDepth) {
      float survive = fminf(0.95f, maxComponent(beta));
      if (uRoulette >= survive) break;
      beta = beta / survive;
    }
  }
  return result;
}

// NaN, infinite or negative estimates come from numerical failures; they are dropped, never accumulated.
CANDELA_FN bool isValidSample(Vec3 l) { return isFinite(l) && l.x >= 0.0f && l.y >= 0.0f && l.z >= 0.0f; }

// One sample of pixel (x, y): a jittered camera ray, then the path.
template <class Tracer>
CANDELA_HD PathResult renderPixelSample(const SceneView& scene, const Tracer& tracer, const Camera& camera,
                                        const RenderSettings& settings, uint32_t x, uint32_t y,
                                        uint32_t sampleIndex) {
  PathSampler sampler(y * settings.width + x, sampleIndex, settings.seed);
  float jx = sampler.next1D(), jy = sampler.next1D();
  Vec2 uLens;
  if (camera.lensRadius > 0.0f) uLens = {sampler.next1D(), sampler.next1D()};
  Ray ray = camera.generateRay(float(x) + jx, float(y) + jy, int(settings.width), int(settings.height), uLens);
  return tracePath(scene, tracer, ray, sampler, settings);
}

}  // namespace candela
