// KHR_materials_iridescence's thin-film Fresnel term (kernel/bsdf/thin_film.h): against a brute-force spectral
// sum of the film's Airy reflectance, its limit at zero thickness, its bounds, and the metallic-roughness model's
// energy with a film on top.
#include <gtest/gtest.h>

#include <complex>

#include "bsdf/bsdf_cases.h"

namespace candela::test {
namespace {

// CIE 1931 colour matching functions as fitted by Wyman, Sloan and Shirley (2013): an independent description of
// the curves whose Fourier transforms the kernel's Gaussians fit.
double lobe(double lambda, double mu, double sigmaBelow, double sigmaAbove) {
  const double t = (lambda - mu) / (lambda < mu ? sigmaBelow : sigmaAbove);
  return std::exp(-0.5 * t * t);
}
void cieXyz(double lambda, double xyz[3]) {
  xyz[0] = 1.056 * lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * lobe(lambda, 442.0, 16.0, 26.7) -
           0.065 * lobe(lambda, 501.1, 20.4, 26.2);
  xyz[1] = 0.821 * lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * lobe(lambda, 530.9, 16.3, 31.1);
  xyz[2] = 1.217 * lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * lobe(lambda, 459.0, 26.0, 13.8);
}

double schlick(double f0, double cosTheta) { return f0 + (1 - f0) * std::pow(1 - cosTheta, 5); }

// The film's reflectance by brute force: per wavelength, the amplitudes of the light reflected at the top and of
// the light that crosses the film and bounces k = 1..200 times at its base, summed with their phases; the
// reflectance spectrum, less its mean (which the extension takes as white), integrated against the colour
// matching functions over 360-830 nm in 0.25 nm steps, normalised by the integral of y-bar and taken to linear
// sRGB, plus that mean. The interfaces are the extension's: Schlick's reflectance at both, the base's index from
// its f0, a phase of pi for a reflection off a denser medium (and the Stokes relation r21 = -r12). Channel i uses
// the base's f0[i] and the i-th sRGB component of its spectrum.
Vec3 spectralReference(double cosTheta1, double filmIor, double thicknessNm, Vec3 baseF0) {
  const double cosTheta2 = std::sqrt(1 - (1 - cosTheta1 * cosTheta1) / (filmIor * filmIor));
  const double r12 = schlick(std::pow((filmIor - 1) / (filmIor + 1), 2), cosTheta1), t121 = 1 - r12;
  const double phi12 = filmIor < 1 ? kPi : 0, phi21 = kPi - phi12;
  double out[3];
  for (int i = 0; i < 3; ++i) {
    const double sqrtF0 = std::sqrt(double(baseF0[i])), baseIor = (1 + sqrtF0) / (1 - sqrtF0);
    const double r23 = schlick(std::pow((baseIor - filmIor) / (baseIor + filmIor), 2), cosTheta2);
    const double phi23 = baseIor < filmIor ? kPi : 0;
    const double mean = r12 + t121 * t121 * r23 / (1 - r12 * r23);
    double xyz[3] = {0, 0, 0}, yIntegral = 0;
    for (double lambda = 360; lambda <= 830; lambda += 0.25) {
      const double delta = 2 * kPi * 2 * filmIor * thicknessNm * cosTheta2 / lambda;
      using C = std::complex<double>;
      C amplitude = std::sqrt(r12) * std::exp(C(0, phi12));
      // First pass: into the film (t12), off the base, back out (t21): t12 t21 = 1 - r12 for the intensities.
      C path = t121 * std::sqrt(r23) * std::exp(C(0, delta + phi23));
      const C bounce = std::sqrt(r12) * std::sqrt(r23) * std::exp(C(0, delta + phi21 + phi23));
      for (int k = 1; k <= 200; ++k, path *= bounce) amplitude += path;
      const double reflectance = std::norm(amplitude);
      double cmf[3];
      cieXyz(lambda, cmf);
      for (int c = 0; c < 3; ++c) xyz[c] += (reflectance - mean) * cmf[c];
      yIntegral += cmf[1];
    }
    for (double& c : xyz) c /= yIntegral;
    const double rgb[3] = {3.2404542 * xyz[0] - 1.5371385 * xyz[1] - 0.4985314 * xyz[2],
                           -0.9692660 * xyz[0] + 1.8760108 * xyz[1] + 0.0415560 * xyz[2],
                           0.0556434 * xyz[0] - 0.2040259 * xyz[1] + 1.0572252 * xyz[2]};
    out[i] = mean + rgb[i];
  }
  return {float(out[0]), float(out[1]), float(out[2])};
}

// The kernel's analytic integration (Gaussian fits in Fourier space, two interference orders) agrees with the
// brute-force sum within 0.008 over a dielectric base and 0.02 over a metal, where the base reflects more and the
// orders left out weigh more (measured: 0.0003-0.007 and 0.006-0.014). The cases keep the base's index clearly on
// one side of the film's in every channel, where the reference's per-channel phases are the physical ones (a base
// of the film's index flips its phase on float round-off).
TEST(ThinFilm, MatchesABruteForceSpectralAirySum) {
  struct Case {
    float cosTheta, filmIor, thicknessNm;
    Vec3 baseF0;
    float tolerance;
  };
  const Vec3 dielectric{0.04f, 0.04f, 0.04f};
  const Case cases[] = {
      {1.0f, 1.3f, 300.0f, dielectric, 0.008f},           {0.7f, 1.3f, 250.0f, dielectric, 0.008f},
      {0.9f, 2.0f, 400.0f, dielectric, 0.008f},           {0.5f, 1.4f, 150.0f, dielectric, 0.008f},
      {0.9f, 1.3f, 800.0f, dielectric, 0.008f},           {1.0f, 1.3f, 500.0f, {0.9f, 0.6f, 0.3f}, 0.02f},
      {0.8f, 1.8f, 350.0f, {0.95f, 0.64f, 0.54f}, 0.02f},
  };
  for (const Case& c : cases) {
    const Vec3 kernel = thinFilmFresnel(c.cosTheta, c.filmIor, c.thicknessNm, c.baseF0);
    const Vec3 reference = spectralReference(c.cosTheta, c.filmIor, c.thicknessNm, c.baseF0);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(kernel[i], reference[i], c.tolerance)
          << "channel " << i << " at cos " << c.cosTheta << ", film index " << c.filmIor << ", " << c.thicknessNm
          << " nm";
  }
  // The film does colour the reflection: 300 nm of index 1.3 reflects red and blue, little green.
  const Vec3 colours = thinFilmFresnel(1.0f, 1.3f, 300.0f, dielectric);
  EXPECT_GT(colours.x, 4 * colours.y);
  EXPECT_GT(colours.z, 4 * colours.y);
}

// As the film thins to nothing the lobe's Fresnel term becomes the base's Schlick term, continuously (the film's
// weight fades over the reference's 0.03 nm, within which the film's own term still departs from the base's at
// grazing angles), and a film of thickness 0 is none at all.
TEST(ThinFilm, AVanishingFilmReflectsAsTheBase) {
  const Vec3 base{0.9f, 0.6f, 0.3f};
  for (float metallic : {0.0f, 0.5f, 1.0f})
    for (float cosTheta : {1.0f, 0.7f, 0.3f, 0.05f}) {
      const Vec3 f0 = lerp(metallic, Vec3{0.04f, 0.04f, 0.04f}, base);
      const Vec3 schlick = fresnelSchlick(f0, cosTheta);
      for (float thickness : {0.02f, 0.01f, 1e-3f, 1e-4f}) {
        const ThinFilm film = ThinFilm::over(1.0f, 1.8f, thickness, metallic, {0.04f, 0.04f, 0.04f}, base);
        const Vec3 f = film.fresnel(schlick, cosTheta);
        const float gap = std::fmax(maxComponent(f - schlick), maxComponent(schlick - f));
        const float t = thickness / 0.03f, fade = t * t * (3 - 2 * t);
        EXPECT_LE(gap, fade + 1e-7f) << thickness << " nm at cos " << cosTheta;
        if (thickness == 1e-4f) {
          EXPECT_LT(gap, 1e-4f) << "cos " << cosTheta;
        }
      }
      const ThinFilm none = ThinFilm::over(1.0f, 1.8f, 0.0f, metallic, {0.04f, 0.04f, 0.04f}, base);
      EXPECT_FALSE(none.present());
      const Vec3 f = none.fresnel(schlick, cosTheta);
      EXPECT_EQ(f.x, schlick.x);
      EXPECT_EQ(f.y, schlick.y);
      EXPECT_EQ(f.z, schlick.z);
    }
  // Without the fade the reference's film would not reach the base: at 1e-4 nm and cos 0.3 its own term is off.
  const Vec3 raw = thinFilmFresnel(0.3f, 1.8f, 1e-4f, {0.04f, 0.04f, 0.04f});
  EXPECT_GT(raw.x - fresnelSchlick(0.04f, 0.3f), 0.02f);
}

// Reflectance in [0, 1] per channel over film indices, thicknesses, angles and bases: the reference's fit
// overshoots 1 at grazing angles (1.28 for f0 0.8 under 245 nm of index 1.8 at cos 0.08), which is clamped.
TEST(ThinFilm, ReflectanceIsBetweenZeroAndOne) {
  float highest = 0.0f;
  for (float f0 : {0.0f, 0.04f, 0.5f, 0.8f, 0.95f, 1.0f})
    for (float ior : {1.0f, 1.3f, 1.8f, 3.0f})
      for (float thickness = 0.0f; thickness <= 1200.0f; thickness += 5.0f)
        for (float cosTheta = 0.0f; cosTheta <= 1.0f; cosTheta += 0.02f) {
          const Vec3 f = thinFilmFresnel(cosTheta, ior, thickness, {f0, f0, f0});
          for (int i = 0; i < 3; ++i) {
            ASSERT_TRUE(f[i] >= 0.0f && f[i] <= 1.0f)
                << f[i] << " for f0 " << f0 << ", index " << ior << ", " << thickness << " nm, cos " << cosTheta;
            highest = std::fmax(highest, f[i]);
          }
        }
  EXPECT_EQ(highest, 1.0f);  // the clamp is reached
}

// White furnace per channel: a white metallic-roughness material under the strongest films reflects at most what
// arrives, in every channel (deterministic quadrature of eval(); tolerance 0.5% for the quadrature's error at
// roughness 0.3). Measured: at most 0.997; without the film's weight on the diffuse term, 1.08. The luminance bound
// over sampled estimates is BsdfEnergy.AlbedoAtMostOne.
TEST(ThinFilm, AWhiteIridescentMaterialReflectsAtMostAllLight) {
  for (float roughness : {0.3f, 1.0f})
    for (float metallic : {0.0f, 1.0f})
      for (float ior : {1.3f, 2.5f})
        for (float thickness : {100.0f, 245.0f, 400.0f, 800.0f}) {
          const PbrBsdf model({1, 1, 1}, metallic, roughness, 1.0f, 1.0f, ior, thickness);
          for (float degrees : {0.0f, 45.0f, 75.0f, 89.0f}) {
            const Vec3 wo = directionAt(degrees, 20.0f);
            constexpr int kN = 120;
            Vec3 sum{0, 0, 0};
            for (int i = 0; i < kN; ++i)
              for (int j = 0; j < 2 * kN; ++j) {
                const double mu = (i + 0.5) / kN, phi = 2 * kPi * (j + 0.5) / (2 * kN), st = std::sqrt(1 - mu * mu);
                const Vec3 wi{float(st * std::cos(phi)), float(st * std::sin(phi)), float(mu)};
                sum += model.eval(wo, wi) * float(mu);
              }
            const Vec3 albedo = sum * float((1.0 / kN) * (2 * kPi / (2 * kN)));
            EXPECT_LE(maxComponent(albedo), 1.005f)
                << "roughness " << roughness << ", metallic " << metallic << ", index " << ior << ", " << thickness
                << " nm, " << degrees << " degrees";
          }
        }
}

// A factor of 0 is no film: the model is the plain one, bit for bit, whatever the film's other parameters.
TEST(ThinFilm, FactorZeroIsThePlainModel) {
  const PbrBsdf plain({0.8f, 0.6f, 0.4f}, 0.3f, 0.4f, 0.5f);
  const PbrBsdf unused({0.8f, 0.6f, 0.4f}, 0.3f, 0.4f, 0.5f, 0.0f, 2.0f, 300.0f);
  Material disney = disneyMaterial(0.4f), disneyUnused = disney;
  disneyUnused.iridescenceIor = 2.0f;
  disneyUnused.iridescenceThickness = 300.0f;
  const DisneyBsdf disneyPlain(disney, 1.5f), disneyFilmless(disneyUnused, 1.5f);
  for (uint32_t i = 0; i < 200; ++i) {
    const Vec3 wo = directionAt(float(i % 89), float(i * 7));
    const Vec3 wi = directionAt(float((i * 13) % 89), float(i * 31));
    const Vec3 a = plain.eval(wo, wi), b = unused.eval(wo, wi);
    const Vec3 c = disneyPlain.eval(wo, wi), d = disneyFilmless.eval(wo, wi);
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(a[k], b[k]);
      ASSERT_EQ(c[k], d[k]);
    }
  }
}

}  // namespace
}  // namespace candela::test
