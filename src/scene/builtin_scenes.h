#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

namespace candela {

// The Cornell box as measured at the Cornell Program of Computer Graphics (geometry in metres, camera with a
// 35 mm lens on a 25 mm film), with the usual RGB fits of the measured reflectances and light spectrum.
Scene makeCornellBox();

// The Cornell box with its blocks replaced by two instances of one finely tessellated sphere (159,200
// triangles): a dense mesh for timing traversal.
Scene makeCornellSpheres();

// The inside of a closed sphere whose every point reflects diffusely with `albedo` and emits `emission`:
// radiance is emission / (1 - albedo) everywhere, the camera sits at the centre.
Scene makeClosedEmissiveSphere(float albedo, float emission);

// A white (albedo 1) diffuse sphere under a uniform environment of radiance 1: every pixel is 1.
Scene makeWhiteFurnace();

// Rows of spheres with the Disney BSDF, each row sweeping one parameter from 0 (left) to 1 (right): roughness
// (gold metal), metallic, sheen, clearcoat, subsurface and specular transmission, top to bottom, on a grey floor
// under an area light and a dim uniform sky.
Scene makeMaterialGallery();

// Two parallel mirrors facing each other across a lit floor with a few spheres between them: the camera sees
// the reflections recede through many bounces (render with --max-depth 100).
Scene makeMirrorCorridor();

// Names accepted by makeBuiltinScene, for --help and error messages.
std::vector<std::string> builtinSceneNames();

// Returns true and fills `scene` when `name` is a built-in scene.
bool makeBuiltinScene(const std::string& name, Scene& scene);

}  // namespace candela
