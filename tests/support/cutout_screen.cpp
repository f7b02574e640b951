#include "support/cutout_screen.h"

#include "scene/mesh_builders.h"

namespace candela::test {

namespace {

constexpr float kScreenHalfSize = 200.0f;
constexpr float kCheckerPeriod = 0.5f;  // the camera sees a square of side 1
// Texels per checker cell. Filtering blends neighbouring texels across one texel at each cell edge, and a GPU
// texture unit computes that blend in 8-bit fixed point: with wide cells its rounding touches little of the
// screen (with one texel per cell, an H200 let 2% less sky through than the exact filter).
constexpr uint32_t kCellTexels = 64;

// A quad facing `towards`, with texture coordinates that repeat every kCheckerPeriod in x and z.
void appendTexturedQuad(Mesh& mesh, float y, float halfSize, Vec3 towards, uint32_t material) {
  appendQuad(mesh, {-halfSize, y, -halfSize}, {halfSize, y, -halfSize}, {halfSize, y, halfSize},
             {-halfSize, y, halfSize}, towards, material);
  for (size_t i = mesh.positions.size() - 4; i < mesh.positions.size(); ++i)
    mesh.uvs.push_back({mesh.positions[i].x / kCheckerPeriod, mesh.positions[i].z / kCheckerPeriod});
}

}  // namespace

Scene makeCutoutScreen(ScreenCoverage coverage) {
  Scene scene;
  scene.name = "cutout-screen";
  Material floor;
  floor.baseColor = {kScreenFloorAlbedo, kScreenFloorAlbedo, kScreenFloorAlbedo};
  Material screen;
  screen.baseColor = {0, 0, 0};
  Material culled = screen;
  culled.doubleSided = 0;
  switch (coverage) {
    case ScreenCoverage::CheckerMask:
      screen.alphaMode = AlphaMode::Mask;
      screen.opacityTexture = 0;
      break;
    case ScreenCoverage::HalfBlend:
      screen.alphaMode = AlphaMode::Blend;
      screen.opacity = 0.5f;
      break;
    case ScreenCoverage::Opaque:
    case ScreenCoverage::Absent: break;
  }
  scene.materials = {floor, screen, culled};

  Texture checker;
  checker.name = "a checker of 2x2 cells";
  checker.width = checker.height = 2 * kCellTexels;
  checker.channels = 1;
  for (uint32_t y = 0; y < checker.height; ++y)
    for (uint32_t x = 0; x < checker.width; ++x)
      checker.bytes.push_back((x / kCellTexels + y / kCellTexels) % 2 == 0 ? 255 : 0);
  scene.textures.push_back(checker);

  Mesh mesh;
  appendTexturedQuad(mesh, 0.0f, 1.0f, {0, 1, 0}, 0);
  if (coverage != ScreenCoverage::Absent) appendTexturedQuad(mesh, 1.0f, kScreenHalfSize, {0, 0, 0}, 1);
  appendTexturedQuad(mesh, 0.75f, 1.0f, {0, 2, 0}, 2);
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, Affine3x4{}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0.5f, 0};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 0, 1};
  scene.camera.verticalFovDegrees = 90.0f;
  return scene;
}

}  // namespace candela::test
