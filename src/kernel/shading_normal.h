#pragma once
#include "core/math.h"
#include "kernel/interaction.h"

namespace candela {

// Bends shading normal `n` towards geometric normal `ng` just enough that the mirror reflection of `wo` about
// it stays above the geometric surface (Cycles' ensure_valid_reflection). A normal map or strongly
// interpolated normals can tilt n so far that reflected directions point into the surface; those paths were
// lost, and normal-mapped metal got black rims. `ng` and `n` must face wo's side. The reflection is lifted to
// a small threshold above the surface (no higher than wo itself), and n is left alone where that already holds.
CANDELA_FN Vec3 ensureValidReflection(Vec3 ng, Vec3 wo, Vec3 n) {
  Vec3 r = n * (2.0f * dot(n, wo)) - wo;
  float threshold = fminf(0.9f * dot(ng, wo), 0.01f);
  if (dot(ng, r) >= threshold) return n;
  // In the frame with ng as z and n in the x-z plane, find n' = (x, 0, z), x^2 + z^2 = 1, with
  // 2 dot(n', wo) z - wo.z = threshold: z^2 = (c +- b) / (2 a), a = wo.x^2 + wo.z^2, b = sqrt(wo.x^2 (a - t^2)),
  // c = wo.z t + a.
  Vec3 x = n - ng * dot(n, ng);
  float xLen = length(x);
  if (!(xLen > 0.0f)) return ng;
  x = x / xLen;
  float ix = dot(wo, x), iz = dot(wo, ng);
  float a = ix * ix + iz * iz;
  if (!(a > 0.0f)) return ng;
  float b = sqrtf(fmaxf(0.0f, ix * ix * (a - threshold * threshold)));
  float c = iz * threshold + a;
  float z1 = 0.5f * (b + c) / a, z2 = 0.5f * (c - b) / a;
  bool valid1 = z1 > 1e-5f && z1 <= 1.0f + 1e-5f, valid2 = z2 > 1e-5f && z2 <= 1.0f + 1e-5f;
  auto normalFor = [](float zz) { return Vec2{sqrtf(fmaxf(0.0f, 1.0f - zz)), sqrtf(fmaxf(0.0f, zz))}; };
  Vec2 chosen;
  if (valid1 && valid2) {
    Vec2 n1 = normalFor(z1), n2 = normalFor(z2);
    float r1 = 2.0f * (n1.x * ix + n1.y * iz) * n1.y - iz, r2 = 2.0f * (n2.x * ix + n2.y * iz) * n2.y - iz;
    // Both lift the reflection: keep the shallower one, the closer to n. Else the one that lifts it.
    chosen = (r1 >= 1e-5f && r2 >= 1e-5f) ? (r1 < r2 ? n1 : n2) : (r1 > r2 ? n1 : n2);
  } else if (valid1 || valid2) {
    chosen = normalFor(valid1 ? z1 : z2);
  } else {
    return ng;
  }
  return normalize(x * chosen.x + ng * chosen.y);
}

// ensureValidReflection on wo's side of the surface; the shading normal stays on the geometric normal's side.
CANDELA_FN void keepReflectionAboveSurface(SurfaceInteraction& si, Vec3 wo) {
  float side = dot(si.geometricNormal, wo) < 0.0f ? -1.0f : 1.0f;
  si.shadingNormal = ensureValidReflection(si.geometricNormal * side, wo, si.shadingNormal * side) * side;
}

// Where a path goes on after the BSDF sampled wi (`n` is the BSDF's normal, facing wo): wi itself when the
// shading and geometric normals agree on which side of the surface it is. A rough lobe about a bent shading
// normal still sends some reflections into the surface; those are mirrored across the geometric surface, so
// the path keeps the weight the BSDF gave it instead of ending black. Returns false when the path must end (a
// transmission the geometric surface says is a reflection).
CANDELA_FN bool continuePathTowards(Vec3 wi, Vec3 wo, Vec3 ng, Vec3 n, Vec3& next) {
  float woSide = dot(wo, ng);
  bool geometricAbove = dot(wi, ng) * woSide > 0.0f, shadingAbove = dot(wi, n) > 0.0f;
  next = wi;
  if (geometricAbove == shadingAbove) return true;
  if (!shadingAbove) return false;
  Vec3 up = woSide < 0.0f ? -ng : ng;
  next = wi - up * (2.0f * dot(wi, up));
  return dot(next, up) > 0.0f;
}

}  // namespace candela
