#pragma once
// ReSTIR DI (Bitterli et al. 2020) for the direct light of each pixel's primary vertex, as four passes over the
// image per sample index, which a backend launches one after the other (every pixel or tile of one before any of the
// next) on the buffers of kernel/restir/restir_buffers.h:
//
//   restirPrimaryPass    traces the camera ray and keeps the primary surface;
//   restirPresamplePass  presamples each screen tile's bounded lights for the region of its primary surfaces
//                        (kernel/restir/restir_presampling.h);
//   restirCandidatePass  resamples initial candidates (light samples: the tile's presampled lights, the environment
//                        and directional lights; and one BSDF sample) into a reservoir, tests its sample's visibility
//                        once, and reuses the previous sample's reservoir at the reprojected pixel (temporal reuse);
//   restirShadePass      reuses the reservoirs of a few nearby pixels (spatial reuse), keeps the result as the next
//                        sample's history, and traces the path: the primary vertex takes its direct light from the
//                        reservoir, every later vertex is shaded as without ReSTIR (kernel/path_vertex.h).
//
// Unbiased (RestirMode::Di): reuse combines reservoirs by generalized resampled importance sampling with pairwise MIS
// weights (Bitterli 2022; Wyman et al., "A Gentle Introduction to ReSTIR", 2023), whose densities are the target
// functions evaluated at each reused pixel's own surface, times the visibility from that surface: a reservoir's
// sample is always visible from its pixel (the initial one is tested, and reuse only picks visible ones), so a pixel
// that cannot see a light point cannot have produced it, and its MIS weight must not claim it. RestirMode::DiBiased
// weighs every reservoir by its confidence alone (the 1/M weights of the original paper), with neither the
// re-evaluations at the neighbours nor their visibility rays; its bias is measured in docs/performance.md.
#include "kernel/camera.h"
#include "kernel/integrator.h"
#include "kernel/restir/restir_presampling.h"
#include "kernel/restir/restir_random.h"
#include "kernel/restir/restir_target.h"

namespace candela {

// The counts and sizes below are measured choices (docs/performance.md, 'ReSTIR DI'): a light candidate costs its
// target (a BSDF evaluation) and no walk down the light BVH (the tile's presampled lights have walked it), each
// spatial neighbour a rebuilt BSDF and two shadow rays.
// Light-sampling candidates per pixel and sample (plus one BSDF sample): many where the scene has many bounded
// lights, for the resampling to choose among; few where it has a handful or none (the Cornell box's one light, an
// environment map), where more candidates only pick other points of the same lights at the same cost each.
constexpr uint32_t kRestirLightCandidates = 16;
constexpr uint32_t kRestirFewLightCandidates = 4;
constexpr uint32_t kRestirFewLights = 8;

CANDELA_FN uint32_t restirLightCandidates(const SceneView& scene) {
  return boundedLightCount(scene) <= kRestirFewLights ? kRestirFewLightCandidates : kRestirLightCandidates;
}

// Spatial reuse: neighbours tried, within this radius in pixels (closer neighbours share more of their lights).
constexpr uint32_t kRestirSpatialNeighbours = 2;
constexpr float kRestirSpatialRadius = 8.0f;
// The previous sample's reservoir counts for at most this many times the current initial one (the temporal reuse
// runs only where the film does not average the samples: RestirView::hasHistory).
constexpr float kRestirHistoryCap = 1.0f;
// Reuse only between surfaces whose shading normals are this close (cosine) and whose distances from their cameras
// differ by at most this fraction.
constexpr float kRestirNormalSimilarity = 0.9f;
constexpr float kRestirDepthSimilarity = 0.1f;

// Random bits for a ReSTIR ray's pass-through decisions; scenes without cut-outs never ask for them.
CANDELA_FN uint32_t passThroughBits(const SceneView& scene, RestirRandom& random) {
  return scene.hasCutouts ? random.nextBits() : 0u;
}

// Weighted reservoir sampling of a stream of candidates: keeps one with probability proportional to its resampling
// weight, with that candidate's target value.
struct ReservoirStream {
  RestirSample sample;
  float weightSum = 0.0f;
  float target = 0.0f;

  CANDELA_FN void add(const RestirSample& candidate, float weight, float candidateTarget, float u) {
    if (!(weight > 0.0f) || !(weight < kInf)) return;
    weightSum += weight;
    if (u * weightSum < weight) {
      sample = candidate;
      target = candidateTarget;
    }
  }

  // The reservoir of the kept candidate: its contribution weight is the weight sum over its target value, over
  // `normaliser` (1 where the resampling weights carry their MIS weights; the confidence sum for the 1/M weights).
  CANDELA_FN Reservoir finish(float confidence, float normaliser = 1.0f) const {
    Reservoir r;
    r.confidence = confidence;
    if (target > 0.0f) {
      r.sample = sample;
      r.weight = weightSum / (target * normaliser);
      if (!(r.weight < kInf)) r.weight = 0.0f;
    }
    return r;
  }
};

// The light sample of next-event estimation's sampleLight as a reservoir keeps it.
CANDELA_FN RestirSample restirSampleOf(const LightSample& ls) {
  RestirSample s;
  if (!ls.isDelta && ls.distance >= kInf) {
    s.light = kRestirEnvironment;
    s.coordinates = ls.wi;
  } else {
    s.light = ls.lightIndex;
    s.coordinates = {ls.barycentrics.x, ls.barycentrics.y, 0.0f};
  }
  return s;
}

// Whether the light seen as `light` from `vertex` is unoccluded.
template <class Tracer>
CANDELA_FN bool restirVisible(const SceneView& scene, const Tracer& tracer, const RestirVertex& vertex,
                              const RestirLightAt& light, RestirRandom& random, uint32_t& rays) {
  ++rays;
  return !tracer.occluded(vertex.shadowRay(light), passThroughBits(scene, random));
}

// Resamples restirLightCandidates(scene) light samples and one BSDF sample at `vertex` with the target function, each
// candidate weighted by the balance heuristic over the two strategies (with the light strategy's count): its
// resampling weight is then target / (M p_light + p_bsdf), both densities in solid angle (the measure's Jacobian
// cancels), and a punctual light, which the BSDF cannot sample, has target / (M p_light). The light strategy is
// sampleLight()'s choice between the environment, the directional and the bounded lights, and a bounded light is one
// of the pixel's tile's presampled lights (kernel/restir/restir_presampling.h): the candidates take them at evenly
// spaced places from a random start, so that they differ, each one uniformly picked. The kept sample's visibility is
// tested once: where it is occluded the reservoir keeps nothing (its confidence stays 1).
template <class Tracer>
CANDELA_FN Reservoir initialReservoir(const SceneView& scene, const Tracer& tracer, const RenderSettings& settings,
                                      const RestirLightTile& tile, uint32_t tilePixels, const RestirVertex& vertex,
                                      RestirRandom& random, uint32_t& rays) {
  if (!vertex.usable) return {};
  ReservoirStream stream;
  const LightSampleContext ctx{vertex.position, vertex.bsdf.normal()};
  const uint32_t candidateCount = restirLightCandidates(scene);
  const float candidates = float(candidateCount);
  const float pOthers =
      scene.environmentSelectProbability +
      scene.directionalSelectProbability * float(scene.punctualLightCount - scene.boundedPunctualLightCount);
  const bool anyBounded = scene.boundedSelectProbability > 0.0f;
  const uint32_t start = uint32_t(random.next1D() * float(tilePixels)) % tilePixels;
  for (uint32_t i = 0; i < candidateCount; ++i) {
    const float uSelect = random.next1D();
    const float uKeep = random.next1D();
    RestirSample sample;
    RestirLightAt light;
    float lightPdf;
    if (uSelect < pOthers || !anyBounded) {
      const LightSample ls = sampleLight(scene, settings.lightSampler, ctx, uSelect, random.next2D());
      if (!ls.valid) continue;
      sample = restirSampleOf(ls);
      light = restirLightAt(scene, sample, vertex.position);
      lightPdf = ls.pdf;
    } else {
      const PresampledLight& presampled = tile.lights[(start + i * tilePixels / candidateCount) % tilePixels];
      if (presampled.light == kRestirNoLight) continue;
      sample.light = presampled.light;
      sample.coordinates = {presampled.barycentrics.x, presampled.barycentrics.y, 0.0f};
      light = sample.light < scene.lightCount ? restirLightAt(presampled.point, vertex.position)
                                              : restirLightAt(scene, sample, vertex.position);
      lightPdf = presampledCandidatePdf(scene, sample.light, presampled.pdf, light);
    }
    Vec3 value;
    const BsdfEval e = vertex.contribution(light, value);
    const float target = luminance(value);
    if (!(target > 0.0f)) continue;
    const float bsdfPdf = light.isPunctual ? 0.0f : e.pdf;
    stream.add(sample, target / (candidates * lightPdf + bsdfPdf), target * light.jacobian, uKeep);
  }

  const float uChoice = random.next1D();
  const Vec2 uBsdf = random.next2D();
  const float uKeep = random.next1D();
  const BsdfSample bs = vertex.bsdf.sample(vertex.wo, uChoice, uBsdf);
  if (bs.valid && !bs.isDelta && bs.pdf > 0.0f && !isBlack(bs.f)) {
    const Ray ray{offsetRayOrigin(vertex.position, vertex.geometricNormal, bs.wi), bs.wi, 0.0f, kInf};
    Hit hit;
    ++rays;
    RestirSample sample;
    if (tracer.intersect(ray, hit, passThroughBits(scene, random))) {
      const uint32_t index = findLightIndex(scene, hit.instanceId, hit.primitiveId);
      if (index < scene.lightCount) sample = {index, {hit.b1, hit.b2, 0.0f}};
    } else if (scene.environmentSelectProbability > 0.0f) {
      sample = {kRestirEnvironment, bs.wi};
    }
    if (sample.light != kRestirNoLight) {
      const RestirLightAt light = restirLightAt(scene, sample, vertex.position);
      Vec3 value;
      const BsdfEval e = vertex.contribution(light, value);
      const float target = luminance(value);
      if (target > 0.0f) {
        const float lightPdf = restirLightPdf(scene, settings.lightSampler, tile.region, sample, light);
        stream.add(sample, target / (candidates * lightPdf + e.pdf), target * light.jacobian, uKeep);
      }
    }
  }

  Reservoir r = stream.finish(1.0f);
  if (r.weight > 0.0f) {
    const RestirLightAt light = restirLightAt(scene, r.sample, vertex.position);
    if (!restirVisible(scene, tracer, vertex, light, random, rays)) r.weight = 0.0f;
  }
  return r;
}

// Combines a pixel's own (canonical) reservoir with those of `neighbours` other pixels (the previous sample's at the
// reprojected pixel, or nearby pixels of this sample), added one by one, by generalized RIS. Unbiased mode: pairwise
// MIS with confidences, k = neighbours, c the canonical pixel, i a neighbour, M their confidences and
// Q(x) = p-hat(x) V(x) at each one's own surface:
//   m_i(x) = 1/k * M_i Q_i(x) / (M_i Q_i(x) + M_c/k Q_c(x)),
//   m_c(x) = 1/k * sum_i (M_c/k) Q_c(x) / (M_i Q_i(x) + M_c/k Q_c(x)),
// which sum to 1 wherever Q_c(x) > 0, the only place the pixel's integrand lives. A neighbour's resampling weight is
// m_i(y_i) Q_c(y_i) W_i, the canonical's m_c(y_c) p-hat_c(y_c) W_c; the result's contribution weight is their sum
// over the kept sample's target, and it is visible from c. Evaluating a neighbour's Q at its own sample needs no
// visibility ray (its reservoir's sample is visible from it); the two cross terms each need one.
// Biased mode: resampling weights M_i p-hat_c(y_i) W_i (unshadowed), normalised by the confidence sum.
template <class Tracer>
struct ReservoirReuse {
  const SceneView& scene;
  const Tracer& tracer;
  const RestirVertex& centre;
  Reservoir canonical;
  float canonicalTarget = 0.0f;  // p-hat_c(y_c)
  float neighbours;
  bool biased;
  RestirRandom& random;
  uint32_t& rays;
  ReservoirStream stream;
  float canonicalMis = 0.0f;
  float confidence;

  CANDELA_FN ReservoirReuse(const SceneView& s, const Tracer& t, const RestirVertex& c, const Reservoir& own,
                            uint32_t neighbourCount, bool biasedWeights, RestirRandom& rng, uint32_t& rayCount)
      : scene(s),
        tracer(t),
        centre(c),
        canonical(own),
        neighbours(float(neighbourCount)),
        biased(biasedWeights),
        random(rng),
        rays(rayCount),
        confidence(own.confidence) {
    RestirLightAt light;
    if (canonical.weight > 0.0f) canonicalTarget = centre.target(scene, canonical.sample, light);
  }

  // Adds the reservoir `r` of the pixel whose primary surface is `surface`; only the unbiased weights rebuild that
  // surface's shading point.
  CANDELA_FN void add(const RenderSettings& settings, const PrimarySurface& surface, const Reservoir& r) {
    confidence += r.confidence;
    const float uKeep = random.next1D();
    if (biased) {
      RestirLightAt atCentre;
      const float target = r.weight > 0.0f ? centre.target(scene, r.sample, atCentre) : 0.0f;
      stream.add(r.sample, target * r.weight * r.confidence, target, uKeep);
      return;
    }
    const RestirVertex neighbour(scene, settings, surface);
    const float canonicalShare = canonical.confidence / neighbours;
    if (r.weight > 0.0f) {
      RestirLightAt atNeighbour, atCentre;
      const float own = neighbour.target(scene, r.sample, atNeighbour);
      float atC = centre.target(scene, r.sample, atCentre);
      if (atC > 0.0f && !restirVisible(scene, tracer, centre, atCentre, random, rays)) atC = 0.0f;
      const float denominator = r.confidence * own + canonicalShare * atC;
      const float mis = denominator > 0.0f ? r.confidence * own / (neighbours * denominator) : 0.0f;
      stream.add(r.sample, mis * atC * r.weight, atC, uKeep);
    }
    if (canonicalTarget > 0.0f) {
      RestirLightAt atNeighbour;
      float there = neighbour.target(scene, canonical.sample, atNeighbour);
      if (there > 0.0f && !restirVisible(scene, tracer, neighbour, atNeighbour, random, rays)) there = 0.0f;
      canonicalMis +=
          canonicalShare * canonicalTarget / (neighbours * (r.confidence * there + canonicalShare * canonicalTarget));
    }
  }

  CANDELA_FN Reservoir finish() {
    if (neighbours == 0.0f) return canonical;
    const float uKeep = random.next1D();
    if (biased) {
      stream.add(canonical.sample, canonicalTarget * canonical.weight * canonical.confidence, canonicalTarget, uKeep);
      return stream.finish(confidence, confidence);
    }
    stream.add(canonical.sample, canonicalMis * canonicalTarget * canonical.weight, canonicalTarget, uKeep);
    return stream.finish(confidence);
  }
};

// Whether two primary surfaces are alike enough to reuse each other's reservoirs: both lit by ReSTIR, normals within
// kRestirNormalSimilarity, and `other`'s distance from its camera within kRestirDepthSimilarity of `expectedDepth`,
// the distance at which it would lie if it were the same point as `surface`.
CANDELA_FN bool restirSimilar(const PrimarySurface& surface, const PrimarySurface& other, float expectedDepth) {
  if (!surface.found || !other.found) return false;
  if (!(dot(surface.normal, other.normal) >= kRestirNormalSimilarity)) return false;
  return fabsf(other.hit.t - expectedDepth) <= kRestirDepthSimilarity * expectedDepth;
}

// The pixel of `camera` (width x height) that sees the point p, as (column, row); false where p is behind the camera
// or outside the image. Through the lens's centre for a thin lens.
CANDELA_FN bool projectToPixel(const Camera& camera, uint32_t width, uint32_t height, Vec3 p, uint32_t& column,
                               uint32_t& row) {
  // p - position = a.x * forward' + a.y * right + a.z * up, with forward' the forward axis (unit for an
  // orthographic camera); for a perspective one the film offsets are a.y / a.x and a.z / a.x.
  const Vec3 f = camera.orthographic ? normalize(camera.forward) : camera.forward;
  const Vec3 d = p - camera.position;
  const float det = dot(f, cross(camera.right, camera.up));
  if (!(fabsf(det) > 0.0f)) return false;
  const Vec3 a{dot(d, cross(camera.right, camera.up)) / det, dot(f, cross(d, camera.up)) / det,
               dot(f, cross(camera.right, d)) / det};
  if (!(a.x > 0.0f)) return false;
  const float sx = camera.orthographic ? a.y : a.y / a.x, sy = camera.orthographic ? a.z : a.z / a.x;
  const float px = (sx + 1.0f) * 0.5f * float(width), py = (1.0f - sy) * 0.5f * float(height);
  if (!(px >= 0.0f && px < float(width) && py >= 0.0f && py < float(height))) return false;
  column = uint32_t(px);
  row = uint32_t(py);
  return column < width && row < height;
}

// No pixel of the previous sample to reuse.
constexpr uint32_t kNoHistory = 0xFFFFFFFFu;

// The previous sample's pixel whose reservoir the pixel with primary surface `surface` (point `position`) may reuse:
// the one that saw the point, where its own surface is alike (restirSimilar: geometry that moved in front, or away,
// fails); kNoHistory where there is none, and after a restart that dropped the history.
CANDELA_FN uint32_t temporalHistoryPixel(const RenderSettings& settings, const RestirView& restir,
                                         const PrimarySurface& surface, Vec3 position) {
  uint32_t column, row;
  if (!restir.hasHistory || !surface.found ||
      !projectToPixel(restir.previousCamera, settings.width, settings.height, position, column, row))
    return kNoHistory;
  const uint32_t previous = row * settings.width + column;
  const PrimarySurface& before = restir.previousSurfaces[previous];
  return restirSimilar(surface, before, length(position - before.ray.origin)) ? previous : kNoHistory;
}

// Pass 1 of a sample: pixel (x, y)'s camera ray and its primary surface, written to restir.surfaces; returns the
// rays traced.
template <class Tracer>
CANDELA_FN uint32_t restirPrimaryPass(const SceneView& scene, const Tracer& tracer, const Camera& camera,
                                      const RenderSettings& settings, const RestirView& restir, uint32_t x, uint32_t y,
                                      uint32_t sampleIndex) {
  const uint32_t pixel = y * settings.width + x;
  PathSampler sampler(pixel, sampleIndex, settings.seed, settings.sampler);
  PrimarySurface surface;
  surface.ray = pixelSampleRay(camera, settings, x, y, sampler);
  uint32_t rays = 0;
  if (isTraceableCameraRay(surface.ray)) {
    const uint32_t bits = passThroughBits(scene, sampler);
    surface.found = tracer.intersect(surface.ray, surface.hit, bits) ? 1u : 0u;
    surface.coneWidth = cameraRayCone(camera, settings.height).widthAt(surface.hit.t);
    surface.dimension = sampler.dimension();
    ++rays;
  }
  const RestirVertex vertex(scene, settings, surface);
  if (vertex.usable) {
    surface.normal = vertex.bsdf.normal();
    surface.position = vertex.position;
  }
  restir.surfaces[pixel] = surface;
  return rays;
}

// Pass 3 of a sample, after the primary pass and the presampling (restirPresamplePass) over the whole image: pixel
// (x, y)'s initial candidates, visibility, temporal reuse. Writes restir.reservoirs at the pixel; returns the rays
// traced.
template <class Tracer>
CANDELA_FN uint32_t restirCandidatePass(const SceneView& scene, const Tracer& tracer, const RenderSettings& settings,
                                        const RestirView& restir, uint32_t x, uint32_t y, uint32_t sampleIndex) {
  const uint32_t pixel = y * settings.width + x;
  const PrimarySurface& surface = restir.surfaces[pixel];
  const RestirVertex vertex(scene, settings, surface);
  RestirRandom random(pixel, sampleIndex, settings.seed, uint32_t(RestirPass::Candidates));
  const uint32_t tile = restirTileOf(settings, x, y);
  uint32_t rays = 0;
  Reservoir r = initialReservoir(scene, tracer, settings, restir.lightTiles[tile], restirTilePixels(settings, tile),
                                 vertex, random, rays);

  const uint32_t previous = temporalHistoryPixel(settings, restir, surface, vertex.position);
  if (previous != kNoHistory) {
    Reservoir history = restir.history[previous];
    history.confidence = fminf(history.confidence, kRestirHistoryCap * r.confidence);
    ReservoirReuse<Tracer> reuse(scene, tracer, vertex, r, 1, settings.restir == RestirMode::DiBiased, random, rays);
    reuse.add(settings, restir.previousSurfaces[previous], history);
    r = reuse.finish();
  }
  restir.reservoirs[pixel] = r;
  return rays;
}

// Whether the ray that the primary vertex's BSDF sample would trace can add nothing, and is not traced: at the last
// bounce (maxDepth 1) a ray off a non-delta lobe ends at a vertex that neither samples lights nor scatters, and
// whatever emission it finds the reservoir has counted (kDirectLightCounted gives it weight 0), unless the path still
// has its denoiser guides to record there. Only a delta lobe's ray, whose emission counts in full, is traced.
template <bool kWithAovs>
CANDELA_FN bool lastRayFindsNothing(const RenderSettings& settings, const VertexScatter& scatter,
                                    const PathAovState& a) {
  return settings.maxDepth == 1 && scatter.directFromReservoir && !scatter.sample.isDelta &&
         !(kWithAovs && a.aovsPending);
}

// Pass 4 of a sample: spatial reuse at pixel (x, y), the result kept as the next sample's history, and the pixel's
// path, its primary vertex lit by the reservoir (shadeVertex's directFromReservoir says why nothing is counted twice).
template <bool kWithAovs, class Tracer>
CANDELA_FN PathResult restirShadePass(const SceneView& scene, const Tracer& tracer, const Camera& camera,
                                      const RenderSettings& settings, const RestirView& restir, uint32_t x, uint32_t y,
                                      uint32_t sampleIndex) {
  const uint32_t pixel = y * settings.width + x;
  const PrimarySurface surface = restir.surfaces[pixel];
  if (!isTraceableCameraRay(surface.ray)) {
    restir.history[pixel] = {};
    return droppedSample();
  }
  const RestirVertex vertex(scene, settings, surface);
  const bool biased = settings.restir == RestirMode::DiBiased;
  Reservoir r = restir.reservoirs[pixel];
  uint32_t restirRays = 0;
  if (vertex.usable) {
    RestirRandom random(pixel, sampleIndex, settings.seed, uint32_t(RestirPass::Shade));
    uint32_t chosen[kRestirSpatialNeighbours];
    uint32_t count = 0;
    for (uint32_t i = 0; i < kRestirSpatialNeighbours; ++i) {
      const Vec2 offset = sampleUniformDiskConcentric(random.next2D());
      const int nx = int(x) + int(floorf(offset.x * kRestirSpatialRadius + 0.5f));
      const int ny = int(y) + int(floorf(offset.y * kRestirSpatialRadius + 0.5f));
      if (nx < 0 || ny < 0 || nx >= int(settings.width) || ny >= int(settings.height) || (nx == int(x) && ny == int(y)))
        continue;
      const uint32_t n = uint32_t(ny) * settings.width + uint32_t(nx);
      if (restirSimilar(surface, restir.surfaces[n], surface.hit.t)) chosen[count++] = n;
    }
    ReservoirReuse<Tracer> reuse(scene, tracer, vertex, r, count, biased, random, restirRays);
    for (uint32_t i = 0; i < count; ++i) reuse.add(settings, restir.surfaces[chosen[i]], restir.reservoirs[chosen[i]]);
    r = reuse.finish();
    // The 1/M weights keep samples that may be occluded from here: their visibility is tested before shading.
    if (biased && r.weight > 0.0f) {
      const RestirLightAt light = restirLightAt(scene, r.sample, vertex.position);
      if (!restirVisible(scene, tracer, vertex, light, random, restirRays)) r.weight = 0.0f;
    }
  }
  restir.history[pixel] = r;

  PathSampler sampler(pixel, sampleIndex, settings.seed, settings.sampler);
  sampler.setDimension(surface.dimension);
  PathState s = startPath(cameraRayCone(camera, settings.height));
  PathAovState a;
  Ray ray = surface.ray;
  if (!surface.found) {
    followPath<kWithAovs, true>(scene, tracer, settings, s, a, sampler, ray, 0u, false, surface.hit);
  } else {
    ShadowQuery shadow;
    VertexScatter scatter;
    const bool more =
        shadeVertex<kWithAovs>(scene, settings, s, a, sampler, ray, true, surface.hit, shadow, scatter, vertex.usable);
    if (vertex.usable && r.weight > 0.0f && settings.maxDepth > 0) {
      const RestirLightAt light = restirLightAt(scene, r.sample, vertex.position);
      Vec3 value;
      vertex.contribution(light, value);
      s.radiance += s.beta * value * (light.jacobian * r.weight);
    }
    if (!isBlack(shadow.contribution) && !tracer.occluded(shadow.ray, shadow.bits)) s.radiance += shadow.contribution;
    uint32_t bits = 0;
    if (more && !lastRayFindsNothing<kWithAovs>(settings, scatter, a) &&
        continuePath<kWithAovs>(scene, settings, s, a, sampler, scatter, ray, bits))
      followPath<kWithAovs, false>(scene, tracer, settings, s, a, sampler, ray, bits);
  }
  PathResult result;
  result.radiance = s.radiance;
  result.rays = s.rays + restirRays;
  if (kWithAovs) {
    result.emitted = a.emitted;
    result.aovs = a.aovs;
  }
  return result;
}

}  // namespace candela
