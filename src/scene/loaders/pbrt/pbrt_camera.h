#pragma once
#include <glm/mat4x4.hpp>

#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_film.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// pbrt's camera looks down +z with +y up and +x to the right of the image: a left-handed frame when its
// world-from-camera transform is a rotation. candela's cameras are right-handed, so the loader mirrors the whole
// world (x -> -x) unless the camera transform already mirrors (as after pbrt's customary `Scale -1 1 1`).
bool pbrtWorldNeedsMirror(const glm::mat4& cameraFromWorld);

// The camera of a `Camera` directive whose current transform was `cameraFromWorld`, for `film`'s image:
// perspective (fov on the shorter image axis) or orthographic, each with lensradius, focaldistance, screenwindow
// and frameaspectratio, all of the film's full resolution, of which the camera shows the film's crop window; other
// projections are drawn as perspective with a warning.
CameraDescription makePbrtCamera(const std::string& type, const PbrtParameters& params,
                                 const glm::mat4& cameraFromWorld, const PbrtFilm& film, bool mirrorX,
                                 PbrtContext& context);

}  // namespace candela
