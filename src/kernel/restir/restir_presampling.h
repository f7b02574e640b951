#pragma once
// ReSTIR DI's light candidates, presampled per screen tile (RTXDI's local-light presampling, with the light BVH in
// place of its power texture): once per sample index, each tile of kRestirTileSize^2 pixels draws one bounded light
// per pixel from the distribution of the light BVH (or power table) for the region its pixels' primary surfaces
// occupy, and a pixel's light candidates are then picked uniformly among its tile's. A candidate costs one walk down
// the light BVH per pixel instead of one per candidate.
//
// Unbiasedness: a candidate picked uniformly among the tile's presampled lights, each drawn from the tile's
// distribution p_tile, is itself distributed by p_tile, whose density at any light point is known
// (presampledLightPdf); resampled importance sampling needs no more of its candidates than that each one's marginal
// density is the one its weight divides by, so that the candidates may share presampled lights. p_tile is positive
// wherever any point of the region can receive light (lightImportance of a region), so wherever a pixel's integrand
// is.
#include "core/sampling.h"
#include "kernel/lights.h"
#include "kernel/restir/restir_buffers.h"
#include "kernel/restir/restir_random.h"
#include "kernel/restir/restir_target.h"

namespace candela {

// The screen tile of pixel (x, y), and the index of the pixel within it, row by row (a backend that presamples
// with one thread per pixel gives each its light of the tile by it).
CANDELA_FN uint32_t restirTileOf(const RenderSettings& settings, uint32_t x, uint32_t y) {
  return (y / kRestirTileSize) * restirTilesAcross(settings.width) + x / kRestirTileSize;
}
CANDELA_FN uint32_t restirIndexInTile(const RenderSettings& settings, uint32_t x, uint32_t y) {
  const uint32_t x0 = x - x % kRestirTileSize;
  const uint32_t tileWidth = settings.width - x0 < kRestirTileSize ? settings.width - x0 : kRestirTileSize;
  return (y % kRestirTileSize) * tileWidth + x % kRestirTileSize;
}

// How many pixels (and so presampled lights) tile `tile` has: fewer than kRestirPresampledLights at the right and
// bottom edges of the image.
CANDELA_FN uint32_t restirTilePixels(const RenderSettings& settings, uint32_t tile) {
  const uint32_t across = restirTilesAcross(settings.width);
  const uint32_t x0 = (tile % across) * kRestirTileSize, y0 = (tile / across) * kRestirTileSize;
  const uint32_t w = settings.width - x0 < kRestirTileSize ? settings.width - x0 : kRestirTileSize;
  const uint32_t h = settings.height - y0 < kRestirTileSize ? settings.height - y0 : kRestirTileSize;
  return w * h;
}

// The region of the points that tile `tile`'s pixels light through ReSTIR (RestirVertex::usable), as a sphere around
// their bounding box, with the cone of their shading normals (none where they spread over 90 degrees or more from
// their mean); a radius below 0 where there are none. The points are those the primary pass has written to
// restir.surfaces.
CANDELA_FN LightSampleContext restirTileRegion(const RenderSettings& settings, const RestirView& restir,
                                               uint32_t tile) {
  const uint32_t across = restirTilesAcross(settings.width);
  const uint32_t x0 = (tile % across) * kRestirTileSize, y0 = (tile / across) * kRestirTileSize;
  Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf}, normals{};
  bool any = false;
  for (uint32_t y = y0; y < y0 + kRestirTileSize && y < settings.height; ++y)
    for (uint32_t x = x0; x < x0 + kRestirTileSize && x < settings.width; ++x) {
      const PrimarySurface& s = restir.surfaces[y * settings.width + x];
      if (!s.lit()) continue;
      lo = {fminf(lo.x, s.position.x), fminf(lo.y, s.position.y), fminf(lo.z, s.position.z)};
      hi = {fmaxf(hi.x, s.position.x), fmaxf(hi.y, s.position.y), fmaxf(hi.z, s.position.z)};
      normals += s.normal;
      any = true;
    }
  LightSampleContext region;
  region.radius = -1.0f;
  if (!any) return region;
  region.p = (lo + hi) * 0.5f;
  region.radius = 0.5f * length(hi - lo) * 1.0001f;  // a point at a corner stays within it after rounding
  const float normalsLength = length(normals);
  if (!(normalsLength > 0.0f)) return region;
  const Vec3 axis = normals / normalsLength;
  float cosSpread = 1.0f;
  for (uint32_t y = y0; y < y0 + kRestirTileSize && y < settings.height; ++y)
    for (uint32_t x = x0; x < x0 + kRestirTileSize && x < settings.width; ++x) {
      const PrimarySurface& s = restir.surfaces[y * settings.width + x];
      if (s.lit()) cosSpread = fminf(cosSpread, dot(axis, s.normal));
    }
  cosSpread -= 1e-4f;  // rounding leaves every normal within the cone
  if (cosSpread > 0.0f) {
    region.n = axis;
    region.cosNormalSpread = cosSpread;
    region.sinNormalSpread = sqrtf(1.0f - cosSpread * cosSpread);
  }
  return region;
}

// A bounded light for `region`, drawn with uSelect (the light) and uPoint (a point on a triangle, uniform by area: a
// point's density must not depend on the pixel that uses it); none where no bounded light reaches the region.
CANDELA_FN PresampledLight presampleLight(const SceneView& scene, LightSamplerKind kind, LightSampleContext region,
                                          float uSelect, Vec2 uPoint) {
  PresampledLight presampled;
  if (!(region.radius >= 0.0f) || boundedLightCount(scene) == 0) return presampled;
  const SampledLight picked = sampleBoundedLight(scene, kind, region, uSelect);
  if (!(picked.pmf > 0.0f)) return presampled;
  presampled.light = picked.index;
  if (picked.index >= scene.lightCount) {
    presampled.pdf = picked.pmf;
    return presampled;
  }
  presampled.barycentrics = sampleUniformTriangle(uPoint);
  presampled.pdf = picked.pmf / scene.lights[picked.index].area;
  presampled.point = restirLightPoint(scene, picked.index, presampled.barycentrics);
  return presampled;
}

// The density with which presampleLight() picks a point of the bounded light `light` for `region`: in area measure
// on a triangle, a punctual light's probability.
CANDELA_FN float presampledLightPdf(const SceneView& scene, LightSamplerKind kind, LightSampleContext region,
                                    uint32_t light) {
  if (!(region.radius >= 0.0f)) return 0.0f;
  const float pmf = boundedLightPmf(scene, kind, region, light);
  return light < scene.lightCount ? pmf / scene.lights[light].area : pmf;
}

// The solid-angle density (a punctual light's probability) with which one light candidate of a pixel, seen there as
// `light`, is the bounded light `index` where the presampling picks it with density `presampledPdf`.
CANDELA_FN float presampledCandidatePdf(const SceneView& scene, uint32_t index, float presampledPdf,
                                        const RestirLightAt& light) {
  const float pdf = scene.boundedSelectProbability * presampledPdf;
  if (index >= scene.lightCount) return pdf;
  return light.jacobian > 0.0f ? pdf / light.jacobian : 0.0f;  // from area to solid angle at the pixel
}

// The density with which one light candidate of a pixel in a tile whose region is `region` (initialReservoir's light
// strategy) finds `sample`, seen from the pixel as `light`: in solid angle, a punctual light's probability. The light
// strategy picks the environment, a directional light or the bounded lights as sampleLight() does, and a bounded
// light among the tile's presampled ones.
CANDELA_FN float restirLightPdf(const SceneView& scene, LightSamplerKind kind, LightSampleContext region,
                                const RestirSample& sample, const RestirLightAt& light) {
  if (sample.light == kRestirEnvironment) return environmentPdf(scene, light.wi);
  if (sample.light >= scene.lightCount + scene.boundedPunctualLightCount) return scene.directionalSelectProbability;
  return presampledCandidatePdf(scene, sample.light, presampledLightPdf(scene, kind, region, sample.light), light);
}

// Presamples lights [first, end) of tile `tile` (and with the first, writes the tile's region), for sample index
// `sampleIndex`. Random numbers: white noise keyed by the tile, the sample index and the presampled light; the
// light's choice stratified over the tile's presampled lights (the i-th of n draws within [i/n, (i+1)/n)), so that
// they spread over the distribution, while one picked uniformly among them is still distributed by p_tile.
CANDELA_FN void restirPresamplePass(const SceneView& scene, const RenderSettings& settings, const RestirView& restir,
                                    uint32_t tile, uint32_t first, uint32_t end, uint32_t sampleIndex) {
  RestirLightTile& out = restir.lightTiles[tile];
  const LightSampleContext region = restirTileRegion(settings, restir, tile);
  if (first == 0) out.region = region;
  const uint32_t count = restirTilePixels(settings, tile);
  for (uint32_t i = first; i < end && i < count; ++i) {
    RestirRandom random(tile * kRestirPresampledLights + i, sampleIndex, settings.seed,
                        uint32_t(RestirPass::Presample));
    const float uSelect = fminf((float(i) + random.next1D()) / float(count), 0.99999994f);
    out.lights[i] = presampleLight(scene, settings.lightSampler, region, uSelect, random.next2D());
  }
}

}  // namespace candela
