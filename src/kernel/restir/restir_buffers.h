#pragma once
// What ReSTIR DI (kernel/restir/restir_passes.h) keeps per pixel between its passes and from one sample to the
// next, declared once: the per-pixel buffers, their pointers for kernel code (RestirView) and every backend's
// storage of them are made from CANDELA_RESTIR_BUFFERS. For host and device code alike.
#include <cstdint>

#include "core/math.h"
#include "kernel/camera.h"
#include "kernel/hit.h"

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
  uint32_t dimension = 0;  // the pixel sampler's next dimension after the camera ray and its pass-through bits
  uint32_t found = 0;      // 0: the camera ray escaped, or could not be traced
};

// ReSTIR's per-pixel buffers, one X(Type, name, description) each, width x height elements, row-major:
//   surfaces          this sample's primary surfaces (written by the candidate pass);
//   previousSurfaces  the previous sample's, where the temporal reuse evaluates its history (the backend swaps the
//                     two after every sample);
//   reservoirs        after initial candidates and temporal reuse, read by the spatial pass at the neighbours;
//   history           after spatial reuse: what the pixel was shaded with, and the next sample's temporal history.
#define CANDELA_RESTIR_BUFFERS(X)                                                        \
  X(PrimarySurface, surfaces, "this sample's primary surfaces")                          \
  X(PrimarySurface, previousSurfaces, "the previous sample's primary surfaces")          \
  X(Reservoir, reservoirs, "the reservoirs after initial candidates and temporal reuse") \
  X(Reservoir, history, "the reservoirs after spatial reuse, the next sample's history")

// Pointers to the buffers in host or device memory, with the previous sample's camera (temporal reprojection).
struct RestirView {
#define CANDELA_RESTIR_VIEW_POINTER(Type, name, description) Type* name = nullptr;
  CANDELA_RESTIR_BUFFERS(CANDELA_RESTIR_VIEW_POINTER)
#undef CANDELA_RESTIR_VIEW_POINTER
  Camera previousCamera;
  uint32_t hasHistory = 0;  // 0 after a restart that invalidates the history (scene, settings, size)
};

}  // namespace candela
