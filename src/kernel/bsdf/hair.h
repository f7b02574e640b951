#pragma once
#include "core/math.h"
#include "kernel/bsdf/bsdf_sample.h"
#include "kernel/bsdf/fresnel.h"
#include "kernel/material.h"

namespace candela {

// pbrt-v4's HairBxDF, the hair model of Chiang, Bitterli, Tappan and Burley (2016, "A Practical and Controllable
// Hair and Fur Model for Production Path Tracing"). Light meets a rough dielectric cylinder of index eta that
// absorbs sigma_a inside, and leaves after term p of its paths: p = 0 reflects off the surface, 1 passes through,
// 2 reflects once inside, and the last term (kPMax) gathers every longer path. Each term is the product of a
// longitudinal lobe Mp (of variance v from the roughness beta_m, centred on the mirror direction tilted by the
// cuticle's scales, alpha), the attenuation Ap (Fresnel and absorption) and an azimuthal lobe Np (a logistic of
// a scale from the roughness beta_n, around the azimuth the path turns the light by); the last term is uniform in
// azimuth. A sample picks a term in proportion to its Ap, then theta from Mp and phi from Np.
//
// The fibre runs along the local frame's x axis (the surface's tangent). Angles are pbrt's: theta from the plane
// normal to the fibre (sin theta = w.x) and phi around the fibre (atan2(w.z, w.y)); h in [-1, 1] is where the
// light meets the fibre across its width. Scattering covers the whole sphere (on a surface, the model transmits);
// f is divided by |cos| to the normal, as every BSDF's, so that f |cos| is the fibre's scattering function; light
// is not bent (a sample's eta is 1).
struct HairBsdf {
  static constexpr int kPMax = 3;

  float h;                                     // where light meets the fibre across its width, -1 to 1
  float eta;                                   // the fibre's index of refraction
  Vec3 sigmaA;                                 // absorption inside the fibre, per unit of its radius
  float variance[kPMax + 1];                   // each term's longitudinal variance
  float azimuthalScale;                        // the azimuthal logistic's scale
  float sin2kAlpha[kPMax], cos2kAlpha[kPMax];  // the scales' tilt: angles alpha, 2 alpha and 4 alpha

  HairBsdf() = default;
  // The roughnesses are clamped to [0.01, 1] and h to [-1, 1], as pbrt-v4's HairMaterial does.
  CANDELA_FN HairBsdf(float hOffset, float indexOfRefraction, Vec3 absorption, float betaM, float betaN,
                      float alphaDegrees)
      : h(clampf(hOffset, -1.0f, 1.0f)), eta(indexOfRefraction), sigmaA(absorption) {
    betaM = clampf(betaM, 0.01f, 1.0f);
    betaN = clampf(betaN, 0.01f, 1.0f);
    // Chiang et al.'s fits of the variance and the scale that make the lobes' widths follow beta linearly.
    variance[0] = sqr(0.726f * betaM + 0.812f * sqr(betaM) + 3.7f * powf(betaM, 20.0f));
    variance[1] = 0.25f * variance[0];
    variance[2] = 4.0f * variance[0];
    for (int p = 3; p <= kPMax; ++p) variance[p] = variance[2];
    constexpr float kSqrtPiOver8 = 0.626657069f;
    azimuthalScale = kSqrtPiOver8 * (0.265f * betaN + 1.194f * sqr(betaN) + 5.372f * powf(betaN, 22.0f));
    sin2kAlpha[0] = sinf(alphaDegrees * (kPi / 180.0f));
    cos2kAlpha[0] = sqrtf(fmaxf(0.0f, 1.0f - sqr(sin2kAlpha[0])));
    for (int i = 1; i < kPMax; ++i) {
      sin2kAlpha[i] = 2.0f * cos2kAlpha[i - 1] * sin2kAlpha[i - 1];
      cos2kAlpha[i] = sqr(cos2kAlpha[i - 1]) - sqr(sin2kAlpha[i - 1]);
    }
  }

  static constexpr bool kDelta = false;
  CANDELA_FN bool hasTransmission() const { return true; }
  CANDELA_FN static bool transmits(const Material&) { return true; }
  CANDELA_FN static bool orientedByTangent(const Material&) { return true; }
  static constexpr bool kInLeanKernel = false;
  CANDELA_FN static Vec3 guideAlbedo(const Material& m) {
    return reflectanceOfAbsorption(m.fibreAbsorption, m.azimuthalRoughness);
  }
  // h from the surface's v coordinate, as pbrt-v4 takes it from a curve's (-1 + 2v): candela's v runs down the
  // image where pbrt's runs up (loaders flip it), so pbrt's -1 + 2v is 1 - 2v here. eta is the fibre's own, not
  // relative to the side wo lies on.
  CANDELA_FN static HairBsdf fromMaterial(const Material& m, float /*eta*/, Vec2 uv) {
    return HairBsdf(1.0f - 2.0f * uv.y, m.ior > 0.0f ? m.ior : 1.55f, m.fibreAbsorption, m.roughness,
                    m.azimuthalRoughness, m.scaleTilt);
  }

  // pbrt-v4's HairBxDF::SigmaAFromConcentration: the absorption of eumelanin and pheomelanin concentrations.
  CANDELA_FN static Vec3 absorptionOfMelanin(float eumelanin, float pheomelanin) {
    return Vec3{0.419f, 0.697f, 1.37f} * eumelanin + Vec3{0.187f, 0.4f, 1.05f} * pheomelanin;
  }
  // pbrt-v4's HairBxDF::SigmaAFromReflectance: the absorption that gives hair of azimuthal roughness betaN about
  // the colour `c` (in (0, 1] per channel) after many bounces, and its inverse.
  CANDELA_FN static float reflectanceFit(float betaN) {
    return 5.969f - 0.215f * betaN + 2.532f * sqr(betaN) - 10.73f * betaN * sqr(betaN) + 5.574f * sqr(sqr(betaN)) +
           0.245f * betaN * sqr(sqr(betaN));
  }
  CANDELA_FN static Vec3 absorptionOfReflectance(Vec3 c, float betaN) {
    const float fit = reflectanceFit(betaN);
    return {sqr(logf(c.x) / fit), sqr(logf(c.y) / fit), sqr(logf(c.z) / fit)};
  }
  CANDELA_FN static Vec3 reflectanceOfAbsorption(Vec3 sigmaA, float betaN) {
    const float fit = reflectanceFit(clampf(betaN, 0.01f, 1.0f));
    return {expf(-fit * sqrtf(fmaxf(sigmaA.x, 0.0f))), expf(-fit * sqrtf(fmaxf(sigmaA.y, 0.0f))),
            expf(-fit * sqrtf(fmaxf(sigmaA.z, 0.0f)))};
  }

  CANDELA_FN Vec3 eval(Vec3 wo, Vec3 wi) const { return evalPdf(wo, wi).f; }
  CANDELA_FN float pdf(Vec3 wo, Vec3 wi) const { return evalPdf(wo, wi).pdf; }
  CANDELA_FN BsdfEval evalPdf(Vec3 wo, Vec3 wi) const {
    const Terms t = terms(wo);
    const float sinThetaI = clampf(wi.x, -1.0f, 1.0f);
    return evalPdfAt(t, sinThetaI, atan2f(wi.z, wi.y) - t.phiO, fabsf(wi.z));
  }

  CANDELA_FN BsdfSample sample(Vec3 wo, float uChoice, Vec2 u) const {
    BsdfSample s;
    const Terms t = terms(wo);
    // The term, in proportion to its attenuation, and uChoice rescaled to [0, 1) within it for the azimuth.
    int p = 0;
    float cdf = 0.0f;
    while (p < kPMax && uChoice >= cdf + t.apPdf[p]) cdf += t.apPdf[p++];
    if (!(t.apPdf[p] > 0.0f)) return s;
    const float uPhi = fminf((uChoice - cdf) / t.apPdf[p], 0x1.fffffep-1f);

    // theta from Mp about the term's tilted mirror direction.
    const float cosTheta = 1.0f + variance[p] * logf(fmaxf(u.x, 1e-5f) + (1.0f - u.x) * expf(-2.0f / variance[p]));
    const float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - sqr(cosTheta)));
    const float cosPhi = cosf(2.0f * kPi * u.y);
    const float sinThetaI = clampf(-cosTheta * t.sinThetaPO[p] + sinTheta * cosPhi * t.cosThetaPO[p], -1.0f, 1.0f);
    const float cosThetaI = sqrtf(fmaxf(0.0f, 1.0f - sqr(sinThetaI)));

    // phi from Np about the term's deflection; the last term's is uniform.
    const float dPhi = p < kPMax ? deflection(p, t.gammaO, t.gammaT) + sampleTrimmedLogistic(uPhi) : 2.0f * kPi * uPhi;
    const float phiI = t.phiO + dPhi;
    s.wi = {sinThetaI, cosThetaI * cosf(phiI), cosThetaI * sinf(phiI)};
    const BsdfEval e = evalPdfAt(t, sinThetaI, dPhi, fabsf(s.wi.z));
    s.f = e.f;
    s.pdf = e.pdf;
    s.valid = s.pdf > 0.0f;
    return s;
  }

 private:
  // What depends on wo alone: its angles, the refracted ray's, and each term's attenuation, its probability of
  // being sampled and wo's angle tilted by the scales for it.
  struct Terms {
    float sinThetaO, cosThetaO, phiO, gammaO, gammaT;
    Vec3 ap[kPMax + 1];
    float apPdf[kPMax + 1];
    float sinThetaPO[kPMax + 1], cosThetaPO[kPMax + 1];
  };

  CANDELA_FN Terms terms(Vec3 wo) const {
    Terms t;
    t.sinThetaO = clampf(wo.x, -1.0f, 1.0f);
    t.cosThetaO = sqrtf(fmaxf(0.0f, 1.0f - sqr(t.sinThetaO)));
    t.phiO = atan2f(wo.z, wo.y);
    t.gammaO = asinf(h);

    // The refracted ray: its longitudinal angle, and its azimuthal one through the modified index of Bravais.
    const float sinThetaT = t.sinThetaO / eta;
    const float cosThetaT = sqrtf(fmaxf(0.0f, 1.0f - sqr(sinThetaT)));
    const float etaP = sqrtf(fmaxf(0.0f, sqr(eta) - sqr(t.sinThetaO))) / t.cosThetaO;
    const float sinGammaT = clampf(h / etaP, -1.0f, 1.0f);
    const float cosGammaT = sqrtf(fmaxf(0.0f, 1.0f - sqr(sinGammaT)));
    t.gammaT = asinf(sinGammaT);

    // One crossing of the fibre transmits T; each term's attenuation follows from it and the Fresnel reflectance.
    const float pathLength = 2.0f * cosGammaT / cosThetaT;
    const Vec3 T{expf(-sigmaA.x * pathLength), expf(-sigmaA.y * pathLength), expf(-sigmaA.z * pathLength)};
    const float f = fresnelDielectric(t.cosThetaO * sqrtf(fmaxf(0.0f, 1.0f - sqr(h))), eta);
    t.ap[0] = Vec3{f, f, f};
    t.ap[1] = T * sqr(1.0f - f);
    for (int p = 2; p < kPMax; ++p) t.ap[p] = t.ap[p - 1] * T * f;
    const Vec3 tf = T * f;
    t.ap[kPMax] = {tf.x < 1.0f ? t.ap[kPMax - 1].x * tf.x / (1.0f - tf.x) : 0.0f,
                   tf.y < 1.0f ? t.ap[kPMax - 1].y * tf.y / (1.0f - tf.y) : 0.0f,
                   tf.z < 1.0f ? t.ap[kPMax - 1].z * tf.z / (1.0f - tf.z) : 0.0f};
    float sum = 0.0f;
    for (const Vec3& a : t.ap) sum += channelMean(a);
    for (int p = 0; p <= kPMax; ++p) t.apPdf[p] = sum > 0.0f ? channelMean(t.ap[p]) / sum : 0.0f;

    // The scales tilt R's lobe by -2 alpha, TT's by alpha and TRT's by 4 alpha; the last term is untilted.
    t.sinThetaPO[0] = t.sinThetaO * cos2kAlpha[1] - t.cosThetaO * sin2kAlpha[1];
    t.cosThetaPO[0] = t.cosThetaO * cos2kAlpha[1] + t.sinThetaO * sin2kAlpha[1];
    t.sinThetaPO[1] = t.sinThetaO * cos2kAlpha[0] + t.cosThetaO * sin2kAlpha[0];
    t.cosThetaPO[1] = t.cosThetaO * cos2kAlpha[0] - t.sinThetaO * sin2kAlpha[0];
    t.sinThetaPO[2] = t.sinThetaO * cos2kAlpha[2] + t.cosThetaO * sin2kAlpha[2];
    t.cosThetaPO[2] = t.cosThetaO * cos2kAlpha[2] - t.sinThetaO * sin2kAlpha[2];
    t.sinThetaPO[3] = t.sinThetaO;
    t.cosThetaPO[3] = t.cosThetaO;
    // A tilt past the pole leaves a negative cosine, which Mp takes as its magnitude.
    for (float& c : t.cosThetaPO) c = fabsf(c);
    return t;
  }

  // f and the density for wi at longitudinal sine sinThetaI and azimuth phi from wo's; cosI is |wi.z|.
  CANDELA_FN BsdfEval evalPdfAt(const Terms& t, float sinThetaI, float phi, float cosI) const {
    const float cosThetaI = sqrtf(fmaxf(0.0f, 1.0f - sqr(sinThetaI)));
    BsdfEval e;
    e.f = {0, 0, 0};
    for (int p = 0; p <= kPMax; ++p) {
      const float mp = longitudinal(cosThetaI, t.cosThetaPO[p], sinThetaI, t.sinThetaPO[p], variance[p]);
      const float np = p < kPMax ? azimuthal(phi, p, t.gammaO, t.gammaT) : 1.0f / (2.0f * kPi);
      e.f += t.ap[p] * (mp * np);
      e.pdf += t.apPdf[p] * mp * np;
    }
    if (cosI > 0.0f) e.f = e.f / cosI;
    if (!isFinite(e.f) || !isFinite(e.pdf)) return {};
    return e;
  }

  CANDELA_FN static float channelMean(Vec3 c) { return (c.x + c.y + c.z) * (1.0f / 3.0f); }

  // The modified Bessel function of the first kind I0 by its series' first ten terms, and its logarithm (an
  // asymptotic expansion past 12, where the series would overflow), as pbrt-v4 computes them.
  CANDELA_FN static float besselI0(float x) {
    float value = 0.0f, x2i = 1.0f, factorial = 1.0f, fourToI = 1.0f;
    for (int i = 0; i < 10; ++i) {
      if (i > 1) factorial *= float(i);
      value += x2i / (fourToI * sqr(factorial));
      x2i *= x * x;
      fourToI *= 4.0f;
    }
    return value;
  }
  CANDELA_FN static float logBesselI0(float x) {
    if (x > 12.0f) return x + 0.5f * (-logf(2.0f * kPi) + logf(1.0f / x) + 1.0f / (8.0f * x));
    return logf(besselI0(x));
  }

  // Mp: the longitudinal lobe of variance `variance`, normalised over the sphere; for narrow lobes in logarithms,
  // which keeps I0 and sinh finite.
  CANDELA_FN static float longitudinal(float cosThetaI, float cosThetaO, float sinThetaI, float sinThetaO,
                                       float variance) {
    const float a = cosThetaI * cosThetaO / variance, b = sinThetaI * sinThetaO / variance;
    if (variance <= 0.1f) return expf(logBesselI0(a) - b - 1.0f / variance + 0.6931f + logf(1.0f / (2.0f * variance)));
    return expf(-b) * besselI0(a) / (sinhf(1.0f / variance) * 2.0f * variance);
  }

  // The azimuth by which term p turns light that meets the fibre at gammaO and refracts to gammaT.
  CANDELA_FN static float deflection(int p, float gammaO, float gammaT) {
    return 2.0f * float(p) * gammaT - 2.0f * gammaO + float(p) * kPi;
  }

  // The logistic of scale s, and its density and samples trimmed to [-pi, pi].
  CANDELA_FN static float logistic(float x, float scale) {
    x = fabsf(x);
    const float e = expf(-x / scale);
    return e / (scale * sqr(1.0f + e));
  }
  CANDELA_FN static float logisticCdf(float x, float scale) { return 1.0f / (1.0f + expf(-x / scale)); }
  CANDELA_FN float trimmedLogistic(float x) const {
    return logistic(x, azimuthalScale) / (logisticCdf(kPi, azimuthalScale) - logisticCdf(-kPi, azimuthalScale));
  }
  CANDELA_FN float sampleTrimmedLogistic(float u) const {
    u = lerp(u, logisticCdf(-kPi, azimuthalScale), logisticCdf(kPi, azimuthalScale));
    return clampf(-azimuthalScale * logf(1.0f / u - 1.0f), -kPi, kPi);
  }

  // Np: term p's azimuthal lobe at azimuth phi from wo's.
  CANDELA_FN float azimuthal(float phi, int p, float gammaO, float gammaT) const {
    float dPhi = phi - deflection(p, gammaO, gammaT);
    // Into [-pi, pi]: phi and the deflection each lie within a few turns.
    dPhi -= 2.0f * kPi * floorf((dPhi + kPi) / (2.0f * kPi));
    return trimmedLogistic(dPhi);
  }
};

}  // namespace candela
