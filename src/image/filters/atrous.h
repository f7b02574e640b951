#pragma once
#include <array>
#include <functional>
#include <memory>

#include "image/aov_images.h"
#include "image/filters/planes.h"
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
  // On |z_p - z_q| over the difference the centre's depth gradient predicts for the tap (SVGF). 4 rather than SVGF's
  // 1 or the 10 this was: on the quality scenes at 4 spp with the Sobol sampler, 10 left the material gallery 3.9x
  // better than raw and 4 makes it 4.1x (docs/denoising.md, 'With the Sobol sampler').
  float depthSigma = 4.0f;
};

constexpr int kMaxAtrousPasses = 10;

// Throws std::invalid_argument for a pass count outside [0, kMaxAtrousPasses] or a sigma that is not positive.
void validateAtrousParams(const AtrousParams& params);

// Throws std::invalid_argument for bad params or AOVs (emission included) of another size than the image.
void validateAtrousInput(const Image& color, const AovImages& aovs, const AtrousParams& params);
Image atrousDenoise(const Image& color, const AovImages& aovs, const AtrousParams& params);

// The a-trous passes on planes that outlive one image, over one signal or two (the reflected light and the emission)
// guided by the same normals and depths: each tap's guide terms are then computed once for both. The temporal filter
// writes its accumulated signals (already what the passes should smooth: no demodulation, no mix with raw pixels)
// straight into them frame after frame, and fills the guides once for both.
class AtrousWorkspace {
 public:
  AtrousWorkspace();
  ~AtrousWorkspace();
  // The guide planes from the AOVs' normals and depths; the planes are made for their size, or kept from the last
  // call where it is the same.
  void setGuides(const AovImages& guides);
  // The unit normals (zero where the path escaped) setGuides made of the AOVs', x, y and z in the three planes.
  RgbPlanes unitNormals();
  // Where runPasses starts: the caller writes signal `which` (0 or 1) there (after setGuides).
  RgbPlanes signal(int which);
  // The passes on signals 0 to signalCount - 1 (1 or 2), guided by the guides set, each as if filtered alone.
  // `afterFirstPass`, unless null, receives signal 0's output of the first pass (SVGF's history; the signal itself for
  // no passes). `firstPassVariance`, unless null, gives signal 0's first pass the variance of each pixel's luminance
  // (negative: the neighbourhood's, as ever). Returns the planes that hold each signal's result, valid until the next
  // call or until the next signal is written (after an even number of passes they are signal()'s).
  std::array<RgbPlanes, 2> runPasses(const AtrousParams& params, int signalCount,
                                     const std::function<void(const RgbPlanes&)>& afterFirstPass = nullptr,
                                     const float* firstPassVariance = nullptr);
  // A plane of the size free for the caller once runPasses is done, until the next call.
  float* scratch();

 private:
  uint32_t width_ = 0, height_ = 0;
  std::unique_ptr<PlaneStack> stack_;
};

}  // namespace candela
