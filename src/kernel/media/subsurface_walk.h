#pragma once
// Subsurface scattering as a volumetric random walk (Cycles' random walk; Chiang, Kutz and Burley, "Practical and
// Controllable Subsurface Scattering for Production Path Tracing", 2016): a subsurface material is a dielectric
// boundary around a homogeneous medium (Medium::subsurface), and a path that refracts into it walks from
// collision to collision until it reaches the boundary again, where the boundary's BSDF lets it out or reflects
// it back in.
//
// The walk differs from scattering in any other medium in two ways. Its steps do not count towards the path's
// depth (a walk in a dense medium takes hundreds): they have their own bound, past which the path ends, as in
// Cycles. And it samples no light: every shadow ray from inside would end on the material's own boundary, which
// is no interface, so next-event estimation there is wasted work; the phase-sampled direction carries the whole
// estimate (an emitter inside the object is found by it, unweighted). Nor does Russian roulette end a walk: its
// throughput falls only by the medium's albedo.
#include <cstdint>

#include "kernel/media/medium.h"

namespace candela {

// The most collisions one walk takes (Cycles' BSSRDF_MAX_BOUNCES); a path still inside after them ends.
constexpr uint32_t kMaxSubsurfaceSteps = 256;

CANDELA_FN bool isSubsurfaceWalk(const Medium& m) { return m.subsurface != 0; }

}  // namespace candela
