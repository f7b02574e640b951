#pragma once
// A receding checkerboard: the scene the texture filtering tests render on either backend.
#include <cstdint>

#include "image/image.h"
#include "scene/scene.h"

namespace candela::test {

// A size x size linear 8-bit grey texture of black and white squares `square` texels wide.
Texture checkerboardTexture(uint32_t size, uint32_t square);

// A large plane that emits `texture` (repeated many times across it) and reflects nothing, seen from just above
// it towards the horizon: near the bottom of the image a texel covers several pixels, towards the top a pixel
// covers many squares. Nothing else lights or is seen, so a pixel's value is the emitted texture under it alone:
// a render's error against a supersampled reference is all aliasing (and filtering), no lighting noise.
Scene recedingTexturedPlane(const Texture& texture);

// A mirror floor at y = 0 under a ceiling at y = 2 that emits `texture` as recedingTexturedPlane's plane does,
// seen from between them towards the horizon: the image's upper half is the ceiling, the lower half its
// reflection, whose texture footprints come from cones carried through the mirror.
Scene mirroredTexturedCeiling(const Texture& texture);

// The mean over all pixels of the squared difference of the luminances of two images of one size, or over rows
// [firstRow, firstRow + rows) only.
double meanSquaredDifference(const Image& a, const Image& b);
double meanSquaredDifference(const Image& a, const Image& b, uint32_t firstRow, uint32_t rows);

// Rows of recedingTexturedPlane's 160x120 image where the plane is far: from just above the horizon (row 56) to
// where a square of a 16-texel checkerboard is about a pixel deep.
constexpr uint32_t kFarPlaneFirstRow = 45, kFarPlaneRows = 30;

// The mean luminance of an image.
double meanLuminance(const Image& image);

}  // namespace candela::test
