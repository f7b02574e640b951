#pragma once
// Scenes of curves for the curve tests: straight curves along x, and the same tubes as triangle meshes.
#include <cstdint>

#include "scene/scene.h"

namespace candela::test {

// A mesh of one straight curve from (-halfLength, y, z) to (halfLength, y, z) of radius `radius`, of `type`
// (a ribbon's normal is -z, towards a camera on the -z side), material 0.
Mesh straightCurve(CurveType type, float halfLength, float radius, float y = 0.0f, float z = 0.0f);

// A scene of `rows` straight tubes along x, `spacing` apart in y, radius `radius`, seen from -z by the scene's
// camera, under a uniform white environment; one diffuse material of reflectance `albedo`. As curves, or as closed
// triangle tubes of `sides` sides whose polygon has the circle's area.
Scene tubeGrid(bool asCurves, float albedo, uint32_t rows = 5, float spacing = 0.5f, float radius = 0.15f,
               uint32_t sides = 96);

}  // namespace candela::test
