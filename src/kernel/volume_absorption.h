#pragma once
#include "core/math.h"
#include "kernel/material.h"

namespace candela {

// Beer-Lambert absorption inside transmissive materials (glTF's KHR_materials_volume). Closed meshes are wound
// outwards (kernel/bsdf/bsdf.h), so a ray that meets a surface from behind has travelled inside that surface's
// material since it last scattered, and its throughput falls by exp(-absorption * distance) over the segment.
// Reading the medium from the surface that ends a segment carries no state along the path. It takes volumes to
// be closed and not nested, as glTF's are: a segment that ends on another object inside the volume, or a shadow
// ray that stays inside one, is not attenuated.
CANDELA_FN bool absorbs(const Material& m) {
  return m.absorption.x > 0.0f || m.absorption.y > 0.0f || m.absorption.z > 0.0f;
}

// The fraction of light left after `distance` inside m (a unit direction's ray parameter is that distance).
CANDELA_FN Vec3 volumeTransmittance(const Material& m, float distance) {
  return {expf(-m.absorption.x * distance), expf(-m.absorption.y * distance), expf(-m.absorption.z * distance)};
}

}  // namespace candela
