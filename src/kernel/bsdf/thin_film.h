#pragma once
#include "kernel/bsdf/fresnel.h"
#include "kernel/kernel_variant.h"

namespace candela {

// Thin-film interference (iridescence) as glTF's KHR_materials_iridescence defines it: Belcour and Barla 2017,
// "A Practical Extension to Microfacet Theory for the Modeling of Varying Iridescence", in the approximation of the
// extension's "iridescent_fresnel" and the Khronos glTF Sample Viewer's evalIridescence. Light from outside (index
// 1) meets a dielectric film of index `filmIor` and thickness `thicknessNm` over a base whose index follows from
// its normal-incidence reflectance `baseF0` (no extinction, also for metals). Both interfaces reflect by Schlick's
// approximation, unpolarised; the Airy reflectance's constant term and first two interference orders are
// integrated over the spectrum analytically, against Gaussian fits of the CIE colour matching functions in Fourier
// space, and returned in linear sRGB.

// The colour matching functions' response to the interference term cos(2 pi opd / lambda + shift), integrated over
// wavelength, over the integral of y-bar (1.0685e-7 m), in linear sRGB. `shift` is per X, Y, Z as in the
// reference. Each lobe is val sqrt(2 pi var) cos(pos phase + shift) exp(-var phase^2), its amplitude given here
// already divided by the normalisation.
CANDELA_FN Vec3 thinFilmSensitivity(float opdNm, Vec3 shift) {
  const float phase = 2.0f * kPi * opdNm * 1.0e-9f;  // per metre
  const float phase2 = phase * phase;
  const float x = 0.84659f * cosf(1.6810e6f * phase + shift.x) * expf(-4.3278e9f * phase2) +
                  0.1538683f * cosf(2.2399e6f * phase + shift.x) * expf(-4.5282e9f * phase2);
  const float y = 1.000222f * cosf(1.7953e6f * phase + shift.y) * expf(-9.3046e9f * phase2);
  const float z = 1.001122f * cosf(2.2084e6f * phase + shift.z) * expf(-6.6121e9f * phase2);
  return {3.2404542f * x - 1.5371385f * y - 0.4985314f * z, -0.9692660f * x + 1.8760108f * y + 0.0415560f * z,
          0.0556434f * x - 0.2040259f * y + 1.0572252f * z};
}

// Reflectance at normal incidence between media of indices a and b.
CANDELA_FN float normalIncidenceReflectance(float a, float b) { return sqr((a - b) / (a + b)); }

// The film's reflectance for light arriving at cosTheta1 to the (micro)surface's normal, in [0, 1] per channel.
// The reference clamps below only; its spectral fit overshoots 1 (by up to 0.28, at grazing angles), which an
// energy-conserving path tracer cannot take, so the result is also clamped above.
CANDELA_FN Vec3 thinFilmFresnel(float cosTheta1, float filmIor, float thicknessNm, Vec3 baseF0) {
  constexpr float kOutsideIor = 1.0f;
  // The film's index tends to the outside's as its thickness goes to zero (the reference's smoothstep over 0.03 nm).
  const float t = clampf(thicknessNm / 0.03f, 0.0f, 1.0f);
  const float eta2 = lerp(t * t * (3.0f - 2.0f * t), kOutsideIor, filmIor);
  const float sin2Theta2 = sqr(kOutsideIor / eta2) * (1.0f - cosTheta1 * cosTheta1);
  if (sin2Theta2 >= 1.0f) return {1, 1, 1};  // total internal reflection
  const float cosTheta2 = sqrtf(1.0f - sin2Theta2);

  // First interface, outside to film; a reflection off a denser medium shifts the phase by pi.
  const float r12 = fresnelSchlick(normalIncidenceReflectance(eta2, kOutsideIor), cosTheta1);
  const float t121 = 1.0f - r12;
  const float phi21 = eta2 < kOutsideIor ? 0.0f : kPi;
  const float opd = 2.0f * eta2 * thicknessNm * cosTheta2;  // optical path difference, nm

  // Second interface, film to base, per channel; then the series' terms.
  float r23[3], phi[3], r123[3], c0[3], cm[3];
  for (int i = 0; i < 3; ++i) {
    const float sqrtF0 = sqrtf(clampf(baseF0[i], 0.0f, 0.9999f));
    const float baseIor = (1.0f + sqrtF0) / (1.0f - sqrtF0);
    r23[i] = fresnelSchlick(normalIncidenceReflectance(baseIor, eta2), cosTheta2);
    phi[i] = phi21 + (baseIor < eta2 ? kPi : 0.0f);
    const float r123Squared = clampf(r12 * r23[i], 1e-5f, 0.9999f);
    r123[i] = sqrtf(r123Squared);
    const float rs = t121 * t121 * r23[i] / (1.0f - r123Squared);
    c0[i] = r12 + rs;  // m = 0: the incoherent sum
    cm[i] = rs - t121;
  }
  Vec3 reflectance{c0[0], c0[1], c0[2]};
  for (int m = 1; m <= 2; ++m) {
    for (int i = 0; i < 3; ++i) cm[i] *= r123[i];
    const Vec3 s = thinFilmSensitivity(float(m) * opd, Vec3{phi[0], phi[1], phi[2]} * float(m));
    reflectance += Vec3{cm[0] * s.x, cm[1] * s.y, cm[2] * s.z} * 2.0f;
  }
  return {clampf(reflectance.x, 0.0f, 1.0f), clampf(reflectance.y, 0.0f, 1.0f), clampf(reflectance.z, 0.0f, 1.0f)};
}

// An iridescent film over a metallic-roughness specular lobe, whose Fresnel term becomes
//   mix(weight, Schlick(f0), mix(metallic, thinFilm(dielectricF0), thinFilm(metalF0)))
// with f0 = mix(metallic, dielectricF0, metalF0): glTF's mix of the iridescent dielectric and conductor layers.
// A weight of 0 (no film, the default) leaves Schlick's term alone and costs nothing else.
struct ThinFilm {
  float weight = 0.0f;
  float ior = 1.3f;
  float thickness = 0.0f;  // nm
  float metallic = 0.0f;
  Vec3 dielectricF0{0, 0, 0};
  Vec3 metalF0{0, 0, 0};

  // glTF's iridescence factor (times its texture), film index and thickness. A film of thickness 0 is none, as in
  // the Sample Viewer; below 0.03 nm it fades in with the reference's index, so the Fresnel term is continuous in
  // the thickness and reaches the base's at 0.
  CANDELA_FN static ThinFilm over(float iridescence, float ior, float thicknessNm, float metallic, Vec3 dielectricF0,
                                  Vec3 metalF0) {
    ThinFilm film;
    const float t = clampf(thicknessNm / 0.03f, 0.0f, 1.0f);
    film.weight = clampf(iridescence, 0.0f, 1.0f) * t * t * (3.0f - 2.0f * t);
    film.ior = fmaxf(ior, 1.0f);
    film.thickness = fmaxf(thicknessNm, 0.0f);
    film.metallic = clampf(metallic, 0.0f, 1.0f);
    film.dielectricF0 = dielectricF0;
    film.metalF0 = metalF0;
    return film;
  }

  // Never in the lean kernel (kernel/kernel_variant.h), whose scenes have no films.
  CANDELA_FN bool present() const { return !kLeanKernel && weight > 0.0f; }

  // The film's reflectance at cosTheta over the dielectric base alone: what the diffuse base sees.
  CANDELA_FN Vec3 overDielectric(float cosTheta) const {
    return thinFilmFresnel(cosTheta, ior, thickness, dielectricF0);
  }

  // The lobe's Fresnel term at cosTheta given Schlick's, `schlick`, for its f0.
  CANDELA_FN Vec3 fresnel(Vec3 schlick, float cosTheta) const {
    if (!present()) return schlick;
    Vec3 film{0, 0, 0};
    if (metallic < 1.0f) film += overDielectric(cosTheta) * (1.0f - metallic);
    if (metallic > 0.0f) film += thinFilmFresnel(cosTheta, ior, thickness, metalF0) * metallic;
    return lerp(weight, schlick, film);
  }
};

}  // namespace candela
