#pragma once
#include "image/aov_images.h"
#include "image/image.h"

namespace candela {

// Edge-avoiding a-trous wavelet filter (Dammertz et al. 2010), the spatial part of SVGF: `passes` passes of the
// 5x5 B3-spline kernel with holes of 2^i pixels, each tap weighted down by its difference from the centre in
// colour, normal and depth. The colour weight compares luminance. What is filtered:
// - the reflected light, demodulated by the albedo (texture detail is not noise) and remodulated after, so only the
//   lighting is smoothed;
// - apart from it, the radiance the camera sees emitted (aovs.emission: lights, emissive textures, the sky), which
//   is no lighting of a surface: divided by an emitter's albedo (often zero) and multiplied back by its neighbours'
//   it would spread the emitter over them. Filtered on its own it loses the noise of emitters' edges.
// Their sum is then mixed with the raw pixel by the pixel's variance (aovs.variance, at least its neighbourhood's
// median: blendVariance and blendWithRaw in atrous_kernel.h): where the filter moved a pixel by more than its noise
// explains, the raw value is kept, so the filter's bias (smoothed shadows, highlights, edges) fades as the image
// converges.
struct AtrousParams {
  int passes = 5;
  // Colour edge-stopping width in standard deviations of the local luminance noise, estimated in every pass
  // from the 3x3 neighbourhood (SVGF's spatial variance estimate): it narrows as the image gets smoother.
  float colorSigma = 1.25f;
  float normalSigma = 1.0f;  // on |n_p - n_q| of unit normals
  // On |z_p - z_q| over the difference the centre's depth gradient predicts for the tap (SVGF).
  float depthSigma = 10.0f;
};

constexpr int kMaxAtrousPasses = 10;

// Throws std::invalid_argument for a pass count outside [0, kMaxAtrousPasses] or a sigma that is not positive.
void validateAtrousParams(const AtrousParams& params);

// Throws std::invalid_argument for bad params or AOVs (emission included) of another size than the image.
void validateAtrousInput(const Image& color, const AovImages& aovs, const AtrousParams& params);
Image atrousDenoise(const Image& color, const AovImages& aovs, const AtrousParams& params);

// The passes alone, on a signal that is already what they should smooth (the temporal filter's accumulated
// demodulated light), guided by the AOVs' normals and depths; no demodulation and no mix with raw pixels.
// `firstLevel`, unless null, receives the output of the first pass (SVGF's history). `firstPassVariance`, unless
// null, gives the first pass the variance of each pixel's luminance (negative: the neighbourhood's, as ever).
Image atrousSmooth(const Image& signal, const AovImages& guides, const AtrousParams& params, Image* firstLevel,
                   const std::vector<float>* firstPassVariance = nullptr);

}  // namespace candela
