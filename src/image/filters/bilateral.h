#pragma once
#include "image/image.h"

namespace candela {

// An edge-preserving blur: each pixel becomes the weighted mean of its (2 radius + 1)^2 neighbours inside the
// image, with weight exp(-|q - p|^2 / (2 spatialSigma^2) - |I(q) - I(p)|^2 / (2 rangeSigma^2)), where the
// range distance is Euclidean in linear RGB. The viewer's GLSL pass and the CUDA version compute the same sum.
struct BilateralParams {
  int radius = 3;             // pixels; 0 leaves the image unchanged
  float spatialSigma = 2.0f;  // pixels
  float rangeSigma = 0.2f;    // linear radiance
};

// Throws std::invalid_argument when radius is outside [0, kMaxBilateralRadius] or a sigma is not positive.
Image bilateralFilter(const Image& input, const BilateralParams& params);

// The filter on the part of `input` that is not `emission` (the radiance the camera sees emitted, an image of the
// same size), with `emission` added back after: emitters are not smoothed into their surroundings. Throws
// std::invalid_argument as above, or when the sizes differ.
Image bilateralFilter(const Image& input, const Image& emission, const BilateralParams& params);

constexpr int kMaxBilateralRadius = 32;

// The range checks of bilateralFilter, for the other implementations of the same filter.
void validateBilateralParams(const BilateralParams& params);

}  // namespace candela
