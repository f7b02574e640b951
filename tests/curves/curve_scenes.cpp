#include "curves/curve_scenes.h"

#include <cmath>

namespace candela::test {

Mesh straightCurve(CurveType type, float halfLength, float radius, float y, float z) {
  Mesh mesh;
  mesh.name = "straight curve";
  for (int i = 0; i < 4; ++i)
    mesh.curveVertices.push_back({-halfLength + 2.0f * halfLength * float(i) / 3.0f, y, z, radius});
  if (type == CurveType::Ribbon) mesh.curveNormals.assign(4, Vec3{0, 0, -1});
  mesh.curveSegments.push_back({0, 0, type});
  return mesh;
}

namespace {

// A closed tube along x: `sides` quads around, the polygon scaled to the circle's area, and its two end caps.
Mesh triangleTube(float halfLength, float radius, float y, uint32_t sides) {
  Mesh mesh;
  mesh.name = "triangle tube";
  const float step = 2.0f * kPi / float(sides);
  const float scaled = radius * std::sqrt(step / std::sin(step));  // polygon area = circle area
  for (uint32_t i = 0; i < sides; ++i) {
    const float a = step * float(i);
    for (float x : {-halfLength, halfLength})
      mesh.positions.push_back({x, y + scaled * std::cos(a), scaled * std::sin(a)});
  }
  for (uint32_t i = 0; i < sides; ++i) {
    const uint32_t j = (i + 1) % sides;
    mesh.indices.insert(mesh.indices.end(), {2 * i, 2 * j, 2 * j + 1, 2 * i, 2 * j + 1, 2 * i + 1});
  }
  for (uint32_t i = 1; i + 1 < sides; ++i)
    mesh.indices.insert(mesh.indices.end(), {0, 2 * (i + 1), 2 * i, 1, 2 * i + 1, 2 * (i + 1) + 1});
  mesh.triangleMaterials.assign(mesh.triangleCount(), 0);
  return mesh;
}

}  // namespace

Scene tubeGrid(bool asCurves, float albedo, uint32_t rows, float spacing, float radius, uint32_t sides) {
  Scene scene;
  scene.name = asCurves ? "curve tubes" : "triangle tubes";
  Material m;
  m.type = MaterialType::Diffuse;
  m.baseColor = {albedo, albedo, albedo};
  scene.materials.push_back(m);
  scene.materialNames.push_back("white");
  for (uint32_t r = 0; r < rows; ++r) {
    const float y = (float(r) - 0.5f * float(rows - 1)) * spacing;
    // Long enough that the ends stay outside the view.
    scene.meshes.push_back(asCurves ? straightCurve(CurveType::Cylinder, 4.0f, radius, y)
                                    : triangleTube(4.0f, radius, y, sides));
    scene.instances.push_back({uint32_t(scene.meshes.size() - 1), Affine3x4{}, {}});
  }
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0, -4};
  scene.camera.target = {0, 0, 0};
  scene.camera.verticalFovDegrees = 40.0f;
  return scene;
}

}  // namespace candela::test
