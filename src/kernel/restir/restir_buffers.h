#pragma once
// What ReSTIR DI (kernel/restir/restir_passes.h) keeps per pixel and per screen tile between its passes and from one
// sample to the next, declared once: the buffers, their pointers for kernel code (RestirView) and every backend's
// storage of them are made from CANDELA_RESTIR_BUFFERS. For host and device code alike.
#include <cstdint>

#include "core/math.h"
#include "kernel/camera.h"
#include "kernel/hit.h"
#include "kernel/light_bounds.h"

namespace candela {

// RestirSample::light of an environment direction, and of no sample at all.
constexpr uint32_t kRestirEnvironment = 0xFFFFFFFEu;
constexpr uint32_t kRestirNoLight = 0xFFFFFFFFu;

// A light sample as a reservoir keeps it, in terms that do not depend on the shading point, so that any pixel can
// evaluate it (the identity shift: no Jacobian between pixels). `light` is a bounded or directional light as
// LightSample::lightIndex numbers them (a triangle below lightCount, then the punctual lights), or
// kRestirEnvironment. `coordinates`: a triangle's point as the barycentrics of its vertices 1 and 2 (x, y); the
// environment's direction; unused for a punctual light. The measure of the sample space is the area on triangles,
// the solid angle on the environment, and counting on the punctual lights.
struct RestirSample {
  uint32_t light = kRestirNoLight;
  Vec3 coordinates;
};

// A reservoir: its sample, that sample's unbiased contribution weight (W, in the measure above; 0 where the
// reservoir holds nothing) and its confidence (M: how many initial reservoirs of one sample each it stands for).
struct Reservoir {
  RestirSample sample;
  float weight = 0.0f;
  float confidence = 0.0f;
};

// What a pixel's camera ray found, enough to rebuild its shading point (and its BSDF) in any later pass and from any
// pixel: the ray, its hit, the ray cone's width there (texture filtering), and where the path's sampler goes on.
struct PrimarySurface {
  Ray ray;
  Hit hit;
  float coneWidth = 0.0f;
  Vec3 normal;             // the BSDF's shading normal where ReSTIR lights the surface (RestirVertex::usable), else 0
  Vec3 position;           // the shading point there
  uint32_t dimension = 0;  // the pixel sampler's next dimension after the camera ray and its pass-through bits
  uint32_t found = 0;      // 0: the camera ray escaped, or could not be traced

  CANDELA_FN bool lit() const { return normal.x != 0.0f || normal.y != 0.0f || normal.z != 0.0f; }
};

// Light candidates are drawn from samples presampled once per sample index for each square screen tile of this many
// pixels a side and shared by its pixels (as RTXDI presamples local lights): a walk down the light BVH per
// presampled light, not per candidate. One presampled light per pixel of a tile.
constexpr uint32_t kRestirTileSize = 8;
constexpr uint32_t kRestirPresampledLights = kRestirTileSize * kRestirTileSize;

// A point on an emissive triangle as any shading point sees it (kernel/restir/restir_target.h, restirLightPoint):
// where it is, the triangle's unit front normal, and the radiance it emits there (its emission texture applied).
struct RestirLightPoint {
  Vec3 position;
  Vec3 normal;
  Vec3 radiance;
};

// A presampled bounded light (kernel/restir/restir_presampling.h): `light` as RestirSample::light numbers it, the point
// on a triangle as the barycentrics of its vertices 1 and 2 and as `point` (so that a candidate reads neither the
// light table nor the emission texture), and `pdf`, the density with which the tile's presampling picks it: in area
// measure on a triangle (the choice of the triangle included), a punctual light's probability; neither includes the
// probability of the bounded lights among all lights.
struct PresampledLight {
  uint32_t light = kRestirNoLight;
  Vec2 barycentrics;
  float pdf = 0.0f;
  RestirLightPoint point;
};

// A screen tile's presampled lights, and the region of its pixels' primary surfaces for which they were drawn.
struct RestirLightTile {
  LightSampleContext region;
  PresampledLight lights[kRestirPresampledLights];
};

// Elements of the buffers of a width x height image: one per pixel, or one per screen tile.
CANDELA_FN uint32_t restirTilesAcross(uint32_t pixels) { return (pixels + kRestirTileSize - 1) / kRestirTileSize; }
CANDELA_FN size_t restirPixelCount(uint32_t width, uint32_t height) { return size_t(width) * height; }
CANDELA_FN size_t restirTileCount(uint32_t width, uint32_t height) {
  return size_t(restirTilesAcross(width)) * restirTilesAcross(height);
}

// ReSTIR's buffers, one X(Type, name, count, description) each, count(width, height) elements, row-major:
//   surfaces          this sample's primary surfaces (written by the primary pass);
//   previousSurfaces  the previous sample's, where the temporal reuse evaluates its history (the backend swaps the
//                     two after every sample);
//   lightTiles        this sample's presampled lights, per screen tile;
//   reservoirs        after initial candidates and temporal reuse, read by the spatial pass at the neighbours;
//   history           after spatial reuse: what the pixel was shaded with, and the next sample's temporal history.
#define CANDELA_RESTIR_BUFFERS(X)                                                                          \
  X(PrimarySurface, surfaces, restirPixelCount, "this sample's primary surfaces")                          \
  X(PrimarySurface, previousSurfaces, restirPixelCount, "the previous sample's primary surfaces")          \
  X(RestirLightTile, lightTiles, restirTileCount, "the presampled lights of the screen tiles")             \
  X(Reservoir, reservoirs, restirPixelCount, "the reservoirs after initial candidates and temporal reuse") \
  X(Reservoir, history, restirPixelCount, "the reservoirs after spatial reuse, the next sample's history")

// Pointers to the buffers in host or device memory, with the previous sample's camera (temporal reprojection).
struct RestirView {
#define CANDELA_RESTIR_VIEW_POINTER(Type, name, count, description) Type* name = nullptr;
  CANDELA_RESTIR_BUFFERS(CANDELA_RESTIR_VIEW_POINTER)
#undef CANDELA_RESTIR_VIEW_POINTER
  Camera previousCamera;
  // Whether this sample reuses the history: not after a restart that invalidates it (scene, settings, size), and only
  // for the first sample of a film (after a camera move, or the first of a still). Samples that the film averages
  // must not reuse each other: the history ties a pixel's successive samples to the same light points, and their
  // mean then converges more slowly than the same samples without it (docs/performance.md, 'ReSTIR DI').
  uint32_t hasHistory = 0;
};

}  // namespace candela
