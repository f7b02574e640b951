#pragma once
// A scene whose answer is known exactly and depends on how rays treat cut-outs.
#include "scene/scene.h"

namespace candela::test {

enum class ScreenCoverage {
  CheckerMask,  // alpha-tested checker: half of every period open
  HalfBlend,    // alpha-blended, alpha 0.5 everywhere
  Opaque,       // cut-outs treated as solid: a wrong answer
  Absent,       // no screen: cut-outs ignored, a wrong answer
};

// A grey diffuse floor (albedo kScreenFloorAlbedo) under a black screen parallel to it at height 1, lit by a
// uniform sky of radiance 1. The camera sits halfway between them looking straight down; it sees a square of
// the floor exactly 2 x 2 periods of the screen's checker wide, and, the floor being parallel to the image
// plane, every point of that square equally often. Between camera and screen hangs a black single-sided quad
// whose front faces the screen, so every ray from the floor meets its back face: culled, it must let them by.
// Floor, screen and quad are one mesh.
//
// The mean radiance over the image is kScreenFloorAlbedo times the mean cosine-weighted fraction of the sky
// seen through the screen. For alpha blending that fraction is 1/2 at every point. For the checker it is 1/2
// averaged over the square: for any direction the points where rays cross the screen form a translate of the
// square, which covers whole periods, and half of a period is open (shifting by one cell swaps open and
// closed, so this holds for the bilinearly filtered mask too). The screen reaches 200 units out; the sky past
// its edge adds less than 3e-5 of the answer.
Scene makeCutoutScreen(ScreenCoverage coverage);

constexpr float kScreenFloorAlbedo = 0.8f;

}  // namespace candela::test
