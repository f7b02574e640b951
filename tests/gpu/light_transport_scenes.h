#pragma once
// Scenes of light that goes through things (participating media, subsurface scattering, diffuse transmission),
// written as pbrt-v4 text into a folder and loaded as a user's file is: inside a room lit by an area light in its
// ceiling, open towards the camera as the Cornell box is, so that most of the image is lit by light that has
// bounced off the walls or crossed a medium.
#include "scene/scene.h"
#include "scene/scene_test_files.h"

namespace candela::test {

// Two homogeneous media bounded by interface shapes: a forward-scattering fog sphere and a backward-scattering
// smoke box around a diffuse sphere, each scattering and absorbing the three channels differently.
Scene makeFogRoom(const TempFolder& folder);

// The camera in a chromatic haze that fills a box around the whole room, with the fog sphere in the haze (its
// interface has fog inside and haze outside): camera rays start in a medium and cross into another.
Scene makeHazyRoom(const TempFolder& folder);

// A uniformgrid medium of 8^3 densities, empty over a third of its box and a hole, that emits from its `Lescale`
// grid in its lower half.
Scene makeUniformGridRoom(const TempFolder& folder);

// An rgbgrid medium whose samples absorb and scatter each channel differently (some not at all) beside a cloud.
Scene makeRgbGridAndCloudRoom(const TempFolder& folder);

// A nanovdb medium read from a .nvdb file written beside the scene: a density grid with empty voxels and a
// temperature grid, hot in part of it, whose blackbody emission lights the room with the area light.
Scene makeNanoVdbRoom(const TempFolder& folder);

// pbrt's `subsurface` material in both its forms, reflectance and mean free path on a sphere and sigma_a and
// sigma_s behind a rough boundary on a box, and a `diffusetransmission` sphere.
Scene makeSubsurfaceRoom(const TempFolder& folder);

// `scene`, whose media must all be homogeneous, with every medium's absorption and scattering times `factor`.
Scene withDenserHomogeneousMedia(Scene scene, float factor);

}  // namespace candela::test
