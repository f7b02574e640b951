#pragma once
#include <cstdint>
#include <string>

#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// What candela takes from pbrt-v4's `Film`: the image size, and the imaging ratio by which pbrt-v4's sensor scales
// the light that reaches it: the film's `iso` / 100 times the camera's exposure time (`shutterclose` -
// `shutteropen`), 1 by default.
struct PbrtFilm {
  uint32_t width = 1280, height = 720;          // the image candela renders: the crop window's pixels
  uint32_t fullWidth = 1280, fullHeight = 720;  // pbrt's full resolution, which the camera's screen window spans
  uint32_t cropX = 0, cropY = 0;                // the crop window's first column and row (row 0 at the top)
  float imagingRatio = 1.0f;
};

// `film` and `camera` may be null (no such directive). `cropwindow` (x0 x1 y0 y1 in [0, 1] of the full image) keeps
// the pixels pbrt-v4 keeps: columns ceil(x0 W) to ceil(x1 W), rows likewise. The film's other parameters are noted
// as not applied, except `filename` (candela's -o names the output). Throws LoadError when the shutter does not
// open or the crop window holds no pixel.
PbrtFilm readPbrtFilm(const PbrtParameters* film, const PbrtParameters* camera, PbrtContext& context);

// Multiplies every light of the scene (emissive materials, the environment, punctual lights) by `ratio`: the same
// image as pbrt-v4's sensor scaling the light that reaches it.
void scaleSceneLights(Scene& scene, float ratio);

}  // namespace candela
